#pragma once
// Global bundle adjustment after a loop correction, and at the end of a run (ORB-SLAM2
// LoopClosing::RunGlobalBundleAdjustment): every keyframe and point in one Ceres problem (keyframe
// 0 fixed: it defines the world frame), solved on a snapshot without the map lock. Applying the
// result also moves what was created while it ran: new keyframes follow their spanning-tree parent,
// new points their reference keyframe (ORB-SLAM2's propagation through the spanning tree).
#include <map>
#include <vector>

#include "slam/bundle_adjuster.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct GlobalBaSnapshot {
  BaProblem problem;
  std::vector<KeyFramePtr> keyframes;  ///< parallel to problem.keyframes
  std::vector<MapPointPtr> points;     ///< parallel to problem.points
};

/// Snapshot of the whole map (call with the map locked).
GlobalBaSnapshot buildGlobalBa(const Map& map);

/// Writes the optimised poses and points back, propagates to keyframes and points that are not
/// in the snapshot, and erases outlier observations (call with the map locked).
void applyGlobalBa(const GlobalBaSnapshot& snapshot, const BaResult& result, Map& map);

struct GlobalBaRun {
  size_t keyframes = 0, points = 0;
  BaResult result;
};

/// The whole thing: snapshot under the map lock, solve without it, write back (and drop what went
/// bad) under it. Used after a loop correction and for the final BA at the end of a run.
GlobalBaRun runGlobalBa(Map& map, const BaOptions& options);

}  // namespace dynanav
