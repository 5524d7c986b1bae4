// Local bundle adjustment on a synthetic window with a known answer.
#include <gtest/gtest.h>

#include <random>

#include "slam/bundle_adjuster.hpp"

namespace dynanav {
namespace {

const PoseCamera kCamera{525.0, 525.0, 319.5, 239.5, 525.0 * 0.08};

struct Synthetic {
  BaProblem truth;
  BaProblem noisy;
};

/// Six keyframes on a short arc looking at points 1-4 m ahead; the first two are fixed (the
/// window's anchors). The free poses and all points are perturbed.
Synthetic makeWindow(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> pixel_noise(0.0, 0.5);
  std::normal_distribution<double> pose_noise(0.0, 0.01);
  std::normal_distribution<double> point_noise(0.0, 0.03);
  Synthetic s;
  s.truth.camera = kCamera;
  for (int k = 0; k < 6; ++k) {
    const SE3 T_wc =
        makeSE3(Quat(Eigen::AngleAxisd(0.04 * k, Vec3::UnitY())), Vec3(0.08 * k, 0.01 * k, 0.0));
    s.truth.keyframes.push_back({static_cast<uint64_t>(k), T_wc.inverse(), k < 2});
  }
  for (int j = 0; j < 300; ++j) {
    const Vec3 p((u01(rng) - 0.5) * 3.0, (u01(rng) - 0.5) * 2.0, 1.0 + 3.0 * u01(rng));
    s.truth.points.push_back({static_cast<uint64_t>(j), p});
    for (int k = 0; k < 6; ++k) {
      const Vec3 p_c = s.truth.keyframes[k].T_camera_world * p;
      const double u = kCamera.fx * p_c.x() / p_c.z() + kCamera.cx;
      const double v = kCamera.fy * p_c.y() / p_c.z() + kCamera.cy;
      if (u < 0 || u >= 640 || v < 0 || v >= 480) continue;
      BaObservation obs;
      obs.keyframe = k;
      obs.point = j;
      obs.u = u + pixel_noise(rng);
      obs.v = v + pixel_noise(rng);
      if ((j + k) % 3 != 0) obs.u_right = obs.u - kCamera.bf / p_c.z() + pixel_noise(rng);
      s.truth.observations.push_back(obs);
    }
  }
  s.noisy = s.truth;
  for (auto& kf : s.noisy.keyframes) {
    if (kf.fixed) continue;
    Eigen::Matrix<double, 6, 1> xi;
    for (int i = 0; i < 6; ++i) xi(i) = pose_noise(rng);
    kf.T_camera_world = leftPerturb(xi, kf.T_camera_world);
  }
  for (auto& p : s.noisy.points)
    p.p_world += Vec3(point_noise(rng), point_noise(rng), point_noise(rng));
  return s;
}

TEST(BundleAdjuster, ReducesReprojectionErrorAndKeepsFixedKeyframes) {
  for (const std::string solver : {"sparse_schur", "dense_schur"}) {
    Synthetic s = makeWindow(5);
    BaProblem problem = s.noisy;
    BaOptions options;
    options.linear_solver = solver;
    const BaResult result = bundleAdjust(problem, options);
    EXPECT_GT(result.initial_rms_px, 5.0) << solver;
    EXPECT_LT(result.final_rms_px, 1.0) << solver;  // back to the 0.5 px noise level
    for (size_t k = 0; k < problem.keyframes.size(); ++k) {
      const SE3& T = problem.keyframes[k].T_camera_world;
      if (problem.keyframes[k].fixed) {
        EXPECT_TRUE(T.isApprox(s.noisy.keyframes[k].T_camera_world, 0.0))
            << "fixed keyframe " << k << " moved";
      } else {
        // The free poses return close to the truth (the fixed ones pin the gauge).
        EXPECT_LT((T.translation() - s.truth.keyframes[k].T_camera_world.translation()).norm(),
                  0.01)
            << k;
      }
    }
  }
}

TEST(BundleAdjuster, FlagsGrossOutliers) {
  Synthetic s = makeWindow(9);
  BaProblem problem = s.noisy;
  std::vector<size_t> corrupted;
  for (size_t i = 0; i < problem.observations.size(); i += 37) {
    problem.observations[i].u += 40.0;
    corrupted.push_back(i);
  }
  const BaResult result = bundleAdjust(problem, BaOptions{});
  for (const size_t i : corrupted) EXPECT_TRUE(result.outlier[i]) << "observation " << i;
  size_t flagged = 0;
  for (const auto o : result.outlier) flagged += o;
  EXPECT_LT(flagged, corrupted.size() + problem.observations.size() / 20);
}

TEST(BundleAdjuster, AnObservationOffAlongItsBlurStreakIsNoOutlier) {
  for (const bool model_blur : {false, true}) {
    Synthetic s = makeWindow(9);
    BaProblem problem = s.noisy;
    std::vector<size_t> smeared;
    for (size_t i = 0; i < problem.observations.size(); i += 37) {
      BaObservation& obs = problem.observations[i];
      obs.u += 6.0;  // found 6 px along a sideways streak
      if (obs.u_right >= 0.0) obs.u_right += 6.0;
      if (model_blur) obs.blur_sigma_px = Eigen::Vector2d(4.0, 0.0);
      smeared.push_back(i);
    }
    const BaResult result = bundleAdjust(problem, BaOptions{});
    size_t flagged = 0;
    for (const size_t i : smeared) flagged += result.outlier[i];
    if (model_blur) {
      EXPECT_EQ(flagged, 0u) << "the streak's spread (4 px) covers 6 px along it";
    } else {
      EXPECT_EQ(flagged, smeared.size()) << "6 px is far beyond a sharp keypoint's 1 px";
    }
  }
}

TEST(BundleAdjuster, AnObservationOffAcrossItsBlurStreakIsStillAnOutlier) {
  Synthetic s = makeWindow(9);
  BaProblem problem = s.noisy;
  std::vector<size_t> off;
  for (size_t i = 0; i < problem.observations.size(); i += 37) {
    BaObservation& obs = problem.observations[i];
    obs.v += 6.0;  // across a sideways streak
    obs.blur_sigma_px = Eigen::Vector2d(4.0, 0.0);
    off.push_back(i);
  }
  const BaResult result = bundleAdjust(problem, BaOptions{});
  for (const size_t i : off) EXPECT_TRUE(result.outlier[i]) << "observation " << i;
}

}  // namespace
}  // namespace dynanav
