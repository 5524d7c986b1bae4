#pragma once
// One RGB-D observation as every module sees it (DESIGN.md §1, core).
#include <opencv2/core.hpp>
#include <string>

namespace dynanav {

struct RgbdFrame {
  int index = 0;               ///< 0-based position among the sequence's associated frames
  double stamp_s = 0.0;        ///< timestamp of the colour image (seconds)
  double depth_stamp_s = 0.0;  ///< timestamp of the depth image it was associated with
  cv::Mat bgr;                 ///< CV_8UC3, BGR
  cv::Mat depth_m;             ///< CV_32F metres; 0 or NaN = invalid
  std::string rgb_path;        ///< where the images came from (empty for synthetic/live input)
  std::string depth_path;

  [[nodiscard]] int width() const { return bgr.cols; }
  [[nodiscard]] int height() const { return bgr.rows; }
};

/// True when a depth sample is usable (finite and positive).
inline bool validDepth(float z) { return z > 0.0f && z < 1e6f; }  // NaN fails both comparisons

}  // namespace dynanav
