// Loop closing on a synthetic drifting map: the camera turns 440 degrees inside a round room while
// its estimated pose drifts (a small turn and shift per keyframe); the map's points come from the
// drifted poses, and the revisit duplicates the first points. The loop closer must find the loop,
// verify it, fuse the duplicates and shrink the end-point drift at least 5x. A map with no revisit
// must give no loop.
#include <gtest/gtest.h>

#include "slam/loop_closer.hpp"
#include "test_loop_scene.hpp"

namespace dynanav {
namespace {

struct DriftingLoop {
  test::LoopScene scene = test::makeLoopScene(4000, 4.0, 1.0, 21);
  Map map;
  std::vector<SE3> truth;  // T_camera_world
  std::vector<KeyFramePtr> keyframes;

  DriftingLoop(int last_degrees, double drift_rad, double drift_m) {
    std::vector<SE3> estimated;
    const SE3 drift = makeSE3(Quat(Eigen::AngleAxisd(drift_rad, Vec3::UnitY())),
                              Vec3(drift_m, 0.0, 0.5 * drift_m));
    SE3 T_wc = SE3::Identity();
    for (int a = 0; a <= last_degrees; a += 10) {
      truth.push_back(test::orbitPose(a * M_PI / 180.0, 1.0));
      if (truth.size() > 1) {
        const SE3 step =
            truth[truth.size() - 2] * truth.back().inverse();  // T_wc(prev)^-1 T_wc(this)
        T_wc = T_wc * step * drift;
      }
      estimated.push_back(T_wc.inverse());
    }
    keyframes = test::buildMap(scene, truth, estimated, map);
  }
  double endDrift() const {
    return (keyframes.back()->center() - truth.back().inverse().translation()).norm();
  }
};

TEST(LoopCloser, ClosesADriftingLoopAndShrinksTheEndDrift) {
  DriftingLoop world(440, 0.004, 0.01);
  const double before = world.endDrift();
  const size_t points_before = world.map.numPoints();
  LoopConfig config;
  PlaceIndex places(world.scene.vocabulary, config);
  LoopCloser closer(world.map, places, config, 15, /*threaded=*/false);
  for (const auto& kf : world.keyframes) closer.process(kf);
  closer.finish();
  const auto loops = closer.loops();
  ASSERT_GE(loops.size(), 1u) << "the loop is found";
  const LoopEvent& e = loops.front();
  EXPECT_GE(e.keyframe_id, 30u) << "not before the views overlap again (300 degrees on)";
  EXPECT_LE(e.loop_keyframe_id, 8u) << "and it is matched with the start";
  EXPECT_GE(e.matches, config.loop_min_matches);
  EXPECT_EQ(closer.globalBundleAdjustments(), static_cast<int>(loops.size()));
  const double after = world.endDrift();
  EXPECT_GT(before, 0.1);
  EXPECT_LT(after, before / 5.0) << "end drift " << before << " m -> " << after << " m";
  EXPECT_LT(world.map.numPoints(), points_before) << "duplicated points were fused";
  EXPECT_FALSE(world.keyframes[e.keyframe_id]->loop_edges.empty());
  EXPECT_EQ(places.size(), world.keyframes.size()) << "every keyframe entered the database";
}

TEST(LoopCloser, NoRevisitNoLoop) {
  DriftingLoop world(300, 0.004, 0.01);
  LoopConfig config;
  PlaceIndex places(world.scene.vocabulary, config);
  LoopCloser closer(world.map, places, config, 15, false);
  for (const auto& kf : world.keyframes) closer.process(kf);
  EXPECT_TRUE(closer.loops().empty());
}

TEST(LoopCloser, DisabledLoopClosingStillFeedsTheDatabase) {
  DriftingLoop world(440, 0.004, 0.01);
  LoopConfig config;
  config.loop_closing = false;
  PlaceIndex places(world.scene.vocabulary, config);
  LoopCloser closer(world.map, places, config, 15, false);
  for (const auto& kf : world.keyframes) closer.process(kf);
  EXPECT_TRUE(closer.loops().empty());
  EXPECT_EQ(places.size(), world.keyframes.size());
}

}  // namespace
}  // namespace dynanav
