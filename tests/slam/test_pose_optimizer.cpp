// Pose-only optimisation against synthetic correspondences with a known answer.
#include <gtest/gtest.h>

#include <random>

#include "slam/pose_optimizer.hpp"

namespace dynanav {
namespace {

struct Scene {
  std::vector<PoseObservation> observations;
  std::vector<bool> is_outlier;
};

const PoseCamera kCamera{517.3, 516.5, 318.6, 255.3, 517.3 * 0.08};

/// Points in front of the true camera, observed with pixel noise; a share of them gets a
/// wrong pixel (gross outliers). Half have depth (stereo residuals).
Scene makeScene(const SE3& T_cw_true, int n, double outlier_share, double noise_px, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  Scene s;
  const SE3 T_wc = T_cw_true.inverse();
  for (int i = 0; i < n; ++i) {
    const Vec3 p_c((u01(rng) - 0.5) * 3.0, (u01(rng) - 0.5) * 2.0, 0.8 + u01(rng) * 3.0);
    PoseObservation obs;
    obs.p_world = T_wc * p_c;
    obs.u = kCamera.fx * p_c.x() / p_c.z() + kCamera.cx + noise(rng);
    obs.v = kCamera.fy * p_c.y() / p_c.z() + kCamera.cy + noise(rng);
    if (i % 2 == 0) obs.u_right = obs.u - kCamera.bf / p_c.z() + noise(rng);
    const bool outlier = u01(rng) < outlier_share;
    if (outlier) {
      obs.u += 30.0 + 60.0 * u01(rng);
      obs.v -= 30.0 + 60.0 * u01(rng);
      if (obs.u_right >= 0) obs.u_right = obs.u - 5.0;
    }
    s.observations.push_back(obs);
    s.is_outlier.push_back(outlier);
  }
  return s;
}

TEST(PoseOptimizer, RecoversKnownPoseWithOutliers) {
  const SE3 T_true = makeSE3(Quat(Eigen::AngleAxisd(0.3, Vec3(0.2, 1.0, -0.4).normalized())),
                             Vec3(0.4, -0.2, 0.7));
  const Scene scene = makeScene(T_true, 400, 0.2, 0.7, 7);
  // Start 8 cm and ~3 degrees away, as a motion-model prediction might.
  SE3 T = leftPerturb(
      (Eigen::Matrix<double, 6, 1>() << 0.05, -0.04, 0.05, 0.03, -0.03, 0.02).finished(), T_true);
  std::vector<uint8_t> outlier;
  const int inliers = optimizePose(scene.observations, kCamera, PoseOptimizerOptions{}, T, outlier);
  const double translation_error = (T.translation() - T_true.translation()).norm();
  const double rotation_error = rotationAngle(T.linear() * T_true.linear().transpose());
  EXPECT_LT(translation_error, 0.005);
  EXPECT_LT(rotation_error, 0.002);
  int caught = 0, outliers = 0;
  for (size_t i = 0; i < outlier.size(); ++i) {
    if (scene.is_outlier[i]) {
      ++outliers;
      caught += outlier[i];
    }
  }
  EXPECT_EQ(caught, outliers) << "every gross outlier is flagged";
  EXPECT_GT(inliers, 250);
}

TEST(PoseOptimizer, TooFewCorrespondencesLeavePoseAlone) {
  const SE3 T_true = SE3::Identity();
  const Scene scene = makeScene(T_true, 5, 0.0, 0.5, 3);
  SE3 T = T_true;
  T.translation() += Vec3(0.01, 0, 0);
  const SE3 before = T;
  std::vector<uint8_t> outlier;
  optimizePose(scene.observations, kCamera, PoseOptimizerOptions{}, T, outlier);
  EXPECT_TRUE(T.isApprox(before));
}

}  // namespace
}  // namespace dynanav

