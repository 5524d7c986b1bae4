// Relocalisation on a synthetic map with known poses: a lost frame between keyframes gets its
// true pose back from the bag-of-words database, direct-index matching, EPnP-RANSAC and pose
// optimisation; a frame of an unmapped place is refused.
#include <gtest/gtest.h>

#include "slam/loop_places.hpp"
#include "slam/relocaliser.hpp"
#include "test_loop_scene.hpp"

namespace dynanav {
namespace {

struct RelocFixture {
  test::LoopScene scene = test::makeLoopScene(4000, 4.0, 1.0, 11);
  Map map;
  std::unique_ptr<PlaceIndex> places;
  LoopConfig loop;
  TrackingConfig tracking;

  /// Keyframes every 10 degrees over the first `degrees` of the orbit, at their true poses.
  explicit RelocFixture(int degrees) {
    std::vector<SE3> poses;
    for (int a = 0; a <= degrees; a += 10) poses.push_back(test::orbitPose(a * M_PI / 180.0, 1.0));
    test::buildMap(scene, poses, poses, map);
    places = std::make_unique<PlaceIndex>(scene.vocabulary, loop);
    for (const auto& [id, kf] : map.keyframes()) places->add(*kf);
  }
};

TEST(Relocaliser, RecoversAKnownPose) {
  RelocFixture f(120);
  const SE3 T_true = test::orbitPose(63.0 * M_PI / 180.0, 1.0) *
                     makeSE3(Quat(Eigen::AngleAxisd(0.05, Vec3::UnitX())), Vec3(0.05, -0.03, 0.1));
  test::View view = test::renderView(f.scene, T_true, 8, 77);
  Frame frame(500, 50.0, std::move(view.features));
  frame.T_camera_world = SE3::Identity();  // what a lost tracker knows: nothing useful
  Relocaliser relocaliser(*f.places, f.loop, f.tracking);
  const RelocalisationResult r = relocaliser.relocalise(frame, f.map);
  ASSERT_TRUE(r.ok) << r.candidates << " candidates tried";
  EXPECT_GE(r.inliers, f.loop.reloc_min_inliers);
  EXPECT_LT((frame.center() - T_true.inverse().translation()).norm(), 0.01);
  EXPECT_LT(rotationAngle(frame.T_camera_world.linear() * T_true.linear().transpose()), 0.003);
  // The keyframe that gave the pose looks at the same part of the wall (60 or 70 degrees).
  EXPECT_TRUE(r.keyframe_id == 6 || r.keyframe_id == 7) << r.keyframe_id;
  // Every match it kept is a true correspondence.
  int matched = 0, wrong = 0;
  for (int i = 0; i < frame.size(); ++i) {
    const MapPointPtr& p = frame.map_points[i];
    if (!p) continue;
    ++matched;
    const Vec3 p_true = f.scene.points[view.point_of[i]];
    wrong += (p->p_world - p_true).norm() > 0.02;
  }
  EXPECT_GE(matched, f.loop.reloc_min_inliers);
  EXPECT_EQ(wrong, 0);
}

TEST(Relocaliser, RefusesAnUnmappedPlace) {
  RelocFixture f(60);
  // The opposite side of the room: no keyframe has seen that part of the wall.
  const SE3 T_far = test::orbitPose(M_PI, 1.0);
  test::View view = test::renderView(f.scene, T_far, 8, 78);
  Frame frame(600, 60.0, std::move(view.features));
  const SE3 before = frame.T_camera_world;
  Relocaliser relocaliser(*f.places, f.loop, f.tracking);
  EXPECT_FALSE(relocaliser.relocalise(frame, f.map).ok);
  EXPECT_TRUE(frame.T_camera_world.isApprox(before));
  for (const auto& p : frame.map_points) EXPECT_EQ(p, nullptr);
}

TEST(Relocaliser, EmptyDatabaseOrBlackFrameFailsQuietly) {
  RelocFixture f(30);
  Relocaliser relocaliser(*f.places, f.loop, f.tracking);
  Features none = test::renderView(f.scene, test::orbitPose(0.0, 1.0), 0, 1).features;
  none = makeFeatures({}, cv::Mat(0, 32, CV_8U), cv::Mat(), 8.0, f.scene.camera, f.scene.scales);
  Frame black(700, 70.0, std::move(none));
  EXPECT_FALSE(relocaliser.relocalise(black, f.map).ok);
  PlaceIndex empty(f.scene.vocabulary, f.loop);
  Relocaliser nothing(empty, f.loop, f.tracking);
  Frame frame(701, 70.1, test::renderView(f.scene, test::orbitPose(0.1, 1.0), 4, 2).features);
  EXPECT_FALSE(nothing.relocalise(frame, f.map).ok);
}

}  // namespace
}  // namespace dynanav
