#include "slam/trajectory_anchors.hpp"

namespace dynanav {

void TrajectoryAnchors::add(double stamp_s, const KeyFramePtr& reference,
                            const SE3& T_frame_reference) {
  Group& group = by_reference_[reference->id];
  if (!group.reference) group.reference = reference;
  group.anchors.push_back(anchors_.size());
  anchors_.push_back({stamp_s, T_frame_reference});
  reference_of_.push_back(reference->id);
}

int TrajectoryAnchors::reanchorCulled() {
  int moved = 0;
  for (auto it = by_reference_.begin(); it != by_reference_.end();) {
    const KeyFrame& reference = *it->second.reference;
    if (!reference.bad || !reference.parent_when_culled) {
      ++it;
      continue;
    }
    // Up the tree to the first live keyframe, composing the relative poses frozen at culling
    // (as anchoredPose does on every call).
    SE3 T_culled_target = SE3::Identity();
    KeyFramePtr target = it->second.reference;
    while (target->bad && target->parent_when_culled) {
      T_culled_target = T_culled_target * target->T_camera_parent;
      target = target->parent_when_culled;
    }
    Group& into = by_reference_[target->id];
    if (!into.reference) into.reference = target;
    for (const size_t a : it->second.anchors) {
      anchors_[a].T_frame_reference = anchors_[a].T_frame_reference * T_culled_target;
      reference_of_[a] = target->id;
      into.anchors.push_back(a);
      ++moved;
    }
    it = by_reference_.erase(it);
  }
  return moved;
}

std::vector<StampedPose> TrajectoryAnchors::poses() const {
  std::vector<StampedPose> poses;
  poses.reserve(anchors_.size());
  for (size_t a = 0; a < anchors_.size(); ++a) {
    const KeyFrame& reference = *by_reference_.at(reference_of_[a]).reference;
    poses.push_back(
        {anchors_[a].stamp_s, anchoredPose(reference, anchors_[a].T_frame_reference).inverse()});
  }
  return poses;
}

}  // namespace dynanav