namespace dynanav {
namespace {
TEST(PoseOptimizer, ConvergesFromFiveDegreesOff) {
  const SE3 T_true =
      makeSE3(Quat(Eigen::AngleAxisd(0.1, Vec3(0.0, 1.0, 0.0))), Vec3(0.1, 0.0, 0.05));
  const Scene scene = makeScene(T_true, 400, 0.1, 0.7, 11);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Matrix<double, 6, 1> xi = Eigen::Matrix<double, 6, 1>::Zero();
    xi(3 + axis) = 5.0 * M_PI / 180.0;
    xi(axis) = 0.02;
    SE3 T = leftPerturb(xi, T_true);
    std::vector<uint8_t> outlier;
    optimizePose(scene.observations, kCamera, PoseOptimizerOptions{}, T, outlier);
    EXPECT_LT((T.translation() - T_true.translation()).norm(), 0.005) << "axis " << axis;
    EXPECT_LT(rotationAngle(T.linear() * T_true.linear().transpose()), 0.002) << "axis " << axis;
  }
}
}  // namespace
}  // namespace dynanav

namespace dynanav {
namespace {

TEST(PoseOptimizer, BlurWeighsAResidualAlongItsStreakOnly) {
  PoseObservation obs;
  obs.inv_sigma2 = 1.0 / (1.2 * 1.2);
  obs.u_right = 100.0;  // with depth: u_right moves with u
  obs.blur_sigma_px = Eigen::Vector2d(3.0, 4.0);
  const Eigen::Matrix3d W = sqrtInformation(obs);
  const Eigen::Vector3d b(3.0, 4.0, 3.0);
  const Eigen::Matrix3d covariance = 1.2 * 1.2 * Eigen::Matrix3d::Identity() + b * b.transpose();
  EXPECT_TRUE((W.transpose() * W * covariance).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  // Across the streak a residual counts as without blur.
  const Eigen::Vector3d across = b.cross(Eigen::Vector3d(0.0, 0.0, 1.0)).normalized();
  EXPECT_NEAR((W * across).norm(), 1.0 / 1.2, 1e-12);
  obs.blur_sigma_px.setZero();
  EXPECT_TRUE(sqrtInformation(obs).isApprox(Eigen::Matrix3d::Identity() / 1.2, 1e-15));
}

/// A view half of whose keypoints are smeared sideways (a fast yaw blurs the whole image alike;
/// here only the left half, a walker's pan across it, say): each is found anywhere on a 12 px
/// streak with equal chance.
Scene blurredHalf(const SE3& T_cw_true, uint32_t seed, bool model_blur) {
  Scene s = makeScene(T_cw_true, 300, 0.0, 0.5, seed);
  std::mt19937 rng(seed + 1000);
  std::uniform_real_distribution<double> along(-6.0, 6.0);
  for (PoseObservation& obs : s.observations) {
    if (obs.u > kCamera.cx) continue;
    const double shift = along(rng);
    obs.u += shift;
    if (obs.u_right >= 0.0) obs.u_right += shift;
    if (model_blur) obs.blur_sigma_px = Eigen::Vector2d(12.0 / std::sqrt(12.0), 0.0);
  }
  return s;
}

TEST(PoseOptimizer, KeypointsSmearedAlongAStreakPullThePoseLessWhenTheirBlurIsModelled) {
  const SE3 T_true =
      makeSE3(Quat(Eigen::AngleAxisd(0.2, Vec3(0.1, 1.0, 0.0).normalized())), Vec3(0.1, 0.0, 0.3));
  double error_isotropic = 0.0, error_blur = 0.0;
  for (uint32_t seed = 1; seed <= 10; ++seed) {
    for (const bool model_blur : {false, true}) {
      const Scene scene = blurredHalf(T_true, seed, model_blur);
      SE3 T = T_true;
      std::vector<uint8_t> outlier;
      optimizePose(scene.observations, kCamera, PoseOptimizerOptions{}, T, outlier);
      // Position error plus the rotation's at 2 m (a point's displacement there).
      const double error = (T.inverse().translation() - T_true.inverse().translation()).norm() +
                           2.0 * rotationAngle(T.linear() * T_true.linear().transpose());
      (model_blur ? error_blur : error_isotropic) += error / 10.0;
    }
  }
  RecordProperty("mean_error_isotropic_mm", std::to_string(1000.0 * error_isotropic));
  RecordProperty("mean_error_blur_mm", std::to_string(1000.0 * error_blur));
  EXPECT_LT(error_blur, 0.6 * error_isotropic);
}

}  // namespace
}  // namespace dynanav
