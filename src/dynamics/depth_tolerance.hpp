#pragma once
// How far a keypoint's colour pixel may lie from the depth sample it is compared with while the
// camera moves (issue 18). The depth-difference test compares the depth read at a keypoint's
// pixel with its map point's predicted depth. On a depth edge (where ORB finds corners) a few
// pixels of misregistration put the depth sample on the other side of the edge, and moving
// cameras misregister: a corner blurred over the exposure is detected anywhere along its streak,
// and the depth image may be taken at another instant than the colour image. So the test looks
// for the predicted depth among the depths within the pixels the scene moved over in that time,
// and stays as strict as DynaSLAM's when the camera is still (radius 0).
#include <opencv2/core.hpp>

#include "slam/rolling_shutter.hpp"

namespace dynanav {

/// Time (s) by which a keypoint's colour position and its depth sample may differ: half the
/// colour exposure (the corner's place along its blur streak) plus the colour-depth stamp offset
/// (`depth_stamp_s` <= 0: not known, taken as none).
double depthTestTimeSpread(double exposure_s, double colour_stamp_s, double depth_stamp_s);

/// Image displacement (px) of a point at `depth_m` over `time_s` while the camera moves with
/// `velocity` (one frame interval's motion): f·|ω|·t for the rotation (a bound away from the
/// optical axis for roll, exact on the axis for pan and tilt) plus f·|v|·t / z for the translation.
/// 0 when the velocity is unknown (interval <= 0).
double motionDisplacementPx(const CameraVelocity& velocity, double depth_m, double focal_px,
                            double time_s);

struct DepthRange {
  float min_m = 0.f;  ///< 0 when no valid depth lies in the window
  float max_m = 0.f;
  float nearest_m = 0.f;  ///< the valid depth nearest to `expected_m` (0 when none is valid)
};

/// Smallest and largest valid depth in the (2r+1)² window centred on `pixel` (clipped to the
/// image), and the one nearest to `expected_m`, in one pass; r = 0 reads the pixel itself
/// (rounded, as the keypoint's own depth is read).
DepthRange depthRangeAround(const cv::Mat& depth_m, const cv::Point2f& pixel, int radius_px,
                            double expected_m = 0.0);

}  // namespace dynanav
