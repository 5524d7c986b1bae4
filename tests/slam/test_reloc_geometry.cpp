// The solvers behind relocalisation and loop closing, on synthetic data with a known answer:
// EPnP-RANSAC (3D-2D), rigid RANSAC (3D-3D) and the essential-graph pose-graph optimisation.
#include <gtest/gtest.h>

#include <random>

#include "slam/essential_graph.hpp"
#include "slam/pnp_ransac.hpp"
#include "slam/rigid_ransac.hpp"

namespace dynanav {
namespace {

double translationError(const SE3& a, const SE3& b) {
  return (a.translation() - b.translation()).norm();
}
double rotationError(const SE3& a, const SE3& b) {
  return rotationAngle(a.linear() * b.linear().transpose());
}

TEST(PnpRansac, RecoversKnownPoseWithThirtyPercentOutliers) {
  const PinholeCamera camera;
  const SE3 T_cw =
      makeSE3(Quat(Eigen::AngleAxisd(0.4, Vec3(0.3, 1.0, 0.1).normalized())), Vec3(0.3, -0.1, 0.5));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::vector<Vec3> p_world;
  std::vector<Eigen::Vector2d> pixels;
  std::vector<bool> outlier;
  for (int i = 0; i < 200; ++i) {
    const Vec3 p_c(1.5 * u(rng), 1.0 * u(rng), 2.5 + u(rng));
    p_world.push_back(T_cw.inverse() * p_c);
    Eigen::Vector2d px = camera.project(p_c) + Eigen::Vector2d(noise(rng), noise(rng));
    const bool bad = i % 10 < 3;
    if (bad) px += Eigen::Vector2d(40.0 + 50.0 * std::abs(u(rng)), -40.0 * u(rng) - 45.0);
    pixels.push_back(px);
    outlier.push_back(bad);
  }
  const PnpRansacResult r = solvePnpRansac(p_world, pixels, camera);
  ASSERT_TRUE(r.ok);
  EXPECT_LT(translationError(r.T_camera_world, T_cw), 0.01);
  EXPECT_LT(rotationError(r.T_camera_world, T_cw), 0.005);
  int wrong = 0;
  for (size_t i = 0; i < outlier.size(); ++i) wrong += outlier[i] && r.inlier[i];
  EXPECT_EQ(wrong, 0) << "no gross outlier is kept";
  EXPECT_GE(r.inliers, 130);
  // Same input, same answer (the RANSAC is seeded).
  const PnpRansacResult again = solvePnpRansac(p_world, pixels, camera);
  EXPECT_TRUE(again.T_camera_world.isApprox(r.T_camera_world));
}

TEST(PnpRansac, RefusesTooFewOrRandomMatches) {
  const PinholeCamera camera;
  std::vector<Vec3> p_world{{0, 0, 2}, {1, 0, 2}, {0, 1, 2}};
  std::vector<Eigen::Vector2d> pixels{{300, 200}, {400, 200}, {300, 300}};
  EXPECT_FALSE(solvePnpRansac(p_world, pixels, camera).ok);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  p_world.clear();
  pixels.clear();
  for (int i = 0; i < 60; ++i) {
    p_world.emplace_back(u(rng) * 2 - 1, u(rng) * 2 - 1, 2 + u(rng));
    pixels.emplace_back(640 * u(rng), 480 * u(rng));
  }
  PnpRansacOptions options;
  options.min_inliers = 30;
  EXPECT_FALSE(solvePnpRansac(p_world, pixels, camera, options).ok);
}

TEST(RigidRansac, RecoversKnownTransformWithOutliers) {
  const SE3 T_b_a = makeSE3(Quat(Eigen::AngleAxisd(-0.7, Vec3(0.1, 1.0, 0.2).normalized())),
                            Vec3(1.0, 0.2, -0.4));
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Vec3> a, b;
  std::vector<bool> outlier;
  for (int i = 0; i < 150; ++i) {
    const Vec3 pa(2.0 * u(rng), u(rng), 3.0 + u(rng));
    Vec3 pb = T_b_a * pa + Vec3(noise(rng), noise(rng), noise(rng));
    const bool bad = i % 5 == 0;
    if (bad) pb += Vec3(0.5 + u(rng), 0.4, -0.6 * u(rng));
    a.push_back(pa);
    b.push_back(pb);
    outlier.push_back(bad);
  }
  const RigidRansacResult r = estimateRigidRansac(a, b);
  ASSERT_TRUE(r.ok);
  EXPECT_LT(translationError(r.T_b_a, T_b_a), 0.01);
  EXPECT_LT(rotationError(r.T_b_a, T_b_a), 0.003);
  int wrong = 0, kept = 0;
  for (size_t i = 0; i < outlier.size(); ++i) {
    wrong += outlier[i] && r.inlier[i];
    kept += !outlier[i] && r.inlier[i];
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GE(kept, 110);
}

TEST(RigidRansac, RefusesUnrelatedPointSets) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> a, b;
  for (int i = 0; i < 80; ++i) {
    a.emplace_back(u(rng), u(rng), 3 + u(rng));
    b.emplace_back(u(rng), u(rng), 3 + u(rng));
  }
  EXPECT_FALSE(estimateRigidRansac(a, b).ok);
}

// A square loop of 40 poses whose odometry edges carry a small constant error (drift), closed by
// one exact loop edge between the last and the first pose: the optimisation spreads the error
// over the whole loop, so the end-point error shrinks far more than any one step changes.
TEST(EssentialGraph, DistributesALoopError) {
  const int n = 40;
  std::vector<SE3> truth;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    SE3 T = SE3::Identity();
    T.linear() = Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix();
    T.translation() = Vec3(3.0 * std::sin(a), 0.0, 3.0 - 3.0 * std::cos(a));
    truth.push_back(T);  // T_world_camera
  }
  const SE3 drift = makeSE3(Quat(Eigen::AngleAxisd(0.004, Vec3::UnitY())), Vec3(0.01, 0.0, 0.005));
  PoseGraph graph;
  SE3 estimate = truth[0];
  for (int i = 0; i < n; ++i) {
    if (i > 0) estimate = estimate * (truth[i - 1].inverse() * truth[i]) * drift;
    graph.nodes.push_back({static_cast<uint64_t>(i), estimate, i == 0});
  }
  for (int i = 1; i < n; ++i) {
    graph.edges.push_back(
        {i - 1, i, graph.nodes[i - 1].T_world_camera.inverse() * graph.nodes[i].T_world_camera});
  }
  graph.edges.push_back({n - 1, 0, truth[n - 1].inverse() * truth[0]});  // the loop, exact
  const double before = translationError(graph.nodes[n - 1].T_world_camera, truth[n - 1]);
  const PoseGraphSummary summary = optimizePoseGraph(graph, 50);
  const double after = translationError(graph.nodes[n - 1].T_world_camera, truth[n - 1]);
  EXPECT_GT(before, 0.3);
  EXPECT_LT(after, before / 5.0) << "before " << before << " m, after " << after << " m";
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  EXPECT_TRUE(graph.nodes[0].T_world_camera.isApprox(truth[0])) << "the fixed node stays";
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    worst = std::max(worst, translationError(graph.nodes[i].T_world_camera, truth[i]));
  EXPECT_LT(worst, before / 2.0) << "no pose is left with the whole error";
}

}  // namespace
}  // namespace dynanav
