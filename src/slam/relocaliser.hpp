#pragma once
// Relocalisation of a lost camera (ORB-SLAM2 Tracking::Relocalization, T-RO 2015 §V-C):
// keyframes that look like the frame come from the bag-of-words database; each candidate's map
// points are matched to the frame through the vocabulary's direct index; EPnP in RANSAC gives a
// pose, which pose optimisation refines; if support is thin, the candidate's points are searched
// again by projection around the new pose. The tracker then tracks the local map as usual.
#include "core/config/loop.hpp"
#include "core/config/tracking.hpp"
#include "slam/frame.hpp"
#include "slam/loop_places.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct RelocalisationResult {
  bool ok = false;
  uint64_t keyframe_id = 0;  ///< the candidate that gave the pose
  int candidates = 0;        ///< database candidates tried
  int inliers = 0;
};

class Relocaliser {
 public:
  Relocaliser(const PlaceIndex& places, const LoopConfig& loop, const TrackingConfig& tracking)
      : places_(places), loop_(loop), tracking_(tracking) {}

  /// Call with the map locked. On success the frame has a pose and its inlier matches.
  RelocalisationResult relocalise(Frame& frame, const Map& map) const;

  /// One candidate: direct-index matching, EPnP-RANSAC, pose optimisation, projection search.
  /// Exposed for tests. Returns the inlier count (0 on failure); the frame keeps its matches.
  int tryKeyFrame(Frame& frame, const FeatureVector& frame_features,
                  const KeyFrame& candidate) const;

 private:
  const PlaceIndex& places_;
  LoopConfig loop_;
  TrackingConfig tracking_;
};

}  // namespace dynanav
