#include <gtest/gtest.h>

#include "dynamics/depth_difference.hpp"

using namespace dynanav;

TEST(DepthDifference, ThresholdGrowsWithDepth) {
  DynamicsConfig c;
  EXPECT_NEAR(depthDifferenceThreshold(0.0, c), c.depth_diff_min_m, 1e-12);
  EXPECT_GT(depthDifferenceThreshold(4.0, c), depthDifferenceThreshold(1.0, c));
  EXPECT_FALSE(failsDepthTest({2.00f, 2.05f, 0}, c));  // sensor noise
  EXPECT_TRUE(failsDepthTest({1.20f, 2.00f, 0}, c));   // something moved in front
  EXPECT_TRUE(failsDepthTest({3.00f, 2.00f, 0}, c));   // the object left: background behind
  EXPECT_FALSE(failsDepthTest({0.f, 2.0f, 0}, c));     // no measurement: no verdict
  EXPECT_FALSE(failsDepthTest({2.0f, 0.f, 0}, c));     // no map point: no verdict
}

TEST(DepthDifference, InstanceVoteDecidesForAllItsKeypoints) {
  DynamicsConfig c;
  std::vector<DepthCheck> checks;
  // Instance 1 (a pushed box): 4 of 10 checked points fail (40 % >= 30 %), plus 2 unchecked.
  for (int i = 0; i < 10; ++i) checks.push_back({i < 4 ? 1.5f : 2.0f, 2.0f, 1});
  checks.push_back({2.0f, 0.f, 1});
  checks.push_back({0.f, 0.f, 1});
  // Instance 2 (a static chair): 1 of 10 fails (sensor glitch) -> static, its points kept.
  for (int i = 0; i < 10; ++i) checks.push_back({i == 0 ? 1.0f : 2.0f, 2.0f, 2});
  // Outside masks: judged one by one.
  checks.push_back({1.0f, 2.0f, 0});
  checks.push_back({2.0f, 2.0f, 0});
  const auto r = classifyByDepthDifference(checks, c);
  ASSERT_EQ(r.keypoint_dynamic.size(), checks.size());
  for (int i = 0; i < 12; ++i) EXPECT_TRUE(r.keypoint_dynamic[i]) << i;
  for (int i = 12; i < 22; ++i) EXPECT_FALSE(r.keypoint_dynamic[i]) << i;
  EXPECT_TRUE(r.keypoint_dynamic[22]);
  EXPECT_FALSE(r.keypoint_dynamic[23]);
  EXPECT_TRUE(r.instances.at(1).dynamic);
  EXPECT_EQ(r.instances.at(1).checked, 10);
  EXPECT_EQ(r.instances.at(1).failing, 4);
  EXPECT_FALSE(r.instances.at(2).dynamic);
  EXPECT_EQ(r.dynamic, 13);
  EXPECT_EQ(r.checked, 22);
}

TEST(DepthDifference, TooFewPointsGiveNoInstanceVerdict) {
  DynamicsConfig c;
  const std::vector<DepthCheck> checks = {{1.0f, 2.0f, 3}, {1.0f, 2.0f, 3}, {2.0f, 2.0f, 3}};
  const auto r = classifyByDepthDifference(checks, c);
  EXPECT_FALSE(r.instances.at(3).dynamic);  // 3 < instance_min_points
  EXPECT_FALSE(r.keypoint_dynamic[0]);      // the instance (undecided) speaks for its points
}
