#include "viz/report_html.hpp"

#include <cstdio>
#include <sstream>

namespace dynanav {
namespace {

const char* priorityName(FeedbackPriority p) {
  switch (p) {
    case FeedbackPriority::kUrgent:
      return "urgent";
    case FeedbackPriority::kAdvisory:
      return "advisory";
    default:
      return "info";
  }
}

std::string number(const nlohmann::json& j, const char* key, const char* format = "%.3g") {
  if (!j.contains(key) || !j[key].is_number()) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, j[key].get<double>());
  return buffer;
}

template <class... A>
std::string format(const char* f, A... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, f, args...);
  return buffer;
}

void row(std::ostringstream& o, const std::string& name, const std::string& value) {
  o << "<tr><th>" << htmlEscape(name) << "</th><td>" << htmlEscape(value) << "</td></tr>\n";
}

}  // namespace

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t a = uint8_t(bytes[i]);
    const uint32_t b = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0;
    const uint32_t c = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
    const uint32_t v = (a << 16) | (b << 8) | c;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

std::string reportHtml(const ReportData& d) {
  const nlohmann::json& s = d.stats;
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
       "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
    << "<title>dynanav run report: " << htmlEscape(d.sequence) << "</title>\n"
    << "<style>body{font-family:sans-serif;max-width:980px;margin:1em auto;color:#222}"
       "table{border-collapse:collapse}th,td{border:1px solid #ccc;padding:2px 8px;text-align:left}"
       "th{background:#f4f4f4}li.urgent{color:#b00}li.advisory{color:#a60}.note{color:#666}"
       "svg.plot{display:block;margin:0.5em 0}</style></head>\n<body>\n";
  o << "<h1>dynanav run report</h1>\n<h2 id=\"summary\">Summary</h2>\n<table>\n";
  row(o, "sequence", d.sequence);
  row(o, "mode", s.value("mode", std::string("-")));
  row(o, "frames",
      number(s, "frames", "%.0f") + " (tracked " + number(s, "tracked", "%.0f") + ", lost " +
          number(s, "lost", "%.0f") + ")");
  row(o, "keyframes / map points",
      number(s, "keyframes", "%.0f") + " / " + number(s, "map_points", "%.0f"));
  row(o, "wall time",
      number(s, "wall_s", "%.2f") + " s (" + number(s, "fps", "%.1f") + " frames/s)");
  row(o, "loops closed", number(s, "loops", "%.0f"));
  o << "</table>\n";

  o << "<h2 id=\"accuracy\">Accuracy</h2>\n";
  if (d.accuracy) {
    const ReportAccuracy& a = *d.accuracy;
    const ErrorStats& t = a.ate.translation_m;
    o << "<table>\n";
    row(o, "ATE RMSE",
        format("%.4f m (mean %.4f, median %.4f, max %.4f; %zu of %zu poses matched)", t.rmse,
               t.mean, t.median, t.max, a.ate.matched, a.ate.estimated));
    if (a.rpe)
      row(o, "RPE",
          format("translation rmse %.4f m/frame, rotation rmse %.3f deg/frame (%zu pairs)",
                 a.rpe->translation_m.rmse, a.rpe->rotation_deg.rmse, a.rpe->pairs));
    o << "</table>\n";
    o << svgLinePlot(
        {"plot-trajectory", "Trajectory from above (x-z, estimate aligned on ground truth)",
         "x (m)", "z (m)", 720, 420, true},
        a.trajectory_xz);
    o << svgLinePlot({"plot-ate", "Absolute trajectory error over time", "time (s)", "error (m)"},
                     {a.ate_over_time});
  } else {
    o << "<p class=\"note\">" << htmlEscape(d.accuracy_note) << "</p>\n";
  }

  o << "<h2 id=\"timing\">Time per stage</h2>\n";
  std::vector<std::string> labels;
  std::vector<double> means;
  if (s.contains("stage_ms"))
    for (const auto& [stage, t] : s["stage_ms"].items()) {
      labels.push_back(stage + " (" + std::to_string(t.value("count", 0)) + "x)");
      means.push_back(t.value("mean", 0.0));
    }
  o << svgBarChart({"plot-timing", "Mean wall time per call (ms)", "", ""}, labels, means, "ms");
  o << "<p class=\"note\">latency mean "
    << number(s.value("latency_ms", nlohmann::json::object()), "mean", "%.1f") << " ms, p95 "
    << number(s.value("latency_ms", nlohmann::json::object()), "p95", "%.1f") << " ms; peak memory "
    << number(s, "peak_rss_mb", "%.0f") << " MB</p>\n";

  o << "<h2 id=\"speeds\">Speed of tracked objects</h2>\n";
  if (d.speeds.empty()) o << "<p class=\"note\">no tracked objects in this run</p>\n";
  o << svgLinePlot({"plot-speeds", "Speed over time per track", "time (s)", "speed (m/s)"},
                   d.speeds);

  o << "<h2 id=\"messages\">Messages to the wearer</h2>\n";
  PlotSeries marks{"message", {}, {}, 1, false, true};
  for (const FeedbackEvent& e : d.events) {
    marks.x.push_back(e.stamp_s - d.first_stamp_s);
    marks.y.push_back(e.priority == FeedbackPriority::kUrgent     ? 2
                      : e.priority == FeedbackPriority::kAdvisory ? 1
                                                                  : 0);
  }
  PlotSeries span{"run", {0.0, d.last_stamp_s - d.first_stamp_s}, {-0.2, -0.2}, 7};
  o << svgLinePlot({"plot-timeline", "Message timeline (0 info, 1 advisory, 2 urgent)", "time (s)",
                    "priority", 720, 160},
                   {span, marks});
  o << "<ol id=\"message-list\">\n";
  for (const FeedbackEvent& e : d.events)
    o << "<li class=\"" << priorityName(e.priority) << "\">"
      << format("%.2f s", e.stamp_s - d.first_stamp_s) << " [" << htmlEscape(e.kind) << "] "
      << htmlEscape(e.text) << "</li>\n";
  o << "</ol>\n";
  if (d.events.empty()) o << "<p class=\"note\" id=\"no-messages\">no messages in this run</p>\n";

  if (!d.topview_png.empty())
    o << "<h2 id=\"topview\">Top view</h2>\n<img alt=\"top view\" src=\"data:image/png;base64,"
      << base64(d.topview_png) << "\">\n";
  if (!d.outputs.empty()) {
    o << "<h2>Files of this run</h2>\n<ul>\n";
    for (const std::string& f : d.outputs) o << "<li><code>" << htmlEscape(f) << "</code></li>\n";
    o << "</ul>\n";
  }
  // Marks the page as rendered (what the browser test reads back from the DOM).
  o << "<script>document.body.dataset.plots=document.querySelectorAll('svg.plot').length;"
       "document.body.dataset.messages=document.querySelectorAll('#message-list li').length;"
       "</script>\n</body></html>\n";
  return o.str();
}

}  // namespace dynanav
