// Scoring tracked objects against ground truth: the speed RMSE over every matched frame and over
// the frames whose estimate reports its velocity as known (a young track's prior is not).
#include <gtest/gtest.h>

#include <cmath>

#include "eval/object_metrics.hpp"

namespace dynanav {
namespace {

TrackedObject object(uint64_t id, const Vec3& p_world, double speed_mps, bool known) {
  TrackedObject o;
  o.id = id;
  o.class_name = "person";
  o.p_world = p_world;
  o.v_world_mps = Vec3(speed_mps, 0, 0);
  o.speed_mps = speed_mps;
  o.velocity_known = known;
  o.visible_share = 1.0;
  return o;
}

TEST(ObjectMetrics, SpeedRmseOverAllFramesAndOverFramesWithAKnownVelocity) {
  // A walker at 1.2 m/s; the track's first frame reports the prior (0 m/s, not known), then
  // 1.1 and 1.3 m/s.
  std::vector<ObjectsFrame> gt, est;
  const double reported[] = {0.0, 1.1, 1.3};
  for (int i = 0; i < 3; ++i) {
    const double t = i / 30.0;
    const Vec3 p(0.04 * i, 0.0, 3.0);
    gt.push_back({t, {object(1, p, 1.2, true)}});
    est.push_back({t, {object(5, p + Vec3(0.05, 0, 0), reported[i], i > 0)}});
  }
  const ObjectMetrics m = scoreObjects(gt, est);
  EXPECT_EQ(m.matched, 3);
  EXPECT_NEAR(m.speed_rmse_mps, std::sqrt((1.44 + 0.01 + 0.01) / 3.0), 1e-9);
  EXPECT_EQ(m.speed_known_frames, 2);
  EXPECT_NEAR(m.speed_rmse_known_mps, 0.1, 1e-9);
  ASSERT_EQ(m.objects.size(), 1u);
  EXPECT_EQ(m.objects[0].speed_known_frames, 2);
  EXPECT_NEAR(m.objects[0].speed_rmse_known_mps, 0.1, 1e-9);
  EXPECT_NEAR(m.position_rmse_m, 0.05, 1e-9);
}

TEST(ObjectMetrics, StoppedFramesAreScoredByMeanMaxAndRmse) {
  // A box that has stopped: the first frame after the stop still reads 0.4 m/s, then 0.1, 0, 0.
  std::vector<ObjectsFrame> gt, est;
  const double reported[] = {0.4, 0.1, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) {
    const double t = i / 30.0;
    const Vec3 p(1.0, 0.0, 2.0);
    gt.push_back({t, {object(1, p, 0.0, true)}});
    est.push_back({t, {object(2, p, reported[i], true)}});
  }
  const ObjectMetrics m = scoreObjects(gt, est);
  ASSERT_EQ(m.objects.size(), 1u);
  const ObjectScore& s = m.objects[0];
  EXPECT_EQ(s.stopped_frames, 4);
  EXPECT_EQ(s.moving_frames, 0);
  EXPECT_NEAR(s.speed_mean_stopped_mps, 0.125, 1e-9);
  EXPECT_NEAR(s.speed_max_stopped_mps, 0.4, 1e-9);
  EXPECT_NEAR(s.speed_rmse_stopped_mps, std::sqrt((0.16 + 0.01) / 4.0), 1e-9);
}

}  // namespace
}  // namespace dynanav
