#pragma once
// Geometric verification of a loop candidate for RGB-D (ORB-SLAM2 LoopClosing::ComputeSim3 with
// the scale fixed to 1, since depth makes it observable): map points matched through the direct
// index give 3D-3D pairs in the two cameras; RANSAC finds the rigid transform; the points the
// candidate and its neighbours see are then searched around their projections with that pose,
// and a pose optimisation over all matches must keep enough inliers. Functions of explicit
// inputs, so they can be tested on synthetic keyframes.
#include <optional>
#include <utility>
#include <vector>

#include "core/config/loop.hpp"
#include "slam/keyframe.hpp"

namespace dynanav {

struct LoopMatch {
  int keypoint = 0;   ///< keypoint in the current keyframe
  MapPointPtr point;  ///< the loop side's map point it sees
};

struct VerifiedLoop {
  KeyFrame* loop = nullptr;
  SE3 T_camera_world_corrected = SE3::Identity();  ///< current keyframe's pose in the loop's frame
  std::vector<LoopMatch> matches;                  ///< current keypoints to loop points (inliers)
  std::vector<MapPointPtr> loop_points;            ///< points of the loop keyframe and neighbours
  int ransac_inliers = 0;
};

/// Tries the candidates in order; the first that passes every test is returned.
std::optional<VerifiedLoop> verifyLoop(const KeyFrame& current,
                                       const std::vector<KeyFrame*>& candidates,
                                       const LoopConfig& config);

/// Matches `points` projected into `keyframe` at pose T_camera_world (not the keyframe's own) to
/// its keypoints, skipping keypoints listed in `taken` (ORB-SLAM2 SearchByProjection with a
/// corrected pose). Appends to `matches`; returns how many were added.
int matchByProjection(const KeyFrame& keyframe, const SE3& T_camera_world,
                      const std::vector<MapPointPtr>& points, float radius_px,
                      std::vector<uint8_t>& taken, std::vector<LoopMatch>& matches);

}  // namespace dynanav
