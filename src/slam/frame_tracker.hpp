#pragma once
// The three ways to pose a frame (ORB-SLAM2 Tracking): from the constant-velocity motion model,
// from the reference keyframe by descriptor matching, and refined against the local map. Each is
// a function of explicit inputs; the Tracker decides which to call.
#include <functional>
#include <map>
#include <vector>

#include "core/config/tracking.hpp"
#include "slam/frame.hpp"
#include "slam/keyframe.hpp"
#include "slam/local_map.hpp"
#include "slam/pose_optimizer.hpp"

namespace dynanav {

/// Keypoint `keypoint`'s match (it must have a map point) as a pose-optimisation observation.
PoseObservation poseObservation(const Frame& frame, int keypoint);
/// The camera's intrinsics as pose optimisation takes them.
PoseCamera poseCamera(const PinholeCamera& camera);

/// Pose-only optimisation of the frame against its matched map points (sets frame.outlier).
/// Returns the number of inliers.
int optimizeFramePose(Frame& frame, const TrackingConfig& config);

/// The same against only the matches `use(keypoint)` accepts, starting at the frame's pose, which
/// is not changed: the refined pose goes to `T_camera_world`, each keypoint's outlier flag to
/// `outlier` (0 for matches not used). Returns the number of inliers.
int optimizePoseOver(const Frame& frame, const TrackingConfig& config,
                     const std::function<bool(int)>& use, SE3& T_camera_world,
                     std::vector<uint8_t>& outlier);

/// Drops outlier matches; returns how many matches to real map points (with observations) are left.
int discardOutliers(Frame& frame);

/// Frame pose predicted as velocity * last pose, matched to the last frame's points by projection.
bool trackWithMotionModel(Frame& current, const Frame& last, const SE3& T_current_last,
                          const TrackingConfig& config);

/// Frame pose from descriptor matches with the reference keyframe, starting at `initial_pose`.
bool trackReferenceKeyFrame(Frame& current, const KeyFrame& reference, const SE3& initial_pose,
                            const TrackingConfig& config);

/// Rebuilds the local map, matches its points by projection and refines the pose. Returns the
/// number of inlier matches to map points (ORB-SLAM2 mnMatchesInliers); updates found counts.
int trackLocalMap(Frame& frame, const std::map<uint64_t, KeyFramePtr>& keyframes,
                  const TrackingConfig& config, LocalMap& local);

}  // namespace dynanav
