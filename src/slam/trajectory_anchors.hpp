#pragma once
// Every tracked frame's pose relative to its reference keyframe (ORB-SLAM2's mlpReferences and
// mlRelativeFramePoses), from which the refined trajectory is written once later bundle
// adjustments and loop corrections have moved the keyframes. An anchor on a keyframe that local
// mapping culled is moved to the culled keyframe's nearest live ancestor in the spanning tree,
// with the relative pose the culled keyframe froze when it was culled: the frame's pose is the
// same (anchoredPose), and the anchors no longer keep culled keyframes, their features, words and
// map points alive over a long run.
#include <cstdint>
#include <map>
#include <vector>

#include "io/trajectory.hpp"
#include "slam/keyframe.hpp"

namespace dynanav {

class TrajectoryAnchors {
 public:
  /// A frame tracked at `T_frame_reference` relative to `reference` (map locked).
  void add(double stamp_s, const KeyFramePtr& reference, const SE3& T_frame_reference);
  /// Moves every anchor on a culled keyframe to its nearest live ancestor (map locked); returns
  /// the anchors moved. Anchors stay on a culled keyframe with no parent (none is culled so far).
  int reanchorCulled();
  /// Each frame's T_world_camera as its (live) reference keyframe now stands (map locked).
  [[nodiscard]] std::vector<StampedPose> poses() const;
  [[nodiscard]] size_t size() const { return anchors_.size(); }
  /// Distinct keyframes the anchors hold.
  [[nodiscard]] size_t referenceCount() const { return by_reference_.size(); }

 private:
  struct Anchor {
    double stamp_s;
    SE3 T_frame_reference;
  };
  struct Group {
    KeyFramePtr reference;
    std::vector<size_t> anchors;  ///< indices into anchors_
  };
  std::vector<Anchor> anchors_;             ///< in the order frames were tracked
  std::vector<uint64_t> reference_of_;      ///< per anchor: its reference keyframe's id
  std::map<uint64_t, Group> by_reference_;  ///< keyframe id -> the anchors on it
};

}  // namespace dynanav
