#pragma once
// The rigid motion of an object in the frame it is first segmented in. A new track has no
// points of its own in the previous frame, so its velocity would be its prior (0 +- 1 m/s) for
// that frame and the next: a walker the segmenter picks up late (a noisy mask, the detector
// finding someone already in view) was reported standing while it walked. The previous frame's
// depth holds the object's points already: the dense flow (previous -> this frame) carries
// those that land on the new mask, and the same EPnP-RANSAC + Ceres motion as every later frame
// (object_motion.hpp) measures their motion at once.
#include <opencv2/core.hpp>
#include <optional>

#include "core/camera.hpp"
#include "core/se3.hpp"
#include "dynamics/object_motion.hpp"
#include "perception/instances.hpp"

namespace dynanav {

/// What the tracker keeps of the previous frame for this.
struct PreviousDepthFrame {
  cv::Mat depth_m;  ///< CV_32F; empty: none
  SE3 T_world_camera = SE3::Identity();
  double stamp_s = 0.0;
};

struct FirstMotionInput {
  const Instance& instance;
  const cv::Mat& labels;     ///< this frame's instance labels (CV_16U)
  const cv::Mat& flow_half;  ///< previous -> this frame, half-size pixels
  const cv::Mat& depth_m;    ///< this frame's depth
  const SE3& T_world_camera;
  double stamp_s = 0.0;
  const PinholeCamera& camera;
  const PreviousDepthFrame& previous;
  int step_px = 5;                 ///< sampling grid in the previous frame
  double depth_band_m = 0.5;       ///< points this far from their median depth are not the object's
  double search_margin_px = 64.0;  ///< how far outside the new mask's box a point may come from
};

struct FirstMotion {
  Vec3 v_world_mps = Vec3::Zero();  ///< the inliers' centroid velocity
  SE3 H_world = SE3::Identity();    ///< the motion itself (the next frame's prior)
  int inliers = 0;
};

/// None when there is no previous frame or flow, or too few points for a motion.
std::optional<FirstMotion> firstFrameMotion(const FirstMotionInput& input,
                                            const ObjectMotionOptions& options);

}  // namespace dynanav
