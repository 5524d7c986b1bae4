#include "viz/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "viz/colours.hpp"

namespace dynanav {
namespace {

std::string cssColour(uint64_t id) {
  const cv::Scalar c = colourOfId(id);
  // Darkened: the video's bright hues are hard to read on white.
  return "rgb(" + std::to_string(int(c[2] * 0.75)) + "," + std::to_string(int(c[1] * 0.75)) + "," +
         std::to_string(int(c[0] * 0.75)) + ")";
}

/// A "nice" tick step (1, 2 or 5 times a power of ten) for about `n` ticks over `span`.
double tickStep(double span, int n) {
  const double raw = span / std::max(1, n);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(4);
  s << (std::abs(v) < 1e-12 ? 0.0 : v);
  return s.str();
}

}  // namespace

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string svgLinePlot(const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const PlotSeries& s : series)
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
    }
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-9) x0 -= 0.5, x1 += 0.5;
  if (y1 - y0 < 1e-9) y0 -= 0.5, y1 += 0.5;
  const double left = 60, right = 150, top = 28, bottom = 40;
  const double pw = spec.width - left - right, ph = spec.height - top - bottom;
  if (spec.equal_aspect) {  // grow the tighter axis so a metre is as long both ways
    const double scale = std::max((x1 - x0) / pw, (y1 - y0) / ph);
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - scale * pw / 2, x1 = cx + scale * pw / 2;
    y0 = cy - scale * ph / 2, y1 = cy + scale * ph / 2;
  }
  auto X = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return top + (y1 - y) / (y1 - y0) * ph; };
  std::ostringstream o;
  o << "<svg class=\"plot\" id=\"" << htmlEscape(spec.id) << "\" width=\"" << spec.width
    << "\" height=\"" << spec.height << "\" viewBox=\"0 0 " << spec.width << " " << spec.height
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o << "<text x=\"" << left << "\" y=\"16\" font-size=\"13\" font-weight=\"bold\">"
    << htmlEscape(spec.title) << "</text>\n";
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#888\"/>\n";
  const double xs = tickStep(x1 - x0, 6), ys = tickStep(y1 - y0, 5);
  for (double t = std::ceil(x0 / xs) * xs; t <= x1 + 1e-9; t += xs)
    o << "<line x1=\"" << X(t) << "\" x2=\"" << X(t) << "\" y1=\"" << top << "\" y2=\"" << top + ph
      << "\" stroke=\"#eee\"/><text x=\"" << X(t) << "\" y=\"" << top + ph + 14
      << "\" text-anchor=\"middle\">" << fmt(t) << "</text>\n";
  for (double t = std::ceil(y0 / ys) * ys; t <= y1 + 1e-9; t += ys)
    o << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << Y(t) << "\" y2=\""
      << Y(t) << "\" stroke=\"#eee\"/><text x=\"" << left - 4 << "\" y=\"" << Y(t) + 4
      << "\" text-anchor=\"end\">" << fmt(t) << "</text>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << spec.height - 6 << "\" text-anchor=\"middle\">"
    << htmlEscape(spec.x_label) << "</text>\n";
  o << "<text transform=\"translate(14," << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << htmlEscape(spec.y_label) << "</text>\n";
  for (size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    const std::string colour = cssColour(s.colour_id);
    const size_t n = std::min(s.x.size(), s.y.size());
    if (s.markers) {
      for (size_t i = 0; i < n; ++i)
        o << "<circle cx=\"" << X(s.x[i]) << "\" cy=\"" << Y(s.y[i]) << "\" r=\"3\" fill=\""
          << colour << "\"/>";
    } else if (n > 0) {
      o << "<polyline class=\"series\" fill=\"none\" stroke=\"" << colour
        << "\" stroke-width=\"1.6\"" << (s.dashed ? " stroke-dasharray=\"5,3\"" : "")
        << " points=\"";
      for (size_t i = 0; i < n; ++i) o << X(s.x[i]) << "," << Y(s.y[i]) << " ";
      o << "\"/>";
    }
    o << "\n<rect x=\"" << left + pw + 10 << "\" y=\"" << top + 4 + 16 * k
      << "\" width=\"12\" height=\"3\" fill=\"" << colour << "\"/><text x=\"" << left + pw + 26
      << "\" y=\"" << top + 9 + 16 * k << "\">" << htmlEscape(s.name) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

std::string svgBarChart(const PlotSpec& spec, const std::vector<std::string>& labels,
                        const std::vector<double>& values, const std::string& unit) {
  const double left = 170, top = 28, bar_h = 16, gap = 4;
  const int height = int(top + (bar_h + gap) * double(labels.size()) + 10);
  const double vmax =
      values.empty() ? 1.0 : std::max(1e-9, *std::max_element(values.begin(), values.end()));
  const double pw = spec.width - left - 90;
  std::ostringstream o;
  o << "<svg class=\"plot\" id=\"" << htmlEscape(spec.id) << "\" width=\"" << spec.width
    << "\" height=\"" << height << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  o << "<text x=\"4\" y=\"16\" font-size=\"13\" font-weight=\"bold\">" << htmlEscape(spec.title)
    << "</text>\n";
  for (size_t i = 0; i < labels.size(); ++i) {
    const double y = top + double(i) * (bar_h + gap);
    o << "<text x=\"" << left - 6 << "\" y=\"" << y + 12 << "\" text-anchor=\"end\">"
      << htmlEscape(labels[i]) << "</text><rect x=\"" << left << "\" y=\"" << y << "\" width=\""
      << pw * values[i] / vmax << "\" height=\"" << bar_h << "\" fill=\"#4a7fb5\"/><text x=\""
      << left + pw * values[i] / vmax + 4 << "\" y=\"" << y + 12 << "\">" << fmt(values[i]) << " "
      << htmlEscape(unit) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace dynanav
