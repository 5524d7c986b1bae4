#pragma once
// Per-keypoint dynamic handling on a tracked Frame (DESIGN.md §1 steps 3 and 5), as functions of
// explicit inputs so they can be tested without a System:
//  - prior-dynamic instances (people, animals) are cut out of ORB extraction, dilated, so their
//    keypoints never reach the initial pose, the local map or a keyframe;
//  - after the initial pose, every keypoint matched to a map point takes DynaSLAM's
//    depth-difference test with the paper's instance vote (depth_difference.hpp); keypoints
//    judged dynamic are handed back to slam to drop (match and `usable` flag cleared), so
//    local-map tracking, keyframes and new map points skip them.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/config/dynamics.hpp"
#include "perception/instances.hpp"
#include "slam/frame.hpp"
#include "slam/keypoint_drop.hpp"
#include "slam/rolling_shutter.hpp"

namespace dynanav {

/// True if the instance's class is listed in prior_dynamic_classes.
bool isPriorDynamic(const Instance& instance, const DynamicsConfig& config);
/// `class_name` is one of `prior_dynamic_classes` (a class that moves by itself: people).
bool isPriorDynamicClass(const std::string& class_name,
                         const std::vector<std::string>& prior_dynamic_classes);

/// CV_8U mask for the ORB extractor: 255 where features may be extracted, 0 on prior-dynamic
/// instances grown by prior_mask_dilate_px. Person masks miss parts (a head, an arm, a blurred
/// frame), so each prior instance's box also claims the pixels whose depth lies within
/// prior_box_depth_band_m of the mask's median depth (`depth_m` CV_32F; empty: masks only).
/// Empty when there is nothing to cut out (the extractor then allows the whole image).
cv::Mat staticExtractionMask(const Instances& instances, const DynamicsConfig& config,
                             const cv::Mat& depth_m = {});

/// Sets features.instance_id from the label image at each keypoint's (distorted) pixel.
void labelKeypoints(Features& features, const cv::Mat& labels);

struct MoverVerdict {
  int checked = 0;                         ///< keypoints with a map point and depth
  std::vector<uint16_t> moving_instances;  ///< instances voted dynamic (ascending id)
  KeypointDrop drop;  ///< what slam is to drop and cull (SlamSystem::applyDrop)
};

/// What the motion-aware depth test needs besides the frame (depth_tolerance.hpp). Default: a
/// still camera, each keypoint compared with its own depth only (DynaSLAM's test).
struct DepthTestMotion {
  cv::Mat depth_m;             ///< the frame's depth image (CV_32F metres); empty: own depth only
  CameraVelocity velocity;     ///< the camera's motion since the last frame (interval 0: unknown)
  double time_spread_s = 0.0;  ///< depthTestTimeSpread() of the frame
  /// Colour rolling-shutter readout in use (s): a keypoint in row v was seen |v/H - 1/2| readouts
  /// away from the middle row's instant, which the depth image is taken at (as in the simulator;
  /// an unknown depth timing is not narrower), so its search widens by that much time.
  double readout_s = 0.0;
};

/// The depth-difference test on `frame` at its initial pose: `predicted_depth_m` = depth of each
/// keypoint's matched map point in the camera (0 = none; SlamSystem::predictedDepths), measured =
/// sensor depth at the keypoint, or any depth within the pixels it may be misregistered by while
/// the camera moves (`motion`; radius capped by config.depth_test_max_radius_px). Dynamic keypoints
/// (in an instance voted dynamic; outside masks: its own failure, or with `moving_evidence`, its
/// map point's evidence over frames, moving_evidence.hpp) are to be dropped. `moving_evidence`:
/// per keypoint, the evidence its map point carries (NaN = no map point; empty = one-frame votes
/// only); the updated values come back in MoverVerdict::drop.moving_evidence. Map points measured
/// deeper than predicted are to be culled when config.cull_vanished_points; those of keypoints on a
/// moving instance when config.cull_moving_object_points. Reads the frame only.
MoverVerdict findDepthMovers(const Frame& frame, const std::vector<float>& predicted_depth_m,
                             const DynamicsConfig& config, const DepthTestMotion& motion = {},
                             const std::vector<float>& moving_evidence = {});

}  // namespace dynanav
