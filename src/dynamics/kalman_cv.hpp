#pragma once
// Constant-velocity Kalman filter of an object's centre in the world frame: state x = [p, v]
// (m, m/s), white-noise acceleration of spectral density accel_sigma^2 (the discretised
// process noise of Bar-Shalom, "Estimation with Applications to Tracking", §6.3.2); once the
// direction of travel is clear, pace_accel_sigma^2 along it (people change their pace less
// readily than their heading). Measurements are the centre (from the object's points) and, when
// the rigid motion was estimated, the centroid velocity; both enter in one update with their own
// noise.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/se3.hpp"
#include "core/tracked_object.hpp"

namespace dynanav {

struct KalmanCvNoise {
  double accel_sigma_mps2 = 1.0;    ///< process noise: unmodelled acceleration
  double position_sigma_m = 0.05;   ///< centre measurement
  double velocity_sigma_mps = 0.6;  ///< one-frame centroid velocity measurement
  double initial_velocity_sigma_mps = 1.0;
  /// Process noise along the direction of travel once it is clear (clearDirection);
  /// accel_sigma_mps2 stays across it. 0: accel_sigma_mps2 in every direction.
  double pace_accel_sigma_mps2 = 0.0;
};

class KalmanCv {
 public:
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  using Mat6 = Eigen::Matrix<double, 6, 6>;

  KalmanCv() = default;
  /// Starts at p_world, with `position_cov_world` (m^2) or the configured isotropic noise.
  KalmanCv(const Vec3& p_world, const KalmanCvNoise& noise,
           const std::optional<Mat3>& position_cov_world = std::nullopt);

  /// Moves the state dt_s seconds ahead.
  void predict(double dt_s);
  /// Position measurement, optionally with a velocity measurement; `position_cov_world` (m^2)
  /// replaces the configured isotropic noise of this one position measurement.
  void update(const Vec3& p_world, const std::optional<Vec3>& v_world_mps,
              const std::optional<Mat3>& position_cov_world = std::nullopt);
  /// A centre that places the object but whose difference from the earlier ones is not motion (it
  /// was measured on another part of the object, up to `part_offset_sigma_m` from the last): the
  /// position's variance grows by that offset's along the directions the centre measures (those
  /// `position_cov_world` leaves within half the offset) and the position alone is updated; the
  /// velocity and its covariance stay (their correlation with the position is dropped first, so
  /// neither the offset nor the innovation leaks into the velocity, now or in the next frames).
  void reanchor(const Vec3& p_world, double part_offset_sigma_m,
                const std::optional<Mat3>& position_cov_world = std::nullopt);
  /// A velocity measurement alone (with the configured one-frame velocity noise).
  void updateVelocity(const Vec3& v_world_mps);
  /// The same for the two components of the velocity across `ray_world` (the line of sight):
  /// the component along it is not measured (a sliver's motion, biased along the ray).
  void updateVelocityAcross(const Vec3& v_world_mps, const Vec3& ray_world);
  /// One component of the velocity, along the unit `axis_world`, measured as v_mps +- sigma_mps
  /// (a pseudo-measurement of what is known without looking: a walker's vertical velocity).
  void updateVelocityAlong(const Vec3& axis_world, double v_mps, double sigma_mps);
  /// The heading a velocity measurement gives: its component across the filtered direction of
  /// travel in the plane normal to `up_world` (the floor's), +- sigma_mps; its length along that
  /// direction does not enter. Nothing while that direction is not known (the level speed within
  /// twice the velocity's sigma). Returns whether it entered.
  bool updateHeading(const Vec3& v_world_mps, const Vec3& up_world, double sigma_mps);
  /// The squared Mahalanobis distance of that measurement from the prediction (its normalised
  /// innovation, chi-square with 3 or 6 degrees of freedom when the filter is consistent):
  /// how far outside what the covariance allows a measurement lies, before it is used.
  [[nodiscard]] double normalisedInnovation(
      const Vec3& p_world, const std::optional<Vec3>& v_world_mps,
      const std::optional<Mat3>& position_cov_world = std::nullopt) const;
  /// Adds Q to the state's covariance: uncertainty the measurements so far shared and the filter
  /// was not told of (the stature behind every height range of one person, object_tracker.cpp).
  void addCovariance(const Mat6& Q) { P_ += 0.5 * (Q + Q.transpose()); }
  /// Sets the velocity to zero with a small variance (a static object).
  void holdStill();
  /// Undoes what an assumption about the state claimed to know (holdStill's zero velocity, a
  /// centre predicted at a standstill): adds isotropic variance (sigma^2) to the position and
  /// the velocity, so the next measurements set them afresh.
  void reopen(double position_sigma_m, double velocity_sigma_mps);

  [[nodiscard]] Vec3 position() const { return x_.head<3>(); }
  [[nodiscard]] Vec3 velocity() const { return x_.tail<3>(); }
  [[nodiscard]] const Mat6& covariance() const { return P_; }
  /// The unit direction of `v_world_mps` (the filtered velocity or a part of it) when its length
  /// is more than twice the velocity's sigma: the filter knows which way the object goes.
  [[nodiscard]] std::optional<Vec3> clearDirection(const Vec3& v_world_mps) const;
  /// Standard deviation of the velocity along its least certain axis (m/s).
  [[nodiscard]] double velocitySigma() const;
  /// Predicted centre every step_s up to horizon_s, with its spread.
  [[nodiscard]] std::vector<PathPoint> predictPath(double horizon_s, double step_s) const;

 private:
  [[nodiscard]] Mat6 transition(double dt_s) const;
  /// The white-noise acceleration's covariance (spectral density) at the current state: isotropic,
  /// or split along and across a clear direction of travel.
  [[nodiscard]] Mat3 accelerationCovariance() const;
  /// The discretised process noise over dt_s for that acceleration covariance.
  [[nodiscard]] static Mat6 processNoise(double dt_s, const Mat3& accel_cov);
  /// A linear measurement z = H x + noise (R), and its innovation against the current state.
  struct Innovation {
    Eigen::MatrixXd H, R;
    Eigen::VectorXd y;  ///< measurement minus prediction
    Eigen::MatrixXd S;  ///< its covariance
  };
  [[nodiscard]] Innovation innovation(Eigen::MatrixXd H, const Eigen::VectorXd& z,
                                      Eigen::MatrixXd R) const;
  /// The centre (and velocity) measurement of update() and normalisedInnovation().
  [[nodiscard]] Innovation centreInnovation(const Vec3& p_world,
                                            const std::optional<Vec3>& v_world_mps,
                                            const std::optional<Mat3>& position_cov_world) const;
  /// The Kalman correction with that innovation (Joseph form).
  void correct(const Innovation& in);
  KalmanCvNoise noise_;
  Vec6 x_ = Vec6::Zero();
  Mat6 P_ = Mat6::Identity();
};

}  // namespace dynanav
