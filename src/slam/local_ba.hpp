#pragma once
// Bridges the map and the bundle adjuster for ORB-SLAM2's local BA: the window is the new
// keyframe and all its covisible keyframes with every point they see; keyframes outside the
// window that see those points are fixed, and so is keyframe 0 (the world frame).
#include <vector>

#include "slam/bundle_adjuster.hpp"
#include "slam/keyframe.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct LocalBaIndex {
  std::vector<KeyFrame*> keyframes;  ///< parallel to BaProblem::keyframes
  std::vector<MapPointPtr> points;   ///< parallel to BaProblem::points
};

/// Keypoint `keypoint` of a keyframe as a BA observation of point slot `point_slot` in keyframe
/// slot `keyframe_slot` (undistorted pixel, virtual right u, inverse level variance).
BaObservation baObservation(const Features& features, int keypoint, int keyframe_slot, int point_slot);

/// Snapshot of the local window around `keyframe` (call with the map locked).
BaProblem buildLocalBa(KeyFrame& keyframe, LocalBaIndex& index);

/// Writes optimised poses and points back and erases the outlier observations (map locked).
/// Points or keyframes that went bad meanwhile are left alone.
void applyLocalBa(const BaProblem& problem, const BaResult& result, const LocalBaIndex& index);

}  // namespace dynanav
