#include "slam/pose_optimizer.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <memory>

namespace dynanav {
namespace {

constexpr double kChi2Mono = 5.991;    // chi2(2 dof, 95 %)
constexpr double kChi2Stereo = 7.815;  // chi2(3 dof, 95 %)

/// Residual of one observation for a pose update delta = (omega, t) applied on the left of the
/// initial pose: p_camera = R(omega) * (T0 * p_world) + t. p0 = T0 * p_world is precomputed,
/// so the cost function is built once and reused over the rounds.
struct ReprojectionCost {
  ReprojectionCost(const Vec3& p0, const PoseObservation& obs, const PoseCamera& cam, bool stereo)
      : p0_(p0), obs_(obs), cam_(cam), stereo_(stereo), weight_(std::sqrt(obs.inv_sigma2)) {}

  template <class T>
  bool operator()(const T* delta, T* residual) const {
    const T p0[3] = {T(p0_.x()), T(p0_.y()), T(p0_.z())};
    T p[3];
    ceres::AngleAxisRotatePoint(delta, p0, p);
    p[0] += delta[3];
    p[1] += delta[4];
    p[2] += delta[5];
    const T inv_z = T(1.0) / p[2];
    const T u = T(cam_.fx) * p[0] * inv_z + T(cam_.cx);
    residual[0] = T(weight_) * (T(obs_.u) - u);
    residual[1] = T(weight_) * (T(obs_.v) - (T(cam_.fy) * p[1] * inv_z + T(cam_.cy)));
    if (stereo_) residual[2] = T(weight_) * (T(obs_.u_right) - (u - T(cam_.bf) * inv_z));
    return true;
  }

  Vec3 p0_;
  PoseObservation obs_;
  PoseCamera cam_;
  bool stereo_;
  double weight_;
};

/// chi2 = e^T Omega e of an observation at pose T_cw (or infinity behind the camera).
double chi2(const PoseObservation& obs, const PoseCamera& cam, const SE3& T_cw) {
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

SE3 applyDelta(const double* delta, const SE3& T0) {
  SE3 D = SE3::Identity();
  D.linear() = expSO3(Vec3(delta[0], delta[1], delta[2]));
  D.translation() = Vec3(delta[3], delta[4], delta[5]);
  return orthonormalized(D * T0);
}

}  // namespace

int optimizePose(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                 const PoseOptimizerOptions& options, SE3& T_camera_world,
                 std::vector<uint8_t>& outlier) {
  const size_t n = observations.size();
  outlier.assign(n, 0);
  if (n < 3) return 0;
  const SE3 T0 = T_camera_world;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  costs.reserve(n);
  for (const auto& obs : observations) {
    const bool stereo = obs.u_right >= 0.0;
    auto* functor = new ReprojectionCost(T0 * obs.p_world, obs, camera, stereo);
    if (stereo) costs.emplace_back(new ceres::AutoDiffCostFunction<ReprojectionCost, 3, 6>(functor));
    else costs.emplace_back(new ceres::AutoDiffCostFunction<ReprojectionCost, 2, 6>(functor));
  }
  ceres::HuberLoss huber_mono(std::sqrt(kChi2Mono));
  ceres::HuberLoss huber_stereo(std::sqrt(kChi2Stereo));

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.iterations_per_round;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;

  double delta[6] = {0, 0, 0, 0, 0, 0};
  int inliers = static_cast<int>(n);
  for (int round = 0; round < options.rounds; ++round) {
    const bool robust = round < options.rounds - 1;
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    problem.AddParameterBlock(delta, 6);
    int used = 0;
    for (size_t i = 0; i < n; ++i) {
      if (outlier[i]) continue;
      const bool stereo = observations[i].u_right >= 0.0;
      ceres::LossFunction* loss = robust ? (stereo ? static_cast<ceres::LossFunction*>(&huber_stereo) : &huber_mono) : nullptr;
      problem.AddResidualBlock(costs[i].get(), loss, delta);
      ++used;
    }
    if (used < 10) break;  // too few to trust another round (ORB-SLAM2)
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
    const SE3 T = applyDelta(delta, T0);
    inliers = 0;
    for (size_t i = 0; i < n; ++i) {
      const double threshold = observations[i].u_right >= 0.0 ? kChi2Stereo : kChi2Mono;
      outlier[i] = chi2(observations[i], camera, T) > threshold;
      if (!outlier[i]) ++inliers;
    }
  }
  T_camera_world = applyDelta(delta, T0);
  return inliers;
}

}  // namespace dynanav
