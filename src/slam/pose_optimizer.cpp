#include "slam/pose_optimizer.hpp"

#include <ceres/tiny_solver.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <optional>

#include "slam/observation_noise.hpp"
#include "slam/rgbd_jacobian.hpp"

namespace dynanav {
namespace {

constexpr double kChi2Mono = 5.991;    // chi2(2 dof, 95 %)
constexpr double kChi2Stereo = 7.815;  // chi2(3 dof, 95 %)
constexpr double kChi2Depth = 3.841;   // chi2(1 dof, 95 %)

/// A depth sample's normalised point-to-plane distance to the surface at pose T_cw (nullopt: not
/// associated).
std::optional<double> depthResidual(const DepthAlignment& depth, const Vec3& p_world,
                                    const SE3& T_cw) {
  const Vec3 p = T_cw * p_world;
  const auto s = surfaceAt(*depth.surface, p, depth.max_distance_m);
  if (!s) return std::nullopt;
  return s->normal_camera.dot(p - s->p_camera) / depthSigmaM(s->p_camera.z());
}

/// The factor that rescales a residual of squared norm `s` so that its squared norm becomes the
/// Huber cost with threshold `delta` (1 inside it).
double huberScale(double s, double delta) {
  return s > delta * delta ? std::sqrt((2.0 * delta * std::sqrt(s) - delta * delta) / s) : 1.0;
}

/// The residuals of one round for Ceres' TinySolver (dense Levenberg-Marquardt without the
/// general solver's per-problem set-up, which dominated the cost of this 6-parameter problem).
/// Parameters: a left update delta = (omega, t) of the round's starting pose,
/// p_camera = R(omega) * p0 + t with p0 = T0 * p_world. Residuals are weighted by the level's
/// inverse standard deviation; with `robust`, each observation's residual is rescaled so that its
/// squared norm equals the Huber cost of its chi2 (thresholds sqrt(5.991) / sqrt(7.815), as
/// ORB-SLAM2), and its Jacobian by the same factor.
class PoseResiduals {
 public:
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = 6 };

  PoseResiduals(const std::vector<PoseObservation>& observations, const std::vector<int>& used,
                const PoseCamera& camera, const SE3& T0, bool robust, const DepthAlignment& depth,
                const std::vector<int>& depth_used)
      : camera_(camera), robust_(robust) {
    for (const int i : used) {
      const auto& obs = observations[i];
      Item item;
      item.p0 = T0 * obs.p_world;
      item.u = obs.u;
      item.v = obs.v;
      item.u_right = obs.u_right;
      item.sqrt_information = sqrtInformation(obs);
      item.row = num_residuals_;
      num_residuals_ += obs.u_right >= 0.0 ? 3 : 2;
      items_.push_back(item);
    }
    // Each sample is associated once per round, at the round's starting pose, with the plane of
    // the surface it lands on (as ICP does between its iterations): the solver then sees a smooth
    // distance to a fixed plane, and the surface is read once per sample, not per evaluation.
    for (const int i : depth_used) {
      const Vec3 p0 = T0 * (*depth.points_world)[size_t(i)];
      const auto s = surfaceAt(*depth.surface, p0, depth.max_distance_m);
      if (!s) continue;
      planes_.push_back({p0, s->normal_camera, s->normal_camera.dot(s->p_camera),
                         1.0 / depthSigmaM(s->p_camera.z())});
    }
    if (planes_.empty()) return;
    depth_weight_ = std::sqrt(std::min(1.0, depth.effective_samples / double(planes_.size())));
    depth_row_ = num_residuals_;
    num_residuals_ += int(planes_.size());
  }

  [[nodiscard]] int NumResiduals() const { return num_residuals_; }

