// Frames anchored on keyframes that local mapping culls: moving the anchor to the nearest live
// ancestor keeps the pose anchoredPose() gives (also after that ancestor moves), and frees the
// culled keyframes, which a long run would otherwise keep alive with all their features.
#include <gtest/gtest.h>

#include "slam/keyframe.hpp"

namespace dynanav {
namespace {

KeyFramePtr keyframe(uint64_t id, const SE3& T_camera_world) {
  return std::make_shared<KeyFrame>(id, id, double(id), Features{}, T_camera_world,
                                    std::vector<MapPointPtr>{});
}

SE3 pose(double angle, const Vec3& t) {
  return makeSE3(Quat(Eigen::AngleAxisd(angle, Vec3(0.3, 1.0, -0.2).normalized())), t);
}

void link(KeyFrame& child, KeyFrame& parent) {
  child.parent = &parent;
  parent.children.insert(&child);
}

TEST(KeyFrameAnchor, ReanchoringKeepsThePoseAndFreesCulledKeyFrames) {
  const KeyFramePtr root = keyframe(0, pose(0.1, {0, 0, 0}));
  KeyFramePtr middle = keyframe(1, pose(0.4, {0.5, -0.1, 0.2}));
  KeyFramePtr leaf = keyframe(2, pose(-0.3, {1.0, 0.2, -0.4}));
  link(*middle, *root);
  link(*leaf, *middle);
  KeyFramePtr reference = leaf;
  SE3 T_frame_reference = pose(0.05, {0.02, 0.0, 0.1});
  const std::weak_ptr<KeyFrame> leaf_alive = leaf, middle_alive = middle;

  leaf->setBad();
  middle->setBad();
  leaf.reset();
  middle.reset();
  root->setPose(pose(0.2, {0.1, 0.1, 0.1}));  // e.g. a bundle adjustment moved the root
  const SE3 before = anchoredPose(*reference, T_frame_reference);
  ASSERT_FALSE(leaf_alive.expired()) << "the anchor holds the culled keyframe";

  reanchorOnLiveKeyFrame(reference, T_frame_reference);
  EXPECT_EQ(reference, root);
  EXPECT_TRUE(anchoredPose(*reference, T_frame_reference).isApprox(before, 1e-12));
  EXPECT_TRUE(leaf_alive.expired());
  EXPECT_TRUE(middle_alive.expired());
}

TEST(KeyFrameAnchor, LiveReferenceStaysAsItIs) {
  KeyFramePtr reference = keyframe(3, pose(0.3, {1, 2, 3}));
  const KeyFramePtr same = reference;
  SE3 T = pose(0.1, {0, 0, 1});
  const SE3 T_before = T;
  reanchorOnLiveKeyFrame(reference, T);
  EXPECT_EQ(reference, same);
  EXPECT_TRUE(T.matrix() == T_before.matrix());
}

}  // namespace
}  // namespace dynanav
