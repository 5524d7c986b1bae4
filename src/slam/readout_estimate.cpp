#include "slam/readout_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "slam/keyframe.hpp"
#include "slam/rgbd_jacobian.hpp"

namespace dynanav {
namespace {

// As pose optimisation: chi2 95 % for 2 dof (pixel) and 3 dof (pixel + virtual right u).
constexpr double kHuberDelta2Mono = 5.991;
constexpr double kHuberDelta2Stereo = 7.815;

/// World-frame shift of a map point per second of readout error, averaged over its observing
/// keyframes (see the header), and the same weighted by each keyframe's readout used; false when
/// a keyframe's motion is not known.
bool mapPointShift(const MapPoint& point, Vec3& shift_per_s, Vec3& shift_used) {
  shift_per_s.setZero();
  shift_used.setZero();
  int n = 0;
  for (const auto& [kf, index] : point.observations) {
    if (kf->motion.interval_s <= 0.0) return false;
    const Vec3 p_kf = kf->T_camera_world() * point.p_world;
    const double s = kf->features.keypoints[index].pt.y / kf->features.camera->height - 0.5;
    // The keypoint's own shift, less the keyframe pose's: exp(-c) p = p - (rho + phi x p).
    const Eigen::Matrix<double, 6, 1>& c = kf->pose_shift_per_readout;
    const Vec3 d_kf = s * ((kf->motion.omega / kf->motion.interval_s).cross(p_kf) +
                           kf->motion.translation / kf->motion.interval_s) -
                      c.head<3>() - c.tail<3>().cross(p_kf);
    const Vec3 d_world = kf->T_world_camera().linear() * d_kf;
    shift_per_s += d_world;
    shift_used += kf->readout_used_s * d_world;
    ++n;
  }
  if (n == 0) return false;
  shift_per_s /= n;
  shift_used /= n;
  return true;
}

}  // namespace

ReadoutEvidence readoutEvidence(const Frame& frame, const KeypointMeasurements& observed,
                                const CameraVelocity& motion, double readout_used_s) {
  ReadoutEvidence evidence;
  const Features& f = frame.features;
  if (motion.interval_s <= 0.0 || f.size() == 0 || observed.points.size() != size_t(f.size()) ||
      observed.u_right.size() != size_t(f.size()))
    return evidence;
  const PinholeCamera& camera = *f.camera;
  // d(row camera point)/d(readout) is s * (omega x R_row_mid p_mid + v) with omega and v per
  // second (the velocity's rotation vector and translation are per frame interval).
  const Vec3 omega_per_s = motion.omega / motion.interval_s;
  const Vec3 velocity_mps = motion.translation / motion.interval_s;
  Eigen::Matrix<double, 7, 7> H = Eigen::Matrix<double, 7, 7>::Zero();
  Eigen::Matrix<double, 7, 1> b = Eigen::Matrix<double, 7, 1>::Zero();
  for (int i = 0; i < f.size(); ++i) {
    const MapPointPtr& point = frame.map_points[i];
    if (!point || frame.outlier[i] || !f.usable[i]) continue;
    Vec3 map_shift_per_s, map_shift_used;
    if (!mapPointShift(*point, map_shift_per_s, map_shift_used)) continue;
    const double s = f.keypoints[i].pt.y / camera.height - 0.5;  // the shutter's (raw) row
    const Vec3 p_mid = frame.T_camera_world * point->p_world;
    const SE3 T_row_mid = motionOver(motion, s * readout_used_s);
    const Vec3 p_row = T_row_mid * p_mid;
    if (p_mid.z() <= 0.0 || p_row.z() <= 0.0) continue;
    // With depth the pose was fitted to (u, v, u_right), without to (u, v): use the same rows.
    const int rows = observed.u_right[i] >= 0.f ? 3 : 2;
    const Eigen::Vector2d uv = camera.project(p_row);
    Eigen::Vector3d r(observed.points[i].x - uv.x(), observed.points[i].y - uv.y(),
                      observed.u_right[i] - (uv.x() - camera.bf() / p_row.z()));
    const Eigen::Matrix<double, 3, 3> J_pi =
        rgbdProjectionJacobian(camera.fx, camera.fy, camera.bf(), p_row);
    const Mat3 R_row_world = T_row_mid.linear() * frame.T_camera_world.linear();
    Eigen::Matrix<double, 3, 7> J;
    // Pose: left perturbation exp(xi) * T_camera_world, xi = (rho, phi).
    J.block<3, 3>(0, 0) = J_pi * T_row_mid.linear();
    J.block<3, 3>(0, 3) = -J_pi * T_row_mid.linear() * skewSymmetric(p_mid);
    // residual = J_pose xi + (own shear - map shift) R + what the readouts used already explain.
    const Eigen::Vector3d own_shear =
        J_pi * (s * (omega_per_s.cross(T_row_mid.linear() * p_mid) + velocity_mps));
    J.col(6) = own_shear - J_pi * R_row_world * map_shift_per_s;
    Eigen::Vector3d y = r + readout_used_s * own_shear - J_pi * R_row_world * map_shift_used;
    if (rows == 2) {
      J.row(2).setZero();
      y(2) = 0.0;
      r(2) = 0.0;
    }
    double w = f.scales->inv_sigma2[f.keypoints[i].octave];
    const double e2 = r.squaredNorm() * w;
    const double delta2 = rows == 3 ? kHuberDelta2Stereo : kHuberDelta2Mono;
    if (e2 > delta2) w *= std::sqrt(delta2 / e2);
    H.noalias() += w * J.transpose() * J;
    b.noalias() += w * J.transpose() * y;
    ++evidence.points;
  }
  if (evidence.points < ReadoutEstimator::kMinPoints) return evidence;
  // Marginalise the pose: what a pose change can explain is not evidence of the readout.
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> pose(H.topLeftCorner<6, 6>());
  if (pose.info() != Eigen::Success) return evidence;
  const Eigen::Matrix<double, 6, 1> coupling = H.block<6, 1>(0, 6);
  const Eigen::Matrix<double, 6, 1> pose_shift = pose.solve(coupling);
  const double information = H(6, 6) - coupling.dot(pose_shift);
  const double gradient = b(6) - coupling.dot(pose.solve(b.head<6>()));
  if (!(information > 0.0) || !std::isfinite(gradient)) return evidence;
  evidence.information_per_s2 = information;
  evidence.readout_s = gradient / information;
  evidence.pose_shift_per_s = pose_shift;
  // A frame whose estimate leaves [-1, 2] frame intervals has a wrong velocity or matches.
  evidence.valid =
      std::abs(evidence.readout_s - 0.5 * motion.interval_s) <= 1.5 * motion.interval_s;
  return evidence;
}

void ReadoutEstimator::add(const ReadoutEvidence& evidence) {
  if (!evidence.valid || evidence.points < kMinPoints ||
      evidence.information_per_s2 < kMinInformationPerS2)
    return;
  const double w = evidence.information_per_s2, x = evidence.readout_s;
  ++frames_;
  sum_w_ += w;
  sum_w2_ += w * w;
  sum_wx_ += w * x;
  sum_wx2_ += w * x * x;
}

double ReadoutEstimator::readoutS() const {
  return sum_w_ > 0.0 ? sum_wx_ / sum_w_ : 0.0;
}

double ReadoutEstimator::sigmaS() const {
  if (frames_ < kMinFrames) return std::numeric_limits<double>::infinity();
  const double mean = readoutS();
  const double scatter = std::max(0.0, sum_wx2_ / sum_w_ - mean * mean);
  const double effective_frames = sum_w_ * sum_w_ / sum_w2_;
  return std::sqrt(scatter / effective_frames);
}

}  // namespace dynanav
