#include "slam/readout_shear.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slam/rgbd_jacobian.hpp"

namespace dynanav {

void addReadoutShear(BaProblem& problem, const std::vector<const KeyFrame*>& keyframes,
                     double readout_s) {
  problem.estimate_readout = true;
  problem.readout_s = readout_s;
  for (auto& obs : problem.observations) {
    const KeyFrame& kf = *keyframes[obs.keyframe];
    obs.readout_used_s = kf.readout_used_s;
    obs.readout_px_per_s.setZero();
    const CameraVelocity& motion = kf.motion;
    if (motion.interval_s <= 0.0) continue;  // not known: its keypoints are taken as they are
    const PinholeCamera& camera = *kf.features.camera;
    const Vec3 p = kf.T_camera_world() * problem.points[obs.point].p_world;
    if (p.z() <= 0.0) continue;
    // The shutter's (raw) row, as slam/rolling_shutter re-timed it; a keypoint without depth was
    // re-timed by the rotation alone (as if far away), so it shears by the rotation alone.
    const double row_offset = kf.features.keypoints[obs.keypoint].pt.y / camera.height - 0.5;
    Vec3 dp_per_s = (motion.omega / motion.interval_s).cross(p);
    if (obs.u_right >= 0.0) dp_per_s += motion.translation / motion.interval_s;
    obs.readout_px_per_s =
        row_offset * rgbdProjectionJacobian(camera.fx, camera.fy, camera.bf(), p) * dp_per_s;
  }
}

namespace {

/// One observation's linearisation for the reduced system: d(prediction)/d(point) and
/// d(prediction)/d(its columns of the reduced system): its keyframe's pose when free, the readout.
struct ObservationJacobian {
  Eigen::MatrixXd point;    ///< rows x 3
  Eigen::MatrixXd reduced;  ///< rows x cols.size()
  std::vector<int> cols;    ///< columns of the reduced system
  double weight = 1.0;      ///< the level's inverse variance
};

ObservationJacobian linearise(const BaProblem& problem, const BaObservation& obs, int free_slot,
                              int readout_col) {
  ObservationJacobian J;
  const PoseCamera& cam = problem.camera;
  const SE3& T_cw = problem.keyframes[obs.keyframe].T_camera_world;
  const Vec3 p = T_cw * problem.points[obs.point].p_world;
  const int rows = obs.u_right >= 0.0 ? 3 : 2;
  const Eigen::Matrix3d J_pi = rgbdProjectionJacobian(cam.fx, cam.fy, cam.bf, p);
  J.point = J_pi.topRows(rows) * T_cw.linear();
  J.reduced = Eigen::MatrixXd::Zero(rows, free_slot >= 0 ? 7 : 1);
  if (free_slot >= 0) {
    Eigen::Matrix<double, 3, 6> dp_dxi;  // left perturbation exp(xi) T, xi = (rho, phi)
    dp_dxi << Mat3::Identity(), -skewSymmetric(p);
    J.reduced.leftCols(6) = J_pi.topRows(rows) * dp_dxi;
    for (int d = 0; d < 6; ++d) J.cols.push_back(6 * free_slot + d);
  }
  J.reduced.rightCols(1) = obs.readout_px_per_s.head(rows);
  J.cols.push_back(readout_col);
  J.weight = obs.inv_sigma2;
  return J;
}

}  // namespace

double readoutSigmaS(const BaProblem& problem, const std::vector<uint8_t>& outlier) {
  constexpr double kUndetermined = std::numeric_limits<double>::infinity();
  if (!problem.estimate_readout) return kUndetermined;
  std::vector<int> free_slot(problem.keyframes.size(), -1);
  int free_keyframes = 0;
  for (size_t k = 0; k < problem.keyframes.size(); ++k)
    if (!problem.keyframes[k].fixed) free_slot[k] = free_keyframes++;
  const int readout_col = 6 * free_keyframes;
  std::vector<std::vector<int>> by_point(problem.points.size());
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    const BaObservation& obs = problem.observations[i];
    const Vec3 p =
        problem.keyframes[obs.keyframe].T_camera_world * problem.points[obs.point].p_world;
    if ((outlier.empty() || !outlier[i]) && p.z() > 0.0) by_point[obs.point].push_back(int(i));
  }
  // Normal equations over (free poses, readout) with every point eliminated:
  // S -= B^T H_pp^-1 B over the columns each point touches.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(readout_col + 1, readout_col + 1);
  for (const auto& observations : by_point) {
    if (observations.empty()) continue;
    std::vector<ObservationJacobian> jacobians;
    std::vector<int> cols;  // the union of their columns
    Mat3 H_pp = Mat3::Zero();
    for (const int i : observations) {
      const BaObservation& obs = problem.observations[i];
      jacobians.push_back(linearise(problem, obs, free_slot[obs.keyframe], readout_col));
      const ObservationJacobian& J = jacobians.back();
      H_pp += J.weight * J.point.transpose() * J.point;
      const Eigen::MatrixXd CtC = J.weight * J.reduced.transpose() * J.reduced;
      for (size_t a = 0; a < J.cols.size(); ++a)
        for (size_t c = 0; c < J.cols.size(); ++c) S(J.cols[a], J.cols[c]) += CtC(a, c);
      for (const int c : J.cols)
        if (std::find(cols.begin(), cols.end(), c) == cols.end()) cols.push_back(c);
    }
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, Eigen::Index(cols.size()));
    for (const ObservationJacobian& J : jacobians) {
      const Eigen::MatrixXd block = J.weight * J.point.transpose() * J.reduced;
      for (size_t a = 0; a < J.cols.size(); ++a) {
        const auto at = std::find(cols.begin(), cols.end(), J.cols[a]) - cols.begin();
        B.col(at) += block.col(Eigen::Index(a));
      }
    }
    // A point seen once without depth leaves its depth along the ray free; B has no component
    // along that direction, so a slight damping keeps the inverse defined without changing S.
    H_pp += 1e-9 * H_pp.trace() * Mat3::Identity();
    const Eigen::LDLT<Mat3> point(H_pp);
    const Eigen::MatrixXd H_inv_B = point.solve(B);
    for (size_t a = 0; a < cols.size(); ++a)
      for (size_t c = 0; c < cols.size(); ++c)
        S(cols[a], cols[c]) -= B.col(Eigen::Index(a)).dot(H_inv_B.col(Eigen::Index(c)));
  }
  // Then the poses: the readout's information is its entry of that system's Schur complement.
  double information = S(readout_col, readout_col);
  if (readout_col > 0) {
    const Eigen::LDLT<Eigen::MatrixXd> poses(S.topLeftCorner(readout_col, readout_col));
    if (poses.info() != Eigen::Success) return kUndetermined;
    const Eigen::VectorXd coupling = S.block(0, readout_col, readout_col, 1);
    information -= coupling.dot(poses.solve(coupling));
  }
  // Below 0.1 px^2 per s^2 (a standard error over 3 s) the window says nothing: a still camera.
  return information > 0.1 && std::isfinite(information) ? 1.0 / std::sqrt(information)
                                                         : kUndetermined;
}

bool adoptReadout(Map& map, const BaProblem& problem, double sigma_s) {
  if (!problem.estimate_readout || !(sigma_s <= map.readout.adopt_sigma_s)) return false;
  map.readout.readout_s = problem.readout_s;
  map.readout.sigma_s = sigma_s;
  map.readout.window_keyframes = static_cast<int>(problem.keyframes.size());
  ++map.readout.adopted;
  return true;
}

}  // namespace dynanav
