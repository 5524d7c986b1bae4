#pragma once
// Each object's ground-plane motion for the hazard test, measured over a short window of its own
// track positions (issue 14). The tracker's Kalman velocity reacts within a frame to a jump of
// the tracked points (a resampled mask moves the centre by 10 cm: 3 m/s for one frame) and its
// covariance is overconfident (velocity sigma ~0.2 m/s while the measured speed error is
// 0.14-0.39 m/s RMSE, docs/tracking.md). A least-squares line through the last
// velocity_window_s of centres gives a velocity that a single jump barely moves, and its
// residuals give an uncertainty measured on this very track. Until a track has
// velocity_min_span_s of history, its filter state and covariance are used.
#include <Eigen/Core>
#include <deque>
#include <map>
#include <vector>

#include "core/config/assist.hpp"
#include "core/tracked_object.hpp"

namespace dynanav {

/// Ground-plane (world x, z) state of an object: position now, velocity, their covariance.
struct GroundMotion {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();  ///< (x, z) now (m)
  Eigen::Vector2d v = Eigen::Vector2d::Zero();  ///< (vx, vz) (m/s)
  Eigen::Matrix2d cov_pp = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d cov_pv = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d cov_vv = Eigen::Matrix2d::Zero();
  bool fitted = false;  ///< from the position history (false: the tracker's filter)
  /// Covariance of the position `ahead_s` from now (constant velocity, no manoeuvres).
  [[nodiscard]] Eigen::Matrix2d covarianceAt(double ahead_s) const {
    return cov_pp + ahead_s * (cov_pv + cov_pv.transpose()) + ahead_s * ahead_s * cov_vv;
  }
};

/// The tracker's own estimate, on the ground plane (a static object: zero velocity).
GroundMotion filterMotion(const TrackedObject& object);

/// Line fit p = a + b (t - t_now) through (t, p) samples, each weighted by the inverse of its
/// covariance cov_p[i] (none given: zero) plus noise_m^2 I; false when under 3 samples or a span
/// under min_span_s. The covariance of the line is scaled up per axis when the residuals exceed
/// what the weights expect, never down (a perfect line is not certain); that per-axis check uses
/// the weights' diagonals, exact for axis-aligned covariances and an approximation for rotated
/// ones (the line itself uses the full weights). With no cov_p it is the
/// ordinary per-axis least-squares line with its residual variance floored at noise_m^2.
bool fitLine(const std::vector<double>& t_s, const std::vector<Eigen::Vector2d>& p, double t_now_s,
             double min_span_s, double noise_m, GroundMotion& out,
             const std::vector<Eigen::Matrix2d>& cov_p = {});

class MotionHistory {
 public:
  explicit MotionHistory(const AssistConfig& config) : config_(config) {}
  /// Adds this frame's object centres (tracks not in `objects` are forgotten) and returns each
  /// object's motion, in the objects' order.
  std::vector<GroundMotion> update(double stamp_s, const std::vector<TrackedObject>& objects);

 private:
  struct Sample {
    double stamp_s;
    Eigen::Vector2d p;
    Eigen::Matrix2d cov_p;  ///< the tracker's position covariance then
  };
  AssistConfig config_;
  std::map<uint64_t, std::deque<Sample>> samples_;  // by track id
};

}  // namespace dynanav
