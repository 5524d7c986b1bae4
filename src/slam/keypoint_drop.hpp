#pragma once
// What mover rejection (dynamics, DESIGN.md §1 step 5) decided for a frame's keypoints, for slam
// to apply under its map lock: the decision is a pure function of the frame, the applying is
// slam's, so the pipeline never touches the map.
#include <vector>

#include "slam/established_residuals.hpp"
#include "slam/frame.hpp"

namespace dynanav {

struct KeypointDrop {
  /// Keypoints measured deeper than their map point predicts: the point is gone (it lay on
  /// something that moved) and is culled before anything is dropped.
  std::vector<int> cull_vanished;
  /// Keypoints to make unusable (match, outlier flag and usable flag cleared), ascending.
  std::vector<int> drop;
  /// Per entry of `drop`: also cull its map point (the keypoint lies on a moving object).
  std::vector<bool> cull_on_drop;
  /// Per keypoint (or empty): the moving evidence to store in its map point (NaN: none), written
  /// before anything is dropped (dynamics/moving_evidence.hpp).
  std::vector<float> moving_evidence;
  [[nodiscard]] bool empty() const {
    return cull_vanished.empty() && drop.empty() && moving_evidence.empty();
  }
};

/// What mover rejection reads from the map for a frame (step 5), gathered under one map lock.
struct MapPointChecks {
  std::vector<float> predicted_depth_m;  ///< predictedMapPointDepths()
  std::vector<float> moving_evidence;    ///< mapPointMovingEvidence(), or empty when not asked
  std::vector<MapResidual> residuals;    ///< residualsToEstablishedPoints(), or empty
  std::vector<MapResidual> background_residuals;  ///< residualsToBackground(), or empty
};

/// Adds `keypoints` (ascending) to `drop`'s drop list, keeping it ascending and unique; a keypoint
/// already there keeps its entry, with its point culled if either asks.
void addDrops(KeypointDrop& drop, const std::vector<int>& keypoints, bool cull);

/// Depth of each keypoint's matched map point in the frame's camera at its current pose (0 = no
/// usable match: none, an outlier, or a bad point). The caller holds the map lock.
std::vector<float> predictedMapPointDepths(const Frame& frame);

/// The moving evidence of each keypoint's matched map point (NaN = no usable match, as
/// predictedMapPointDepths). The caller holds the map lock.
std::vector<float> mapPointMovingEvidence(const Frame& frame);

/// Applies `drop` to the frame, in order: vanished points culled, then each dropped keypoint's
/// point culled if asked, and the keypoint made unusable. A point is culled once (set bad) and
/// only if it is a real map point. Returns the points culled. The caller holds the map lock.
int applyKeypointDrop(Frame& frame, const KeypointDrop& drop);

}  // namespace dynanav
