#include "sim/sensor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/rng.hpp"

namespace dynanav::sim {

namespace {
// Per-pixel normal samples come from a fixed table indexed by random bits: far cheaper than
// Box–Muller per pixel, and the table is the same on every machine.
constexpr int kTableBits = 16;
const std::array<float, 1 << kTableBits>& normalTable() {
  static const auto table = [] {
    std::array<float, 1 << kTableBits> t{};
    Rng rng(0x5EEDF00DULL);
    for (float& v : t) v = float(rng.normal());
    return t;
  }();
  return table;
}

/// Four normal samples per 64-bit draw.
class NormalStream {
 public:
  explicit NormalStream(Rng rng) : rng_(rng), table_(normalTable().data()) {}
  float next() {
    if (left_ == 0) {
      bits_ = rng_.next();
      left_ = 4;
    }
    const float v = table_[bits_ & ((1u << kTableBits) - 1)];
    bits_ >>= kTableBits;
    --left_;
    return v;
  }

 private:
  Rng rng_;
  const float* table_;
  uint64_t bits_ = 0;
  int left_ = 0;
};

constexpr uint64_t kDepthStream = 1, kHoleStream = 2, kColourStream = 3;
}  // namespace

cv::Mat simulateDepth(const cv::Mat& depth_true, const DepthSensorModel& m, uint64_t seed,
                      int frame) {
  CV_Assert(depth_true.type() == CV_32F);
  cv::Mat z_max, z_min;
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  cv::dilate(depth_true, z_max, kernel);
  cv::erode(depth_true, z_min, kernel);
  cv::Mat out(depth_true.size(), CV_32F);
  const double bf = m.focal_px * m.baseline_m;
  cv::parallel_for_(cv::Range(0, depth_true.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      NormalStream noise(Rng::stream(seed, uint64_t(frame), uint64_t(y), kDepthStream));
      Rng drop = Rng::stream(seed, uint64_t(frame), uint64_t(y), kHoleStream);
      // Dropped pixels by geometric gaps: one draw per dropout rather than one per pixel.
      const double log_keep = std::log1p(-std::clamp(m.dropout_probability, 1e-12, 0.5));
      const auto gap = [&] {
        return int(std::min(1e9, std::floor(std::log(1.0 - drop.uniform()) / log_keep)));
      };
      int next_drop = m.dropout_probability > 0 ? gap() : depth_true.cols;
      const float* z = depth_true.ptr<float>(y);
      const float* zmax = z_max.ptr<float>(y);
      const float* zmin = z_min.ptr<float>(y);
      float* o = out.ptr<float>(y);
      for (int x = 0; x < depth_true.cols; ++x) {
        const double zt = z[x];
        const float n = noise.next();  // drawn for every pixel: the stream stays aligned
        const bool dropped = x == next_drop;
        if (dropped) next_drop = x + 1 + gap();
        const bool edge =
            zmin[x] <= 0.0f || zmax[x] - zmin[x] > m.edge_jump_m + m.edge_jump_rel * zt;
        if (zt < m.min_depth_m || zt > m.max_depth_m || edge || dropped) {
          o[x] = 0.0f;
          continue;
        }
        const double noisy = zt + m.sigma(zt) * n;
        // Structured light measures disparity in sub-pixel steps: depth comes in quantised levels.
        const double d = std::round(bf / noisy / m.disparity_step_px) * m.disparity_step_px;
        o[x] = d > 0 ? float(bf / d) : 0.0f;
      }
    }
  });
  // A few elliptic holes (dark or glossy surfaces that return nothing).
  Rng holes = Rng::stream(seed, uint64_t(frame), 0, kHoleStream + 100);
  for (int i = 0; i < m.holes_per_frame; ++i) {
    const cv::Point c(holes.uniformInt(0, out.cols - 1), holes.uniformInt(0, out.rows - 1));
    const cv::Size axes(holes.uniformInt(2, 12), holes.uniformInt(2, 8));
    cv::ellipse(out, c, axes, holes.uniform(0, 180), 0, 360, cv::Scalar(0), cv::FILLED);
  }
  return out;
}

void simulateColour(cv::Mat& bgr, const ColourSensorModel& m, uint64_t seed, int frame, double t,
                    bool noise) {
  if (m.blur_sigma_px > 0) cv::GaussianBlur(bgr, bgr, {3, 3}, m.blur_sigma_px);
  if (!noise) return;
  const double phase = double(Rng::stream(seed, 0, 0, kColourStream).uniform()) * 2.0 * M_PI;
  const float gain =
      float(1.0 + m.exposure_amplitude * std::sin(2.0 * M_PI * t / m.exposure_period_s + phase));
  const float sigma = float(m.noise_sigma);
  cv::parallel_for_(cv::Range(0, bgr.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      NormalStream n(Rng::stream(seed, uint64_t(frame), uint64_t(y), kColourStream));
      uint8_t* p = bgr.ptr<uint8_t>(y);
      for (int i = 0; i < bgr.cols * 3; ++i)
        p[i] = cv::saturate_cast<uint8_t>(p[i] * gain + sigma * n.next());
    }
  });
}

}  // namespace dynanav::sim
