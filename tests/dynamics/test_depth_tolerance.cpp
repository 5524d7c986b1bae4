#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/depth_difference.hpp"
#include "dynamics/depth_tolerance.hpp"

using namespace dynanav;

namespace {
constexpr double kPi = 3.14159265358979323846;

/// A camera turning at `deg_s` about its y axis and moving at `m_s`, one 30 Hz interval.
CameraVelocity turning(double deg_s, double m_s = 0.0) {
  CameraVelocity v;
  v.interval_s = 1.0 / 30.0;
  v.omega = Vec3(0, deg_s * kPi / 180.0 * v.interval_s, 0);
  v.translation = Vec3(m_s * v.interval_s, 0, 0);
  return v;
}

/// A depth edge: 1.5 m (a cupboard's side) left of column 320, 4.0 m (the wall) from it on.
cv::Mat depthEdge() {
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(4.0f));
  depth.colRange(0, 320).setTo(1.5f);
  return depth;
}
}  // namespace

TEST(DepthTolerance, TimeSpreadIsHalfTheExposurePlusTheStampOffset) {
  EXPECT_NEAR(depthTestTimeSpread(0.010, 5.000, 5.000), 0.005, 1e-12);
  EXPECT_NEAR(depthTestTimeSpread(0.010, 5.000, 5.012), 0.017, 1e-9);
  EXPECT_NEAR(depthTestTimeSpread(0.010, 5.012, 5.000), 0.017, 1e-9);
  EXPECT_NEAR(depthTestTimeSpread(0.0, 5.0, 0.0), 0.0, 1e-12);  // depth stamp not known
}

TEST(DepthTolerance, DisplacementFollowsTheTurnRateAndNearTranslation) {
  // 150 deg/s over 5 ms at f = 525 px: 525 * 2.618 * 0.005 = 6.87 px.
  EXPECT_NEAR(motionDisplacementPx(turning(150), 2.0, 525, 0.005), 6.87, 0.01);
  EXPECT_NEAR(motionDisplacementPx(turning(0), 2.0, 525, 0.005), 0.0, 1e-9);
  // Walking 1.5 m/s sideways: 525 * 1.5 * 0.005 / z px, larger for near points.
  EXPECT_NEAR(motionDisplacementPx(turning(0, 1.5), 1.0, 525, 0.005), 3.94, 0.01);
  EXPECT_NEAR(motionDisplacementPx(turning(0, 1.5), 4.0, 525, 0.005), 0.98, 0.01);
  CameraVelocity unknown;  // no velocity (interval 0): no widening
  EXPECT_EQ(motionDisplacementPx(unknown, 2.0, 525, 0.005), 0.0);
}

TEST(DepthTolerance, RangeCoversTheWindowAndSkipsInvalidDepth) {
  cv::Mat depth = depthEdge();
  depth.at<float>(100, 318) = 0.f;
  depth.at<float>(100, 319) = std::numeric_limits<float>::quiet_NaN();
  const DepthRange own = depthRangeAround(depth, {317.6f, 100.f}, 0);  // rounds to column 318
  EXPECT_EQ(own.min_m, 0.f);                                           // invalid: no range
  const DepthRange near_edge = depthRangeAround(depth, {318.f, 100.f}, 2);
  EXPECT_FLOAT_EQ(near_edge.min_m, 1.5f);
  EXPECT_FLOAT_EQ(near_edge.max_m, 4.0f);
  const DepthRange away = depthRangeAround(depth, {300.f, 100.f}, 5);
  EXPECT_FLOAT_EQ(away.min_m, 1.5f);
  EXPECT_FLOAT_EQ(away.max_m, 1.5f);
  const DepthRange corner = depthRangeAround(depth, {0.f, 0.f}, 3);  // clipped to the image
  EXPECT_FLOAT_EQ(corner.max_m, 1.5f);
}

