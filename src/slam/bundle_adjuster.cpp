#include "slam/bundle_adjuster.hpp"

#include <ceres/ceres.h>
#include <ceres/product_manifold.h>
#include <ceres/rotation.h>

#include "slam/observation_noise.hpp"

namespace dynanav {
namespace {

constexpr double kChi2Mono = 5.991;
constexpr double kChi2Stereo = 7.815;

/// p_camera = R(q) p_world + t with pose = (qw, qx, qy, qz, tx, ty, tz): one 7-parameter block
/// (6 in the tangent space) per keyframe keeps the Schur complement's blocks few and dense.
/// `readout_s` (nullptr: not estimated) adds the shear a readout other than the one the keypoint
/// was re-timed with predicts (BaObservation::readout_px_per_s).
template <class T>
void weightedResidual(const BaObservation& obs, const PoseCamera& cam, const Eigen::Matrix3d& W,
                      const T* pose, const T* point, const T* readout_s, T* residual) {
  const T* q = pose;
  const T* t = pose + 4;
  T p[3];
  ceres::UnitQuaternionRotatePoint(q, point, p);
  p[0] += t[0];
  p[1] += t[1];
  p[2] += t[2];
  const T inv_z = T(1.0) / p[2];
  T u = T(cam.fx) * p[0] * inv_z + T(cam.cx);
  T v = T(cam.fy) * p[1] * inv_z + T(cam.cy);
  T u_right = u - T(cam.bf) * inv_z;
  if (readout_s != nullptr) {
    const T readout_error_s = readout_s[0] - T(obs.readout_used_s);
    u += readout_error_s * T(obs.readout_px_per_s.x());
    v += readout_error_s * T(obs.readout_px_per_s.y());
    u_right += readout_error_s * T(obs.readout_px_per_s.z());
  }
  const T r[3] = {T(obs.u) - u, T(obs.v) - v,
                  obs.u_right >= 0.0 ? T(obs.u_right) - u_right : T(0.0)};
  const int dims = obs.u_right >= 0.0 ? 3 : 2;
  for (int k = 0; k < dims; ++k)
    residual[k] = T(W(k, 0)) * r[0] + T(W(k, 1)) * r[1] + T(W(k, 2)) * r[2];
}

struct BaCost {
  explicit BaCost(const BaObservation& obs, const PoseCamera& cam)
      : obs_(obs),
        cam_(cam),
        sqrt_information_(
            measurementSqrtInformation(obs.inv_sigma2, obs.blur_sigma_px, obs.u_right >= 0.0)) {}
  template <class T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    weightedResidual<T>(obs_, cam_, sqrt_information_, pose, point, nullptr, residual);
    return true;
  }
  BaObservation obs_;
  PoseCamera cam_;
  Eigen::Matrix3d sqrt_information_;
};

struct BaReadoutCost {
  explicit BaReadoutCost(const BaObservation& obs, const PoseCamera& cam)
      : obs_(obs),
        cam_(cam),
        sqrt_information_(
            measurementSqrtInformation(obs.inv_sigma2, obs.blur_sigma_px, obs.u_right >= 0.0)) {}
  template <class T>
  bool operator()(const T* pose, const T* point, const T* readout_s, T* residual) const {
    weightedResidual<T>(obs_, cam_, sqrt_information_, pose, point, readout_s, residual);
    return true;
  }
  BaObservation obs_;
  PoseCamera cam_;
  Eigen::Matrix3d sqrt_information_;
};

template <int kResiduals>
ceres::CostFunction* costFor(const BaObservation& obs, const PoseCamera& cam, bool with_readout) {
  if (with_readout)
    return new ceres::AutoDiffCostFunction<BaReadoutCost, kResiduals, 7, 3, 1>(
        new BaReadoutCost(obs, cam));
  return new ceres::AutoDiffCostFunction<BaCost, kResiduals, 7, 3>(new BaCost(obs, cam));
}

using PoseManifold = ceres::ProductManifold<ceres::QuaternionManifold, ceres::EuclideanManifold<3>>;

struct PoseBlock {
  double x[7];  // qw, qx, qy, qz, tx, ty, tz
};

PoseBlock toBlock(const SE3& T) {
  const Quat q(T.linear());
  const Vec3& t = T.translation();
  return {{q.w(), q.x(), q.y(), q.z(), t.x(), t.y(), t.z()}};
}

SE3 fromBlock(const PoseBlock& b) {
  return makeSE3(Quat(b.x[0], b.x[1], b.x[2], b.x[3]), Vec3(b.x[4], b.x[5], b.x[6]));
}

/// (chi2 weighted by the level variance, pixel error^2 in u,v, in front of the camera?)
struct ObservationError {
  double chi2;
  double pixel2;
  bool in_front;
};

ObservationError evaluate(const BaProblem& problem, const BaObservation& obs) {
  const Vec3 p = problem.keyframes[obs.keyframe].T_camera_world * problem.points[obs.point].p_world;
  if (p.z() <= 0.0) return {std::numeric_limits<double>::infinity(), 0.0, false};
  const PoseCamera& cam = problem.camera;
  const double readout_error_s =
      problem.estimate_readout ? problem.readout_s - obs.readout_used_s : 0.0;
  const Vec3 shear_px = readout_error_s * obs.readout_px_per_s;
  const double inv_z = 1.0 / p.z();
  const double u = cam.fx * p.x() * inv_z + cam.cx;
  const double eu = obs.u - (u + shear_px.x());
  const double ev = obs.v - (cam.fy * p.y() * inv_z + cam.cy + shear_px.y());
  const double pixel2 = eu * eu + ev * ev;
  const Vec3 r(eu, ev,
               obs.u_right >= 0.0 ? obs.u_right - (u - cam.bf * inv_z + shear_px.z()) : 0.0);
  const Eigen::Matrix3d W =
      measurementSqrtInformation(obs.inv_sigma2, obs.blur_sigma_px, obs.u_right >= 0.0);
  return {(W * r).squaredNorm(), pixel2, true};
}

std::vector<uint8_t> classify(const BaProblem& problem) {
  std::vector<uint8_t> outlier(problem.observations.size(), 0);
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    const auto& obs = problem.observations[i];
    const auto e = evaluate(problem, obs);
    const double threshold = obs.u_right >= 0.0 ? kChi2Stereo : kChi2Mono;
    outlier[i] = !e.in_front || e.chi2 > threshold;
  }
  return outlier;
}