  bool operator()(const double* delta, double* residuals, double* jacobian) const {
    const Mat3 R = expSO3(Vec3(delta[0], delta[1], delta[2]));
    const Vec3 t(delta[3], delta[4], delta[5]);
    const int rows = num_residuals_;
    for (const Item& item : items_) {
      const Vec3 p = R * item.p0 + t;
      const double inv_z = 1.0 / p.z();
      const double u = camera_.fx * p.x() * inv_z + camera_.cx;
      const double v = camera_.fy * p.y() * inv_z + camera_.cy;
      const bool stereo = item.u_right >= 0.0;
      const Vec3 r(item.u - u, item.v - v, stereo ? item.u_right - (u - camera_.bf * inv_z) : 0.0);
      const Vec3 e = item.sqrt_information * r;
      const int dims = stereo ? 3 : 2;
      const double scale = robust_ ? huberScale(e[0] * e[0] + e[1] * e[1] + e[2] * e[2],
                                                std::sqrt(stereo ? kChi2Stereo : kChi2Mono))
                                   : 1.0;
      for (int k = 0; k < dims; ++k) residuals[item.row + k] = scale * e[k];
      if (!jacobian) continue;
      // d(residual)/dp = -weight * d(projection)/dp; dp/d(omega) = -[p]x, dp/dt = I (left update).
      const Eigen::Matrix3d dproj = rgbdProjectionJacobian(camera_.fx, camera_.fy, camera_.bf, p);
      Eigen::Matrix<double, 3, 6> dp;
      dp.leftCols<3>() = -skewSymmetric(p);
      dp.rightCols<3>().setIdentity();
      const Eigen::Matrix<double, 3, 6> J = -scale * item.sqrt_information * dproj * dp;
      for (int k = 0; k < dims; ++k)
        for (int c = 0; c < 6; ++c) jacobian[c * rows + item.row + k] = J(k, c);
    }
    // Depth samples: distance to their round's plane over the depth noise.
    for (size_t k = 0; k < planes_.size(); ++k) {
      const Plane& plane = planes_[k];
      const int row = depth_row_ + int(k);
      const Vec3 p = R * plane.p0 + t;
      const double w = depth_weight_ * plane.inv_sigma;
      double e = w * (plane.normal.dot(p) - plane.offset);
      const double scale = robust_ ? huberScale(e * e, std::sqrt(kChi2Depth) * depth_weight_) : 1.0;
      residuals[row] = scale * e;
      if (!jacobian) continue;
      // dp/d(omega) = -[p]x, dp/dt = I: n^T [-[p]x | I] = [(p x n)^T | n^T].
      const Vec3 j_omega = (w * scale) * p.cross(plane.normal);
      for (int c = 0; c < 3; ++c) {
        jacobian[c * rows + row] = j_omega[c];
        jacobian[(c + 3) * rows + row] = w * scale * plane.normal[c];
      }
    }
    return true;
  }

 private:
  struct Item {
    Vec3 p0;
    double u, v, u_right;
    Eigen::Matrix3d sqrt_information;
    int row;
  };
  PoseCamera camera_;
  bool robust_;
  std::vector<Item> items_;
  struct Plane {
    Vec3 p0;  ///< the sample at the round's starting pose (camera frame)
    Vec3 normal;
    double offset;  ///< normal . X = offset on the plane
    double inv_sigma;
  };
  std::vector<Plane> planes_;
  double depth_weight_ = 0.0;
  int depth_row_ = 0;
  int num_residuals_ = 0;
};

SE3 applyDelta(const Eigen::Matrix<double, 6, 1>& delta, const SE3& T0) {
  SE3 D = SE3::Identity();
  D.linear() = expSO3(delta.head<3>());
  D.translation() = delta.tail<3>();
  return orthonormalized(D * T0);
}

}  // namespace

Eigen::Matrix3d sqrtInformation(const PoseObservation& obs) {
  return measurementSqrtInformation(obs.inv_sigma2, obs.blur_sigma_px, obs.u_right >= 0.0);
}

double reprojectionChi2(const PoseObservation& obs, const PoseCamera& cam, const SE3& T_cw) {
  const Vec3 p = T_cw * obs.p_world;
  if (p.z() <= 0.0) return std::numeric_limits<double>::infinity();
  const double inv_z = 1.0 / p.z();
  const double u = cam.fx * p.x() * inv_z + cam.cx;
  const Vec3 r(obs.u - u, obs.v - (cam.fy * p.y() * inv_z + cam.cy),
               obs.u_right >= 0.0 ? obs.u_right - (u - cam.bf * inv_z) : 0.0);
  return (sqrtInformation(obs) * r).squaredNorm();
}