TEST(DepthTolerance, AStaticCornerOnADepthEdgePassesWhenTheRangeHoldsItsDepth) {
  DynamicsConfig c;
  // The corner's map point is on the cupboard (1.5 m); blur put the keypoint 3 px onto the wall.
  DepthCheck check{4.0f, 1.5f, 0};
  EXPECT_TRUE(failsDepthTest(check, c));  // own depth only: a false mover
  const DepthRange nearby = depthRangeAround(depthEdge(), {322.f, 200.f}, 4);
  check.nearby_min_m = nearby.min_m;
  check.nearby_max_m = nearby.max_m;
  EXPECT_FALSE(failsDepthTest(check, c));
  // A real mover stays a mover: someone at 0.8 m in front of a wall point, no edge nearby.
  DepthCheck mover{0.8f, 4.0f, 0, 0.75f, 0.85f};
  EXPECT_TRUE(failsDepthTest(mover, c));
  // A point that vanished (measured far deeper than predicted, nothing near its depth).
  DepthCheck vanished{4.0f, 2.0f, 0, 3.9f, 4.1f};
  EXPECT_TRUE(failsDepthTest(vanished, c));
}

TEST(DepthTolerance, MapPointSigmaFollowsTheSlamsDepthModel) {
  // bf = 525 px * 0.08 m = 42: at 2 m and scale 1, 4 / 42 = 9.5 cm; at 4 m, octave 7 (1.2^7).
  EXPECT_NEAR(mapPointDepthSigma(2.0, 1.0, 42.0), 0.0952, 1e-4);
  EXPECT_NEAR(mapPointDepthSigma(4.0, std::pow(1.2, 7), 42.0), 1.365, 1e-3);
  EXPECT_EQ(mapPointDepthSigma(4.0, 1.0, 0.0), 0.0);
  DynamicsConfig c;
  // A far, coarse keypoint 0.5 m off its map point: no evidence of motion under that sigma.
  DepthCheck far{4.5f, 4.0f, 0};
  EXPECT_TRUE(failsDepthTest(far, c));
  far.predicted_sigma_m = static_cast<float>(mapPointDepthSigma(4.0, std::pow(1.2, 7), 42.0));
  EXPECT_FALSE(failsDepthTest(far, c));
  // A near, fine keypoint 0.4 m in front of its map point (a box pushed towards the camera).
  DepthCheck box{1.6f, 2.0f, 0};
  box.predicted_sigma_m = static_cast<float>(mapPointDepthSigma(2.0, 1.0, 42.0));
  EXPECT_TRUE(failsDepthTest(box, c));
  c.depth_diff_map_sigmas = 0;  // DynaSLAM's fixed threshold
  EXPECT_TRUE(failsDepthTest(far, c));
}

TEST(DepthTolerance, NearestDepthPicksTheWindowsDepthClosestToTheExpectedOne) {
  cv::Mat depth = depthEdge();
  depth.at<float>(100, 321) = 0.f;  // a hole is never picked
  const auto nearest = [&](cv::Point2f pixel, int r, double expected) {
    return depthRangeAround(depth, pixel, r, expected).nearest_m;
  };
  EXPECT_FLOAT_EQ(nearest({321.f, 100.f}, 0, 1.5), 0.f);
  EXPECT_FLOAT_EQ(nearest({321.f, 100.f}, 1, 1.5), 4.0f);  // no cupboard within
  EXPECT_FLOAT_EQ(nearest({321.f, 100.f}, 2, 1.5), 1.5f);
  EXPECT_FLOAT_EQ(nearest({321.f, 100.f}, 2, 3.0), 4.0f);
  EXPECT_FLOAT_EQ(nearest({0.f, 0.f}, 3, 4.0), 1.5f);  // clipped to the image
  EXPECT_FLOAT_EQ(depthRangeAround(cv::Mat(), {0.f, 0.f}, 3, 4.0).nearest_m, 0.f);
}
