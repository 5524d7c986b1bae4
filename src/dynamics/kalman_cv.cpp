#include "dynamics/kalman_cv.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace dynanav {

KalmanCv::KalmanCv(const Vec3& p_world, const KalmanCvNoise& noise,
                   const std::optional<Mat3>& position_cov_world)
    : noise_(noise) {
  x_.head<3>() = p_world;
  P_.setZero();
  P_.topLeftCorner<3, 3>() = position_cov_world.value_or(Mat3::Identity() * noise.position_sigma_m *
                                                         noise.position_sigma_m);
  P_.bottomRightCorner<3, 3>() =
      Mat3::Identity() * noise.initial_velocity_sigma_mps * noise.initial_velocity_sigma_mps;
}

KalmanCv::Mat6 KalmanCv::transition(double dt_s) const {
  Mat6 F = Mat6::Identity();
  F.topRightCorner<3, 3>() = Mat3::Identity() * dt_s;
  return F;
}

Mat3 KalmanCv::accelerationCovariance() const {
  // Isotropic until the direction of travel is clear, then split along and across it. A walker's
  // pace is steadier than its heading: one noise low enough to hold a straight walk's speed steady
  // lets a turning walker's velocity cut the corner (its length sags), and one wide enough for the
  // turn shakes the straight walks' speed (simulated crossing and office, docs/tracking.md
  // "Session 38").
  const double q = noise_.accel_sigma_mps2 * noise_.accel_sigma_mps2;
  if (noise_.pace_accel_sigma_mps2 > 0.0) {
    if (const std::optional<Vec3> along = clearDirection(velocity())) {
      const double q_along = noise_.pace_accel_sigma_mps2 * noise_.pace_accel_sigma_mps2;
      const Mat3 T = *along * along->transpose();
      return T * q_along + (Mat3::Identity() - T) * q;
    }
  }
  return Mat3::Identity() * q;
}

KalmanCv::Mat6 KalmanCv::processNoise(double dt_s, const Mat3& accel_cov) {
  const double dt2 = dt_s * dt_s, dt3 = dt2 * dt_s;
  Mat6 Q = Mat6::Zero();
  Q.topLeftCorner<3, 3>() = accel_cov * dt3 / 3.0;
  Q.topRightCorner<3, 3>() = accel_cov * dt2 / 2.0;
  Q.bottomLeftCorner<3, 3>() = accel_cov * dt2 / 2.0;
  Q.bottomRightCorner<3, 3>() = accel_cov * dt_s;
  return Q;
}

void KalmanCv::predict(double dt_s) {
  if (!(dt_s > 0.0)) return;
  const Mat6 F = transition(dt_s);
  x_ = F * x_;
  P_ = F * P_ * F.transpose() + processNoise(dt_s, accelerationCovariance());
}

KalmanCv::Innovation KalmanCv::innovation(Eigen::MatrixXd H, const Eigen::VectorXd& z,
                                          Eigen::MatrixXd R) const {
  Innovation in;
  in.y = z - H * x_;
  in.S = H * P_ * H.transpose() + R;
  in.H = std::move(H);
  in.R = std::move(R);
  return in;
}

KalmanCv::Innovation KalmanCv::centreInnovation(
    const Vec3& p_world, const std::optional<Vec3>& v_world_mps,
    const std::optional<Mat3>& position_cov_world) const {
  const int m = v_world_mps ? 6 : 3;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, 6);
  H.leftCols(m) = Eigen::MatrixXd::Identity(m, m);
  Eigen::VectorXd z(m);
  z.head<3>() = p_world;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
  R.topLeftCorner<3, 3>() = position_cov_world.value_or(Mat3::Identity() * noise_.position_sigma_m *
                                                        noise_.position_sigma_m);
  if (v_world_mps) {
    z.tail<3>() = *v_world_mps;
    R.bottomRightCorner<3, 3>() =
        Mat3::Identity() * noise_.velocity_sigma_mps * noise_.velocity_sigma_mps;
  }
  return innovation(std::move(H), z, std::move(R));
}

void KalmanCv::correct(const Innovation& in) {
  const auto m = in.y.size();
  const Eigen::MatrixXd K =
      P_ * in.H.transpose() * in.S.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
  x_ += K * in.y;
  // Joseph form: stays symmetric positive semi-definite.
  const Mat6 I_KH = Mat6::Identity() - K * in.H;
  P_ = I_KH * P_ * I_KH.transpose() + K * in.R * K.transpose();
}

void KalmanCv::update(const Vec3& p_world, const std::optional<Vec3>& v_world_mps,
                      const std::optional<Mat3>& position_cov_world) {
  correct(centreInnovation(p_world, v_world_mps, position_cov_world));
}

