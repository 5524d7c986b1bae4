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
             double min_span_s, double noise_m, GroundMotion& out) {
  const size_t n = t_s.size();
  if (n < 3 || t_s.back() - t_s.front() < min_span_s) return false;
  double tau_mean = 0.0;
  Eigen::Vector2d p_mean = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) {
    tau_mean += t_s[i] - t_now_s;
    p_mean += p[i];
  }
  tau_mean /= double(n);
  p_mean /= double(n);
  double s_tt = 0.0;
  Eigen::Vector2d s_tp = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const double dt = t_s[i] - t_now_s - tau_mean;
    s_tt += dt * dt;
    s_tp += dt * (p[i] - p_mean);
  }
  const Eigen::Vector2d b = s_tp / s_tt;
  const Eigen::Vector2d a = p_mean - b * tau_mean;
  // Residual variance per axis (n - 2 degrees of freedom), floored by the measurement noise.
  Eigen::Vector2d rss = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d r = p[i] - (a + b * (t_s[i] - t_now_s));
    rss += r.cwiseProduct(r);
  }
  const double floor = noise_m * noise_m;
  const Eigen::Vector2d s2 = (rss / double(n - 2)).cwiseMax(floor);
  out.p = a;
  out.v = b;
  out.cov_vv = (s2 / s_tt).asDiagonal();
  out.cov_pp = (s2 * (1.0 / double(n) + tau_mean * tau_mean / s_tt)).asDiagonal();
  out.cov_pv = (-s2 * tau_mean / s_tt).asDiagonal();
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
    if (auto it = samples_.find(o.id); it != samples_.end()) history = std::move(it->second);
    history.push_back({stamp_s, {o.p_world.x(), o.p_world.z()}});
    while (stamp_s - history.front().stamp_s > config_.velocity_window_s) history.pop_front();
    GroundMotion m = filterMotion(o);
    if (o.dynamic) {
      std::vector<double> t;
      std::vector<Eigen::Vector2d> p;
      for (const Sample& s : history) t.push_back(s.stamp_s), p.push_back(s.p);
      GroundMotion fit;
      if (fitLine(t, p, stamp_s, config_.velocity_min_span_s, config_.position_noise_m, fit)) {
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