namespace {

/// ORB-SLAM2's rounds: outliers sit out a round but are re-classified after it; the robust loss
/// is dropped for the last round.
int optimizeInRounds(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                     const PoseOptimizerOptions& options, SE3& T_camera_world,
                     std::vector<uint8_t>& outlier, const DepthAlignment& depth) {
  const size_t n = observations.size();
  outlier.assign(n, 0);
  if (n < 3) return 0;
  int inliers = static_cast<int>(n);
  std::vector<int> used;
  const size_t n_depth = depth.active() ? depth.points_world->size() : 0;
  std::vector<uint8_t> depth_out(n_depth, 0);
  std::vector<int> depth_used;
  for (int round = 0; round < options.rounds; ++round) {
    used.clear();
    for (size_t i = 0; i < n; ++i)
      if (!outlier[i]) used.push_back(static_cast<int>(i));
    if (used.size() < 10) break;  // too few to trust another round
    depth_used.clear();
    for (size_t i = 0; i < n_depth; ++i)
      if (!depth_out[i]) depth_used.push_back(static_cast<int>(i));
    const PoseResiduals residuals(observations, used, camera, T_camera_world,
                                  round < options.rounds - 1, depth, depth_used);
    ceres::TinySolver<PoseResiduals> solver;
    solver.options.max_num_iterations = options.iterations_per_round;
    Eigen::Matrix<double, 6, 1> delta = Eigen::Matrix<double, 6, 1>::Zero();
    solver.Solve(residuals, &delta);
    T_camera_world = applyDelta(delta, T_camera_world);
    inliers = 0;
    for (size_t i = 0; i < n; ++i) {
      const double threshold = observations[i].u_right >= 0.0 ? kChi2Stereo : kChi2Mono;
      outlier[i] = reprojectionChi2(observations[i], camera, T_camera_world) > threshold;
      if (!outlier[i]) ++inliers;
    }
    for (size_t i = 0; i < n_depth; ++i) {
      const auto e = depthResidual(depth, (*depth.points_world)[i], T_camera_world);
      depth_out[i] = !e || *e * *e > kChi2Depth;
    }
  }
  return inliers;
}

}  // namespace

double loosestTranslationSigmaM(const std::vector<PoseObservation>& observations,
                                const std::vector<uint8_t>& outlier, const PoseCamera& camera,
                                const SE3& T_camera_world) {
  std::vector<int> inliers;
  for (size_t i = 0; i < observations.size(); ++i)
    if (i >= outlier.size() || !outlier[i]) inliers.push_back(int(i));
  const PoseResiduals residuals(observations, inliers, camera, T_camera_world, false, {}, {});
  const int rows = residuals.NumResiduals();
  if (rows < 6) return std::numeric_limits<double>::infinity();
  Eigen::Matrix<double, Eigen::Dynamic, 6> J(rows, 6);
  Eigen::VectorXd r(rows);
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  residuals(zero, r.data(), J.data());
  const Eigen::Matrix<double, 6, 6> H = J.transpose() * J;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(H);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive())
    return std::numeric_limits<double>::infinity();
  const Eigen::Matrix<double, 6, 6> covariance =
      ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  const Mat3 translation = 0.5 * (covariance.bottomRightCorner<3, 3>() +
                                  covariance.bottomRightCorner<3, 3>().transpose());
  const double largest = Eigen::SelfAdjointEigenSolver<Mat3>(translation).eigenvalues().maxCoeff();
  return largest > 0.0 ? std::sqrt(largest) : std::numeric_limits<double>::infinity();
}

int optimizePose(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                 const PoseOptimizerOptions& options, SE3& T_camera_world,
                 std::vector<uint8_t>& outlier, const DepthAlignment& depth) {
  const int inliers =
      optimizeInRounds(observations, camera, options, T_camera_world, outlier, DepthAlignment{});
  if (!depth.active() || inliers < 10 ||
      loosestTranslationSigmaM(observations, outlier, camera, T_camera_world) <= depth.min_sigma_m)
    return inliers;
  // The keypoints leave the pose loose along some direction: the depth joins them, from where
  // they put it.
  return optimizeInRounds(observations, camera, options, T_camera_world, outlier, depth);
}

}  // namespace dynanav