void KalmanCv::reanchor(const Vec3& p_world, double part_offset_sigma_m,
                        const std::optional<Mat3>& position_cov_world) {
  P_.topRightCorner<3, 3>().setZero();
  P_.bottomLeftCorner<3, 3>().setZero();
  // The offset is opened along the directions the new centre measures; along one it leaves
  // unknown (a side cut by the image's edge) the predicted position stays the better estimate.
  const double offset_var = part_offset_sigma_m * part_offset_sigma_m;
  Mat3 opened = Mat3::Identity() * offset_var;
  if (position_cov_world) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(
        0.5 * (*position_cov_world + position_cov_world->transpose()));
    opened.setZero();
    for (int k = 0; k < 3; ++k)
      if (eig.eigenvalues()(k) < 0.25 * offset_var)
        opened += offset_var * eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose();
  }
  P_.topLeftCorner<3, 3>() += opened;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, 6);
  H.leftCols(3) = Eigen::MatrixXd::Identity(3, 3);
  const Mat3 R = position_cov_world.value_or(Mat3::Identity() * noise_.position_sigma_m *
                                             noise_.position_sigma_m);
  correct(innovation(std::move(H), p_world, R));
}

void KalmanCv::updateVelocity(const Vec3& v_world_mps) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, 6);
  H.rightCols(3) = Eigen::MatrixXd::Identity(3, 3);
  const double r = noise_.velocity_sigma_mps * noise_.velocity_sigma_mps;
  correct(innovation(std::move(H), v_world_mps, Eigen::MatrixXd::Identity(3, 3) * r));
}

void KalmanCv::updateVelocityAcross(const Vec3& v_world_mps, const Vec3& ray_world) {
  // Rows: an orthonormal basis of the plane normal to the ray, applied to the velocity.
  const Vec3 ray = ray_world.normalized();
  const Vec3 u = ray.unitOrthogonal(), w = ray.cross(u);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(2, 6);
  H.block<1, 3>(0, 3) = u.transpose();
  H.block<1, 3>(1, 3) = w.transpose();
  const Eigen::Vector2d z(u.dot(v_world_mps), w.dot(v_world_mps));
  const double r = noise_.velocity_sigma_mps * noise_.velocity_sigma_mps;
  correct(innovation(std::move(H), z, Eigen::MatrixXd::Identity(2, 2) * r));
}

void KalmanCv::updateVelocityAlong(const Vec3& axis_world, double v_mps, double sigma_mps) {
  if (!(sigma_mps > 0.0) || axis_world.norm() < 1e-9) return;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(1, 6);
  H.block<1, 3>(0, 3) = axis_world.normalized().transpose();
  Eigen::VectorXd z(1);
  z(0) = v_mps;
  correct(innovation(std::move(H), z, Eigen::MatrixXd::Constant(1, 1, sigma_mps * sigma_mps)));
}

bool KalmanCv::updateHeading(const Vec3& v_world_mps, const Vec3& up_world, double sigma_mps) {
  if (!(sigma_mps > 0.0) || up_world.norm() < 1e-9) return false;
  const Vec3 up = up_world.normalized();
  const std::optional<Vec3> travel = clearDirection(projectOntoPlane(velocity(), up));
  if (!travel) return false;
  const Vec3 across = up.cross(*travel).normalized();
  updateVelocityAlong(across, across.dot(v_world_mps), sigma_mps);
  return true;
}

double KalmanCv::normalisedInnovation(const Vec3& p_world, const std::optional<Vec3>& v_world_mps,
                                      const std::optional<Mat3>& position_cov_world) const {
  const Innovation in = centreInnovation(p_world, v_world_mps, position_cov_world);
  return in.y.dot(in.S.ldlt().solve(in.y));
}

void KalmanCv::holdStill() {
  x_.tail<3>().setZero();
  P_.topRightCorner<3, 3>().setZero();
  P_.bottomLeftCorner<3, 3>().setZero();
  P_.bottomRightCorner<3, 3>() = Mat3::Identity() * 1e-4;
}

void KalmanCv::reopen(double position_sigma_m, double velocity_sigma_mps) {
  P_.topLeftCorner<3, 3>() += Mat3::Identity() * position_sigma_m * position_sigma_m;
  P_.bottomRightCorner<3, 3>() += Mat3::Identity() * velocity_sigma_mps * velocity_sigma_mps;
}

std::optional<Vec3> KalmanCv::clearDirection(const Vec3& v_world_mps) const {
  if (!(v_world_mps.norm() > 2.0 * velocitySigma())) return std::nullopt;
  return v_world_mps.normalized();
}

double KalmanCv::velocitySigma() const {
  const Mat3 Pv = P_.bottomRightCorner<3, 3>();
  const double lambda =
      Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (Pv + Pv.transpose())).eigenvalues().maxCoeff();
  return std::sqrt(std::max(0.0, lambda));
}

std::vector<PathPoint> KalmanCv::predictPath(double horizon_s, double step_s) const {
  std::vector<PathPoint> path;
  if (!(step_s > 0.0)) return path;
  const Mat3 accel_cov = accelerationCovariance();  // one state: the same at every step
  for (double ahead = step_s; ahead <= horizon_s + 1e-9; ahead += step_s) {
    const Mat6 F = transition(ahead);
    const Mat6 P = F * P_ * F.transpose() + processNoise(ahead, accel_cov);
    const Mat3 Pp = P.topLeftCorner<3, 3>();
    const double lambda =
        Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (Pp + Pp.transpose())).eigenvalues().maxCoeff();
    path.push_back({ahead, (F * x_).head<3>(), std::sqrt(std::max(0.0, lambda))});
  }
  return path;
}

}  // namespace dynanav
