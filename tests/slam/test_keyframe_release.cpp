// Culled keyframes are freed (issue 16, long run): once local mapping culls a keyframe, no live
// keyframe or map point keeps a raw pointer to it (Map::cullKeyFrame), and the refined
// trajectory's anchors move to a live ancestor with the same pose (TrajectoryAnchors), so the
// last shared_ptr goes and the keyframe with its features, words and points is released.
#include <gtest/gtest.h>

#include "slam/trajectory_anchors.hpp"
#include "test_loop_scene.hpp"

namespace dynanav {
namespace {

/// Seven keyframes 10 degrees apart looking at the synthetic room's wall, sharing points.
struct Arc {
  test::LoopScene scene = test::makeLoopScene(1500, 4.0, 1.0, 5);
  Map map;
  std::vector<KeyFramePtr> keyframes;
  Arc() {
    std::vector<SE3> poses;
    for (int a = 0; a <= 60; a += 10) poses.push_back(test::orbitPose(a * M_PI / 180.0, 1.0));
    keyframes = test::buildMap(scene, poses, poses, map);
  }
};

/// Whether any live keyframe or map point of the map still points at `kf` by a raw pointer.
bool referencedRaw(const Map& map, const KeyFrame* kf) {
  for (const auto& [id, other] : map.keyframes()) {
    if (other.get() == kf) continue;
    if (other->parent == kf || other->children.count(const_cast<KeyFrame*>(kf)) ||
        other->connections.count(const_cast<KeyFrame*>(kf)) ||
        other->loop_edges.count(const_cast<KeyFrame*>(kf)))
      return true;
    for (const KeyFrame* c : other->ordered_covisible)
      if (c == kf) return true;
  }
  for (const auto& [id, p] : map.points())
    if (!p->bad && (p->reference == kf || p->observedBy(kf))) return true;
  return false;
}

TEST(KeyFrameRelease, CulledKeyFrameIsUnlinkedEvenFromOneSidedLinksAndFreed) {
  Arc arc;
  ASSERT_EQ(arc.keyframes.size(), 7u);
  KeyFrame* culled = arc.keyframes[3].get();
  ASSERT_FALSE(culled->connections.empty());
  // A one-sided link, as ORB-SLAM2's UpdateConnections leaves when keyframe 3 dropped keyframe 6
  // in its own last update: keyframe 6 still links to 3, 3 no longer to 6.
  KeyFrame* far = arc.keyframes[6].get();
  culled->eraseConnection(far);
  far->addConnection(culled, 3);
  ASSERT_TRUE(arc.map.cullKeyFrame(*culled));
  EXPECT_TRUE(culled->bad);
  EXPECT_FALSE(referencedRaw(arc.map, culled));

  const std::weak_ptr<KeyFrame> weak = arc.keyframes[3];
  const int64_t before = KeyFrame::instances();
  arc.keyframes[3].reset();
  EXPECT_FALSE(weak.expired()) << "the map still holds it until removeBad()";
  arc.map.removeBad();
  EXPECT_TRUE(weak.expired());
  EXPECT_EQ(KeyFrame::instances(), before - 1);
}

TEST(KeyFrameRelease, KeyFrameZeroIsNeverCulled) {
  Arc arc;
  EXPECT_FALSE(arc.map.cullKeyFrame(*arc.keyframes[0]));
  EXPECT_FALSE(arc.keyframes[0]->bad);
}

void expectSamePoses(const std::vector<StampedPose>& a, const std::vector<StampedPose>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].stamp_s, b[i].stamp_s);
    EXPECT_LT((a[i].T_world_camera.matrix() - b[i].T_world_camera.matrix()).norm(), 1e-9) << i;
  }
}

TEST(TrajectoryAnchors, ReanchoringKeepsPosesAndReleasesCulledKeyFrames) {
  Arc arc;
  TrajectoryAnchors anchors;
  // Two frames anchored on each keyframe, a little off its pose.
  const SE3 offset = makeSE3(Quat(Eigen::AngleAxisd(0.02, Vec3::UnitY())), Vec3(0.05, 0.0, 0.1));
  for (size_t k = 0; k < arc.keyframes.size(); ++k) {
    anchors.add(double(k), arc.keyframes[k], offset);
    anchors.add(k + 0.5, arc.keyframes[k], offset.inverse());
  }
  const auto truth = anchors.poses();
  EXPECT_EQ(anchors.reanchorCulled(), 0);

  // Cull keyframes 4 then 3 (3 may have become 4's children's parent): their anchors move up.
  std::vector<std::weak_ptr<KeyFrame>> weak{arc.keyframes[3], arc.keyframes[4]};
  ASSERT_TRUE(arc.map.cullKeyFrame(*arc.keyframes[4]));
  ASSERT_TRUE(arc.map.cullKeyFrame(*arc.keyframes[3]));
  expectSamePoses(anchors.poses(), truth);  // before re-anchoring: through parent_when_culled
  EXPECT_EQ(anchors.reanchorCulled(), 4);
  EXPECT_EQ(anchors.referenceCount(), 5u);
  expectSamePoses(anchors.poses(), truth);

  arc.map.removeBad();
  arc.keyframes[3].reset();
  arc.keyframes[4].reset();
  for (const auto& w : weak) EXPECT_TRUE(w.expired());

  // A later correction of a live keyframe moves the frames re-anchored on it with it.
  KeyFrame& root = *arc.keyframes[0];
  const SE3 shift = makeSE3(Quat::Identity(), Vec3(0.0, 0.3, 0.0));
  for (const auto& kf : arc.keyframes)
    if (kf) kf->setPose(kf->T_camera_world() * shift);
  const auto moved = anchors.poses();
  for (size_t i = 0; i < moved.size(); ++i) {
    const SE3 expected = shift.inverse() * truth[i].T_world_camera;
    EXPECT_LT((moved[i].T_world_camera.matrix() - expected.matrix()).norm(), 1e-9) << i;
  }
  (void)root;
}

}  // namespace
}  // namespace dynanav
