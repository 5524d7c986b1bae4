#include "slam/pose_optimizer.hpp"

#include <ceres/tiny_solver.h>

#include <cmath>
#include <limits>

namespace dynanav {
namespace {

constexpr double kChi2Mono = 5.991;    // chi2(2 dof, 95 %)
constexpr double kChi2Stereo = 7.815;  // chi2(3 dof, 95 %)

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
                const PoseCamera& camera, const SE3& T0, bool robust)
      : camera_(camera), robust_(robust) {
    for (const int i : used) {
      const auto& obs = observations[i];
      Item item;
      item.p0 = T0 * obs.p_world;
      item.u = obs.u;
      item.v = obs.v;
      item.u_right = obs.u_right;
      item.weight = std::sqrt(obs.inv_sigma2);
      item.row = num_residuals_;
      num_residuals_ += obs.u_right >= 0.0 ? 3 : 2;
      items_.push_back(item);
    }
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
      double e[3] = {item.weight * (item.u - u), item.weight * (item.v - v), 0.0};
      if (stereo) e[2] = item.weight * (item.u_right - (u - camera_.bf * inv_z));
      const int dims = stereo ? 3 : 2;
      double scale = 1.0;
      if (robust_) {
        const double s = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        const double delta_h = std::sqrt(stereo ? kChi2Stereo : kChi2Mono);
        if (s > delta_h * delta_h)
          scale = std::sqrt((2.0 * delta_h * std::sqrt(s) - delta_h * delta_h) / s);
      }
      for (int k = 0; k < dims; ++k) residuals[item.row + k] = scale * e[k];
      if (!jacobian) continue;
      // d(residual)/dp = -weight * d(projection)/dp; dp/d(omega) = -[p]x, dp/dt = I (left update).
      const double inv_z2 = inv_z * inv_z;
      Eigen::Matrix<double, 3, 3> dproj;
      dproj << camera_.fx * inv_z, 0.0, -camera_.fx * p.x() * inv_z2,  //
          0.0, camera_.fy * inv_z, -camera_.fy * p.y() * inv_z2,       //
          camera_.fx * inv_z, 0.0, -camera_.fx * p.x() * inv_z2 + camera_.bf * inv_z2;
      Eigen::Matrix<double, 3, 6> dp;
      dp.leftCols<3>() << 0.0, p.z(), -p.y(), -p.z(), 0.0, p.x(), p.y(), -p.x(), 0.0;
      dp.rightCols<3>().setIdentity();
      const Eigen::Matrix<double, 3, 6> J = (-item.weight * scale) * dproj * dp;
      for (int k = 0; k < dims; ++k)
        for (int c = 0; c < 6; ++c) jacobian[c * rows + item.row + k] = J(k, c);
    }
    return true;
  }

 private:
  struct Item {
    Vec3 p0;
    double u, v, u_right, weight;
    int row;
  };
  PoseCamera camera_;
  bool robust_;
  std::vector<Item> items_;
  int num_residuals_ = 0;
};

SE3 applyDelta(const Eigen::Matrix<double, 6, 1>& delta, const SE3& T0) {
  SE3 D = SE3::Identity();
  D.linear() = expSO3(delta.head<3>());
  D.translation() = delta.tail<3>();
  return orthonormalized(D * T0);
}

}  // namespace

double reprojectionChi2(const PoseObservation& obs, const PoseCamera& cam, const SE3& T_cw) {
  const Vec3 p = T_cw * obs.p_world;
  if (p.z() <= 0.0) return std::numeric_limits<double>::infinity();
  const double inv_z = 1.0 / p.z();
  const double u = cam.fx * p.x() * inv_z + cam.cx;
  const double eu = obs.u - u;
  const double ev = obs.v - (cam.fy * p.y() * inv_z + cam.cy);
  double e2 = eu * eu + ev * ev;
  if (obs.u_right >= 0.0) {
    const double er = obs.u_right - (u - cam.bf * inv_z);
    e2 += er * er;
  }
  return e2 * obs.inv_sigma2;
}

int optimizePose(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                 const PoseOptimizerOptions& options, SE3& T_camera_world,
                 std::vector<uint8_t>& outlier) {
  const size_t n = observations.size();
  outlier.assign(n, 0);
  if (n < 3) return 0;
  int inliers = static_cast<int>(n);
  std::vector<int> used;
  for (int round = 0; round < options.rounds; ++round) {
    // ORB-SLAM2: outliers sit out a round but are re-classified after it; the robust loss is
    // dropped for the last round.
    used.clear();
    for (size_t i = 0; i < n; ++i)
      if (!outlier[i]) used.push_back(static_cast<int>(i));
    if (used.size() < 10) break;  // too few to trust another round
    const PoseResiduals residuals(observations, used, camera, T_camera_world,
                                  round < options.rounds - 1);
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
  }
  return inliers;
}

}  // namespace dynanav
