// Rolling-shutter re-timing: keypoints rendered row by row from a moving camera must land where a
// global-shutter camera at the middle row's time would have seen them.
#include <gtest/gtest.h>

#include <random>

#include "slam/rolling_shutter.hpp"
#include "test_rolling_shutter_motion.hpp"

namespace dynanav {
namespace {

constexpr double kReadout = 0.020;

using testing::makeVelocity;

/// Where the kReadout camera sees p_mid.
Vec3 seenByRow(const PinholeCamera& camera, const CameraVelocity& velocity, const Vec3& p_mid) {
  return testing::seenByRow(camera, velocity, kReadout, p_mid);
}

struct Scene {
  Features features;
  std::vector<Vec3> p_mid;  ///< truth, per keypoint
};

/// Points in front of the camera; every second one has no depth and lies far away.
Scene makeScene(const CameraVelocity& velocity) {
  auto camera = std::make_shared<PinholeCamera>();
  Scene s;
  Features& f = s.features;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const bool with_depth = i % 2 == 0;
    const double z = with_depth ? 0.8 + 3.0 * u01(rng) : 1e4;
    const Vec3 p_mid((u01(rng) - 0.5) * 1.0 * z, (u01(rng) - 0.5) * 0.75 * z, z);
    const Vec3 p_row = seenByRow(*camera, velocity, p_mid);
    const Eigen::Vector2d uv = camera->project(p_row);
    if (!camera->inImage(uv.x(), uv.y(), 1.0)) continue;
    s.p_mid.push_back(p_mid);
    f.keypoints.emplace_back(static_cast<float>(uv.x()), static_cast<float>(uv.y()), 31.f);
    f.points.emplace_back(static_cast<float>(uv.x()), static_cast<float>(uv.y()));
    f.depth_m.push_back(with_depth ? static_cast<float>(p_row.z()) : -1.f);
    f.u_right.push_back(with_depth ? static_cast<float>(uv.x() - camera->bf() / p_row.z()) : -1.f);
  }
  f.usable.assign(f.keypoints.size(), 1);
  f.instance_id.assign(f.keypoints.size(), 0);
  f.bounds = camera->undistortedBounds();
  f.grid = FeatureGrid(f.points, f.bounds);
  f.camera = camera;
  return s;
}

/// Largest pixel distance between the keypoints and the middle-row projections of the truth.
double worstPixelError(const Scene& s) {
  double worst = 0.0;
  for (int i = 0; i < s.features.size(); ++i) {
    const Eigen::Vector2d uv = s.features.camera->project(s.p_mid[i]);
    worst = std::max(worst,
                     std::hypot(uv.x() - s.features.points[i].x, uv.y() - s.features.points[i].y));
  }
  return worst;
}

TEST(RollingShutter, RetimedKeypointsMatchTheMiddleRowCamera) {
  // 2 degrees and 1.2 cm per frame: a brisk head turn while walking.
  const CameraVelocity velocity = makeVelocity(Vec3(0.01, 0.035, 0.0), Vec3(0.008, 0.0, -0.009));
  Scene s = makeScene(velocity);
  ASSERT_GT(s.features.size(), 150);
  const double before = worstPixelError(s);
  EXPECT_GT(before, 5.0);  // the shear a global-shutter model would have to absorb
  compensateRollingShutter(s.features, velocity, kReadout);
  // The far points without depth carry ~1e-6 of their translation; the rest is first-order
  // interpolation of the motion.
  EXPECT_LT(worstPixelError(s), 0.05);
  for (int i = 0; i < s.features.size(); ++i) {
    if (!s.features.hasDepth(i)) continue;
    EXPECT_NEAR(s.features.depth_m[i], s.p_mid[i].z(), 1e-4);
    EXPECT_NEAR(s.features.u_right[i],
                s.features.points[i].x - s.features.camera->bf() / s.p_mid[i].z(), 1e-2);
  }
}

TEST(RollingShutter, GridFollowsTheMovedKeypoints) {
  const CameraVelocity velocity = makeVelocity(Vec3(0.0, 0.035, 0.0), Vec3::Zero());
  Scene s = makeScene(velocity);
  compensateRollingShutter(s.features, velocity, kReadout);
  for (int i = 0; i < s.features.size(); ++i) {
    const auto near =
        s.features.featuresInArea(s.features.points[i].x, s.features.points[i].y, 1.f);
    EXPECT_NE(std::find(near.begin(), near.end(), i), near.end()) << "keypoint " << i;
  }
}

TEST(RollingShutter, GlobalShutterOrUnknownMotionLeavesKeypointsAlone) {
  const CameraVelocity velocity = makeVelocity(Vec3(0.01, 0.035, 0.0), Vec3(0.008, 0.0, -0.009));
  Scene s = makeScene(velocity);
  const KeypointMeasurements as_read = KeypointMeasurements::of(s.features);
  compensateRollingShutter(s.features, velocity, 0.0);
  CameraVelocity no_interval = velocity;
  no_interval.interval_s = 0.0;
  compensateRollingShutter(s.features, no_interval, kReadout);
  EXPECT_EQ(s.features.points, as_read.points);
  EXPECT_EQ(s.features.depth_m, as_read.depth_m);
  EXPECT_EQ(s.features.u_right, as_read.u_right);
}

TEST(RollingShutter, RestoringMeasurementsUndoesARetiming) {
  const CameraVelocity velocity = makeVelocity(Vec3(0.01, 0.035, 0.0), Vec3(0.008, 0.0, -0.009));
  Scene s = makeScene(velocity);
  const KeypointMeasurements as_read = KeypointMeasurements::of(s.features);
  compensateRollingShutter(s.features, velocity, kReadout);
  ASSERT_NE(s.features.points, as_read.points);
  as_read.restoreInto(s.features);
  EXPECT_EQ(s.features.points, as_read.points);
  EXPECT_EQ(s.features.depth_m, as_read.depth_m);
}

// Motion blur (slam/observation_noise.hpp): a keypoint's streak over the exposure.
constexpr double kExposure = 0.010;
constexpr double kShare = 0.29;

TEST(MotionBlur, AYawTurnSmearsEveryKeypointSidewaysByItsTravelOverTheExposure) {
  // 2 degrees per frame (60 deg/s): over 10 ms the view turns by 0.3 of that.
  const CameraVelocity velocity = makeVelocity(Vec3(0.0, 0.035, 0.0), Vec3::Zero());
  Scene s = makeScene(velocity);
  measureMotionBlur(s.features, velocity, kExposure, kShare);
  ASSERT_EQ(s.features.blur_sigma_px.size(), size_t(s.features.size()));
  const PinholeCamera& camera = *s.features.camera;
  const double streak_px = camera.fx * 0.035 * kExposure / testing::kFrameInterval;  // ~5.5 px
  for (int i = 0; i < s.features.size(); ++i) {
    const cv::Point2f& sigma = s.features.blur_sigma_px[size_t(i)];
    // Near the image's centre a yaw moves every point alike, near or far (with depth or without);
    // towards the sides the projection stretches the streak.
    EXPECT_GE(std::abs(sigma.x), 0.99 * kShare * streak_px) << "keypoint " << i;
    EXPECT_LE(std::abs(sigma.x), 1.6 * kShare * streak_px) << "keypoint " << i;
    EXPECT_LT(std::abs(sigma.y), 0.5 * std::abs(sigma.x)) << "keypoint " << i;
  }
}

TEST(MotionBlur, ASidestepSmearsNearPointsMoreThanFarOnes) {
  const CameraVelocity velocity = makeVelocity(Vec3::Zero(), Vec3(0.03, 0.0, 0.0));
  Scene s = makeScene(velocity);
  measureMotionBlur(s.features, velocity, kExposure, kShare);
  const PinholeCamera& camera = *s.features.camera;
  for (int i = 0; i < s.features.size(); ++i) {
    const cv::Point2f& sigma = s.features.blur_sigma_px[size_t(i)];
    if (!s.features.hasDepth(i)) {
      EXPECT_EQ(sigma, cv::Point2f(0.f, 0.f)) << "a far point does not move";
      continue;
    }
    // 3 cm per frame, 0.9 cm over the exposure: fx * 0.009 / z.
    const double expected =
        kShare * camera.fx * 0.03 * kExposure / testing::kFrameInterval / s.features.depth_m[i];
    EXPECT_NEAR(std::abs(sigma.x), expected, 0.01 * expected) << "keypoint " << i;
  }
}

TEST(MotionBlur, NoExposureNoShareOrUnknownMotionMeasuresNothing) {
  const CameraVelocity velocity = makeVelocity(Vec3(0.0, 0.035, 0.0), Vec3::Zero());
  Scene s = makeScene(velocity);
  measureMotionBlur(s.features, velocity, kExposure, kShare);
  ASSERT_FALSE(s.features.blur_sigma_px.empty());
  measureMotionBlur(s.features, velocity, 0.0, kShare);
  EXPECT_TRUE(s.features.blur_sigma_px.empty());
  measureMotionBlur(s.features, velocity, kExposure, 0.0);
  EXPECT_TRUE(s.features.blur_sigma_px.empty());
  CameraVelocity no_interval = velocity;
  no_interval.interval_s = 0.0;
  measureMotionBlur(s.features, no_interval, kExposure, kShare);
  EXPECT_TRUE(s.features.blur_sigma_px.empty());
}

}  // namespace
}  // namespace dynanav
