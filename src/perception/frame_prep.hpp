#pragma once
// The per-frame preparation step (DESIGN.md §1, "FramePrep"): the images several stages need,
// computed once per frame and shared — the grey image (ORB extraction) and its half-size copy
// (scene flow; object point tracking).
#include <opencv2/core.hpp>

#include "core/frame.hpp"

namespace dynanav {

struct PreparedFrame {
  cv::Mat grey;       ///< CV_8U, full size
  cv::Mat grey_half;  ///< CV_8U, half size (INTER_AREA); empty unless asked for
};

/// Grey image of `frame` (BGR or already grey) and, when `with_half`, its half-size copy.
PreparedFrame prepareFrame(const RgbdFrame& frame, bool with_half);

}  // namespace dynanav
