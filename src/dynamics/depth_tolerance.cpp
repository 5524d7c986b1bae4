#include "dynamics/depth_tolerance.hpp"

#include <algorithm>
#include <cmath>

#include "core/frame.hpp"

namespace dynanav {

double depthTestTimeSpread(double exposure_s, double colour_stamp_s, double depth_stamp_s) {
  const double offset_s = depth_stamp_s > 0.0 ? std::abs(colour_stamp_s - depth_stamp_s) : 0.0;
  return 0.5 * std::max(0.0, exposure_s) + offset_s;
}

double motionDisplacementPx(const CameraVelocity& velocity, double depth_m, double focal_px,
                            double time_s) {
  if (!(velocity.interval_s > 0.0) || !(time_s > 0.0)) return 0.0;
  const double omega_rad_s = velocity.omega.norm() / velocity.interval_s;
  const double speed_m_s = velocity.translation.norm() / velocity.interval_s;
  double px = focal_px * omega_rad_s * time_s;
  if (depth_m > 0.0) px += focal_px * speed_m_s * time_s / depth_m;
  return px;
}

DepthRange depthRangeAround(const cv::Mat& depth_m, const cv::Point2f& pixel, int radius_px,
                            double expected_m) {
  DepthRange range;
  if (depth_m.empty()) return range;
  const int u = static_cast<int>(std::lround(pixel.x));
  const int v = static_cast<int>(std::lround(pixel.y));
  const int r = std::max(0, radius_px);
  const int x0 = std::max(0, u - r), x1 = std::min(depth_m.cols - 1, u + r);
  const int y0 = std::max(0, v - r), y1 = std::min(depth_m.rows - 1, v + r);
  double nearest_gap = 0.0;
  for (int y = y0; y <= y1; ++y) {
    const float* row = depth_m.ptr<float>(y);
    for (int x = x0; x <= x1; ++x) {
      const float z = row[x];
      if (!validDepth(z)) continue;
      if (range.min_m == 0.f || z < range.min_m) range.min_m = z;
      if (z > range.max_m) range.max_m = z;
      const double gap = std::abs(double(z) - expected_m);
      if (range.nearest_m == 0.f || gap < nearest_gap) range.nearest_m = z, nearest_gap = gap;
    }
  }
  return range;
}

}  // namespace dynanav
