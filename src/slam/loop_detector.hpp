#pragma once
// Loop candidates (ORB-SLAM2 LoopClosing::DetectLoop, T-RO 2015 §VII-A): the keyframes in the
// database that score above the lowest score of the new keyframe's covisible neighbours, are not
// covisible with it, and whose covisibility group is found again by consecutive new keyframes
// (temporal consistency). Geometric verification is the loop closer's job.
#include <set>
#include <vector>

#include "core/config/loop.hpp"
#include "slam/keyframe.hpp"
#include "slam/loop_places.hpp"
#include "slam/map.hpp"

namespace dynanav {

class LoopDetector {
 public:
  explicit LoopDetector(const LoopConfig& config) : config_(config) {}

  /// Candidates that are consistent over `loop_consistency` keyframes (map locked). The keyframe
  /// must already have its bag of words; it is not added to the database here.
  std::vector<KeyFrame*> detect(KeyFrame& keyframe, const PlaceIndex& places, const Map& map);
  /// Forget consistency (after a loop is closed, as ORB-SLAM2 does).
  void reset() { groups_.clear(); }

 private:
  struct ConsistentGroup {
    std::set<KeyframeId> keyframes;
    int consistency = 0;
  };
  LoopConfig config_;
  std::vector<ConsistentGroup> groups_;
};

}  // namespace dynanav
