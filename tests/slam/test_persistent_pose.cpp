#include <gtest/gtest.h>

#include "slam/frame_tracker.hpp"
#include "slam/keyframe.hpp"
#include "slam/persistent_pose.hpp"

using namespace dynanav;

namespace {
/// A frame at 5 s whose camera stands at the identity. It matches `persistent` static points
/// 2-4.5 m away mapped at 0 s (where they are) and `crowd` points 1.5 m away mapped at 4.9 s on
/// walkers that have since moved 8 cm to the right together (their keypoints sit where they are
/// now, their map points where they were). The crowd outnumbers the static points.
struct CrowdScene {
  Frame frame;
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
};

CrowdScene crowdScene(int persistent, int crowd) {
  CrowdScene s;
  Features f;
  f.camera = std::make_shared<PinholeCamera>();
  f.scales = std::make_shared<PyramidScales>(PyramidScales::fromConfig(OrbConfig{}));
  std::vector<Vec3> world;
  auto add = [&](double u, double v, double z, const Vec3& moved_m) {
    const Vec3 p = f.camera->backproject(u, v, z);
    const Vec3 now = p + moved_m;
    const double u_now = f.camera->fx * now.x() / now.z() + f.camera->cx;
    const double v_now = f.camera->fy * now.y() / now.z() + f.camera->cy;
    f.keypoints.emplace_back(cv::Point2f(float(u_now), float(v_now)), 31.f);
    f.points.emplace_back(float(u_now), float(v_now));
    f.depth_m.push_back(float(now.z()));
    f.u_right.push_back(float(u_now - f.camera->bf() / now.z()));
    f.usable.push_back(1);
    f.instance_id.push_back(0);
    world.push_back(p);
  };
  for (int i = 0; i < persistent; ++i)
    add(30 + 60 * (i % 10), 30 + 50 * (i / 10) % 420, 2.0 + 0.05 * (i % 50), Vec3::Zero());
  for (int i = 0; i < crowd; ++i)
    add(150 + 25 * (i % 14), 120 + 20 * (i / 14), 1.5, Vec3(0.08, 0, 0));
  const int n = static_cast<int>(world.size());
  s.frame = Frame(150, 5.0, f);
  for (const double stamp_s : {0.0, 4.9})
    s.keyframes.push_back(std::make_shared<KeyFrame>(s.keyframes.size(), 0, stamp_s, f,
                                                     SE3::Identity(), std::vector<MapPointPtr>(n)));
  for (int i = 0; i < n; ++i) {
    KeyFrame* mapped_by = s.keyframes[i < persistent ? 0 : 1].get();
    auto point = std::make_shared<MapPoint>(i, world[i], mapped_by);
    point->addObservation(mapped_by, i);
    s.frame.map_points[i] = point;
  }
  return s;
}
}  // namespace

TEST(PersistentPose, ACrowdMappedMomentsAgoDoesNotPullThePose) {
  CrowdScene s = crowdScene(40, 120);
  // Every match together: the crowd wins and drags the pose sideways (what this rule is for).
  Frame all = s.frame;
  optimizeFramePose(all, TrackingConfig{});
  EXPECT_GT(all.center().norm(), 0.02);

  const PersistentPose r = optimizePoseOnPersistentPoints(s.frame, TrackingConfig{});
  ASSERT_TRUE(r.applied);
  EXPECT_EQ(r.persistent, 40);
  EXPECT_EQ(r.rejected, 120);
  EXPECT_LT(s.frame.center().norm(), 1e-3);
  for (int i = 0; i < 160; ++i) EXPECT_EQ(s.frame.outlier[i], i < 40 ? 0 : 1) << i;
}

TEST(PersistentPose, YoungStaticPointsStayIn) {
  // 60 more static points mapped moments ago: they agree with the persistent ones.
  CrowdScene young = crowdScene(100, 0);
  for (int i = 40; i < 100; ++i) young.frame.map_points[i]->first_mapped_s = 4.9;
  const PersistentPose r = optimizePoseOnPersistentPoints(young.frame, TrackingConfig{});
  ASSERT_TRUE(r.applied);
  EXPECT_EQ(r.persistent, 40);
  EXPECT_EQ(r.rejected, 0);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(young.frame.outlier[i], 0) << i;
  EXPECT_LT(young.frame.center().norm(), 1e-3);
}

TEST(PersistentPose, TooFewPersistentMatchesOrTheRuleOffLeaveTheFrameAlone) {
  TrackingConfig config;
  CrowdScene s = crowdScene(20, 120);  // under persistent_min_matches (30)
  const SE3 before = s.frame.T_camera_world;
  const PersistentPose few = optimizePoseOnPersistentPoints(s.frame, config);
  EXPECT_FALSE(few.applied);
  EXPECT_EQ(few.persistent, 20);
  EXPECT_TRUE(s.frame.T_camera_world.isApprox(before));

  CrowdScene t = crowdScene(40, 120);
  config.persistent_point_age_s = 0.0;
  EXPECT_FALSE(optimizePoseOnPersistentPoints(t.frame, config).applied);
  // An older age makes the persistent matches too few.
  config.persistent_point_age_s = 6.0;
  EXPECT_FALSE(optimizePoseOnPersistentPoints(t.frame, config).applied);
}

TEST(PersistentPose, FrameOnlyPointsAreNeverPersistent) {
  CrowdScene s = crowdScene(40, 0);
  // A motion-model point made from the last frame has no keyframe observation.
  s.frame.map_points[0] = std::make_shared<MapPoint>(999, Vec3(0, 0, 2), nullptr);
  EXPECT_FALSE(isPersistentMatch(s.frame, 0, 2.0));
  EXPECT_TRUE(isPersistentMatch(s.frame, 1, 2.0));
  EXPECT_FALSE(isPersistentMatch(s.frame, 1, 5.5));
}
