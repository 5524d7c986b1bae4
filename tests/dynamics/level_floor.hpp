#pragma once
// Test scene shared by the tracker's floor tests: the depth a level camera sees of a floor.
#include <opencv2/core.hpp>

#include "core/camera.hpp"

namespace dynanav::test {

/// Depth (m) of a floor `below_m` under a level camera, in the rows below the horizon whose
/// floor lies within `max_range_m` (a depth sensor's range); 0 elsewhere.
inline cv::Mat levelFloorDepth(const PinholeCamera& c, double below_m, double max_range_m) {
  cv::Mat depth(c.height, c.width, CV_32F, cv::Scalar(0.f));
  for (int v = 0; v < c.height; ++v) {
    const double z = below_m * c.fy / (v - c.cy);
    if (v > c.cy && z <= max_range_m) depth.row(v).setTo(float(z));
  }
  return depth;
}

}  // namespace dynanav::test