/// One Ceres solve of the problem in place.
void solve(BaProblem& problem, const BaOptions& options, int iterations, bool robust,
           const std::vector<uint8_t>& skip) {
  std::vector<PoseBlock> poses;
  poses.reserve(problem.keyframes.size());
  for (const auto& kf : problem.keyframes) poses.push_back(toBlock(kf.T_camera_world));
  std::vector<Vec3> points;
  points.reserve(problem.points.size());
  for (const auto& p : problem.points) points.push_back(p.p_world);
  double readout_s = problem.readout_s;

  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.disable_all_safety_checks = true;  // blocks are built here, sizes known
  ceres::Problem ceres_problem(problem_options);
  ceres::HuberLoss huber_mono(std::sqrt(kChi2Mono));
  ceres::HuberLoss huber_stereo(std::sqrt(kChi2Stereo));
  PoseManifold pose_manifold;
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  std::vector<uint8_t> pose_used(poses.size(), 0), point_used(points.size(), 0);
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    if (!skip.empty() && skip[i]) continue;
    const auto& obs = problem.observations[i];
    const bool stereo = obs.u_right >= 0.0;
    ceres::CostFunction* cost = stereo ? costFor<3>(obs, problem.camera, problem.estimate_readout)
                                       : costFor<2>(obs, problem.camera, problem.estimate_readout);
    ceres::LossFunction* loss =
        robust ? (stereo ? &huber_stereo : static_cast<ceres::LossFunction*>(&huber_mono))
               : nullptr;
    PoseBlock& pose = poses[obs.keyframe];
    if (problem.estimate_readout)
      ceres_problem.AddResidualBlock(cost, loss, pose.x, points[obs.point].data(), &readout_s);
    else
      ceres_problem.AddResidualBlock(cost, loss, pose.x, points[obs.point].data());
    if (!pose_used[obs.keyframe]) {
      pose_used[obs.keyframe] = 1;
      ceres_problem.SetManifold(pose.x, &pose_manifold);
      if (problem.keyframes[obs.keyframe].fixed) ceres_problem.SetParameterBlockConstant(pose.x);
      ordering->AddElementToGroup(pose.x, 1);
    }
    if (!point_used[obs.point]) {
      point_used[obs.point] = 1;
      ordering->AddElementToGroup(points[obs.point].data(), 0);
    }
  }
  if (ceres_problem.NumResidualBlocks() == 0) return;
  if (problem.estimate_readout) {
    ordering->AddElementToGroup(&readout_s, 1);
    // A readout is a duration: a global shutter's noise must not shear the map the other way.
    ceres_problem.SetParameterLowerBound(&readout_s, 0, 0.0);
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type =
      options.linear_solver == "dense_schur" ? ceres::DENSE_SCHUR : ceres::SPARSE_SCHUR;
  solver_options.linear_solver_ordering = ordering;
  solver_options.max_num_iterations = iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &ceres_problem, &summary);

  for (size_t k = 0; k < poses.size(); ++k) {
    if (pose_used[k] && !problem.keyframes[k].fixed)
      problem.keyframes[k].T_camera_world = fromBlock(poses[k]);
  }
  for (size_t k = 0; k < points.size(); ++k) {
    if (point_used[k]) problem.points[k].p_world = points[k];
  }
  problem.readout_s = readout_s;
}

}  // namespace

double reprojectionRms(const BaProblem& problem, const std::vector<uint8_t>& skip) {
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    if (!skip.empty() && skip[i]) continue;
    const auto& obs = problem.observations[i];
    const auto e = evaluate(problem, obs);
    if (!e.in_front) continue;
    sum += e.pixel2;
    ++count;
  }
  return count ? std::sqrt(sum / count) : 0.0;
}

BaResult bundleAdjust(BaProblem& problem, const BaOptions& options) {
  BaResult result;
  result.initial_rms_px = reprojectionRms(problem);
  solve(problem, options, options.iterations_first, /*robust=*/true, {});
  // ORB-SLAM2: drop the observations that are still outliers, refine the rest without the
  // robust loss, then report which observations remain outliers.
  const auto first_outliers = classify(problem);
  if (options.iterations_second > 0)
    solve(problem, options, options.iterations_second, false, first_outliers);
  result.outlier = classify(problem);
  result.final_rms_px = reprojectionRms(problem, result.outlier);
  return result;
}

}  // namespace dynanav
