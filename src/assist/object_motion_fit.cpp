#include "assist/object_motion_fit.hpp"

#include <algorithm>

namespace dynanav {
namespace {

Eigen::Matrix2d ground(const Eigen::Matrix3d& c) {
  Eigen::Matrix2d g;
  g << c(0, 0), c(0, 2), c(2, 0), c(2, 2);
  return g;
}

}  // namespace

GroundMotion filterMotion(const TrackedObject& o) {
  GroundMotion m;
  m.p = {o.p_world.x(), o.p_world.z()};
  if (o.dynamic) m.v = {o.v_world_mps.x(), o.v_world_mps.z()};
  m.cov_pp = ground(o.covariance.topLeftCorner<3, 3>());
  m.cov_pv = ground(o.covariance.topRightCorner<3, 3>());
  m.cov_vv = ground(o.covariance.bottomRightCorner<3, 3>());
  return m;
}

bool fitLine(const std::vector<double>& t_s, const std::vector<Eigen::Vector2d>& p, double t_now_s,
             double min_span_s, double noise_m, GroundMotion& out,
             const std::vector<Eigen::Matrix2d>& cov_p) {
  const size_t n = t_s.size();
  if (n < 3 || t_s.back() - t_s.front() < min_span_s) return false;
  // Weighted least squares for x = [a; b], p_i = a + b tau_i + e_i, e_i ~ N(0, C_i + noise^2 I):
  // a centre whose sideways position a partial view could not measure (1 m sigma from the
  // tracker) barely pulls the line that way, and if all of them are such, the fit says so.
  using Mat4 = Eigen::Matrix4d;
  Mat4 normal = Mat4::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  std::vector<Eigen::Matrix2d> weight(n);
  const Eigen::Matrix2d floor = noise_m * noise_m * Eigen::Matrix2d::Identity();
  for (size_t i = 0; i < n; ++i) {
    Eigen::Matrix2d c = Eigen::Matrix2d::Zero();
    if (i < cov_p.size()) c = 0.5 * (cov_p[i] + cov_p[i].transpose());
    weight[i] = (c + floor).inverse();
    Eigen::Matrix<double, 2, 4> h;
    h << Eigen::Matrix2d::Identity(), (t_s[i] - t_now_s) * Eigen::Matrix2d::Identity();
    normal += h.transpose() * weight[i] * h;
    rhs += h.transpose() * weight[i] * p[i];
  }
  const Mat4 normal_inv = normal.inverse();
  const Eigen::Vector4d x = normal_inv * rhs;
  // Residuals larger than the assumed noise (the walker sways, the mask jumps) scale the
  // covariance per axis, as a per-axis variance estimate with n - 2 degrees of freedom would;
  // smaller ones do not shrink it (a perfect line is not certain).
  Eigen::Vector2d chi2 = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e = p[i] - x.head<2>() - (t_s[i] - t_now_s) * x.tail<2>();
    chi2 += (weight[i].diagonal().array() * e.array().square()).matrix();
  }
  const Eigen::Vector2d scale = (chi2 / double(n - 2)).cwiseMax(1.0).cwiseSqrt();
  Eigen::Vector4d d;
  d << scale, scale;
  const Mat4 cov = d.asDiagonal() * normal_inv * d.asDiagonal();
  out.p = x.head<2>();
  out.v = x.tail<2>();
  out.cov_pp = cov.topLeftCorner<2, 2>();
  out.cov_pv = cov.topRightCorner<2, 2>();
  out.cov_vv = cov.bottomRightCorner<2, 2>();
  out.fitted = true;
  return true;
}

std::vector<GroundMotion> MotionHistory::update(double stamp_s,
                                                const std::vector<TrackedObject>& objects) {
  std::map<uint64_t, std::deque<Sample>> kept;
  std::vector<GroundMotion> motions;
  motions.reserve(objects.size());
  for (const TrackedObject& o : objects) {
    std::deque<Sample>& history = kept[o.id];
    // A restarted or reanchored track's earlier centres belong to another extent or part of it:
    // a line from them to this one is not its motion. (Shifting them by the reanchoring's jump
    // instead kept the drift of the centres before it: three real-time replays of static
    // fr1_xyz spoke 5 false urgent warnings that way, 2 with the history restarted,
    // docs/tracking.md "Session 22".)
    if (auto it = samples_.find(o.id); it != samples_.end() && !o.restarted && !o.reanchored)
      history = std::move(it->second);
    GroundMotion m = filterMotion(o);
    history.push_back({stamp_s, m.p, m.cov_pp});
    while (stamp_s - history.front().stamp_s > config_.velocity_window_s) history.pop_front();
    if (o.dynamic) {
      std::vector<double> t;
      std::vector<Eigen::Vector2d> p;
      std::vector<Eigen::Matrix2d> cov;
      for (const Sample& s : history)
        t.push_back(s.stamp_s), p.push_back(s.p), cov.push_back(s.cov_p);
      GroundMotion fit;
      if (fitLine(t, p, stamp_s, config_.velocity_min_span_s, config_.position_noise_m, fit, cov)) {
        // The filter's current centre is the newest measurement's best estimate; the line
        // gives the motion (their cross-covariance is not known: taken as none).
        fit.p = m.p;
        fit.cov_pp = m.cov_pp;
        fit.cov_pv.setZero();
        m = fit;
      }
    }
    motions.push_back(m);
  }
  samples_ = std::move(kept);
  return motions;
}

}  // namespace dynanav
