#include "assist/hazard.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {
namespace {

/// Standard deviation of u·x for x with covariance c (u a unit vector).
double sigmaAlong(const Eigen::Matrix2d& c, const Eigen::Vector2d& u) {
  return std::sqrt(std::max(0.0, u.dot(0.5 * (c + c.transpose()) * u)));
}

double normalCdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

double degrees(double rad) {
  return rad * 180.0 / M_PI;
}

}  // namespace

double corridorProbability(double miss_m, double sigma_m, double corridor_m) {
  if (sigma_m <= 1e-9) return std::abs(miss_m) <= corridor_m ? 1.0 : 0.0;
  return normalCdf((corridor_m - miss_m) / sigma_m) - normalCdf((-corridor_m - miss_m) / sigma_m);
}

int clockOf(double bearing_deg) {
  // 30 degrees per hour; 0 and 12 are the same direction (straight ahead).
  int clock = int(std::lround(bearing_deg / 30.0));
  clock = ((clock % 12) + 12) % 12;
  return clock == 0 ? 12 : clock;
}

Hazard assessHazard(const TrackedObject& o, const GroundMotion& motion, const BodyFrame& body,
                    const AssistConfig& config) {
  Hazard h;
  h.object_id = o.id;
  h.class_name = o.class_name;
  h.person = o.class_name == "person";
  h.seen = o.missed_frames == 0;
  h.p_world = o.p_world;
  const Eigen::Vector2d r_body = body.toBody(o.p_world);  // (right, forward)
  h.distance_m = r_body.norm();
  h.bearing_deg = degrees(std::atan2(r_body.x(), r_body.y()));
  h.clock = clockOf(h.bearing_deg);
  const Eigen::Vector2d v_object = o.dynamic ? motion.v : Eigen::Vector2d::Zero();
  h.speed_mps = v_object.norm();
  h.moving = o.dynamic && h.speed_mps >= config.moving_speed_mps;
  // Ground plane (world x, z): wearer -> object, and the object's velocity relative to the wearer.
  const Eigen::Vector2d r(o.p_world.x() - body.origin_world.x(),
                          o.p_world.z() - body.origin_world.z());
  const Eigen::Vector2d v_rel =
      v_object - Eigen::Vector2d(body.velocity_world_mps.x(), body.velocity_world_mps.z());
  h.closing_mps = r.norm() > 1e-6 ? -r.dot(v_rel) / r.norm() : 0.0;
  if (!h.moving) {
    // Direction and distance only; a static object counts when it stands in the corridor ahead.
    h.in_corridor_ahead = r_body.y() > 0.0 && std::abs(r_body.x()) <= config.corridor_m;
    return h;
  }
  // Relative constant-velocity motion r(t) = r + v_rel t: closest at t* = -r.v / |v|^2.
  const double v2 = v_rel.squaredNorm();
  const double t_star = v2 > 1e-9 ? -r.dot(v_rel) / v2 : 0.0;
  if (t_star <= 0.0) return h;  // the distance only grows from now on
  h.t_closest_s = t_star;
  h.closest_m = (r + t_star * v_rel).norm();
  // The miss distance is the relative position along n, the normal of the relative velocity.
  // Linearised, an error dp in the object's position and dv in its velocity move it by
  // n·(dp + t* dv) exactly (the direction change of n contributes t* n·dv), so its standard
  // deviation is that of the predicted position at t* along n (estimation uncertainty only, see
  // object_motion_fit.hpp: the predicted path's sigma_m adds the filter's process noise, possible
  // manoeuvres of 3 m after 3 s at 1 m/s^2, which would make every walker within 3 m
  // "user-related"). Uncertainty along the relative path (e.g. the sideways position of a walker
  // cut by the image edge, for one crossing in front) shifts the time of the closest approach,
  // not the miss distance.
  const double speed = std::sqrt(v2);
  const Eigen::Vector2d along = v_rel / speed;
  const Eigen::Vector2d normal(-along.y(), along.x());
  h.closest_sigma_m = sigmaAlong(motion.covarianceAt(t_star), normal);
  h.corridor_probability = corridorProbability(normal.dot(r), h.closest_sigma_m, config.corridor_m);
  if (h.closing_mps >= config.closing_min_mps) {
    h.ttc_s = t_star;
    // The same closest approach reached at a closing speed faster by ttc_sigmas sigmas of the
    // speed along the relative path: what a tracker that still underestimates the speed (it
    // lags) may be missing.
    h.ttc_warn_s = t_star * speed / (speed + config.ttc_sigmas * sigmaAlong(motion.cov_vv, along));
  }
  h.user_related = h.ttc_s >= 0.0 && h.ttc_warn_s <= config.user_horizon_s &&
                   h.corridor_probability >= config.corridor_min_probability;
  return h;
}

Hazard assessHazard(const TrackedObject& o, const BodyFrame& body, const AssistConfig& config) {
  return assessHazard(o, filterMotion(o), body, config);
}

}  // namespace dynanav
