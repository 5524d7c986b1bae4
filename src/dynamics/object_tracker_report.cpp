#include "dynamics/object_tracker.hpp"

// What a track reports each frame (TrackedObject): the filter's state in the world and the
// camera, the view geometry, the covariance with a ranged person's common stature error, and
// the predicted path (object_tracker.cpp keeps the tracks).
#include <cmath>

#include "dynamics/height_range.hpp"

namespace dynanav {

TrackedObject ObjectTracker::report(const Track& t, const ObjectTrackerInput& input) const {
  TrackedObject o;
  o.id = t.id;
  o.class_name = t.class_name;
  o.dynamic = !t.stationary;
  o.p_world = t.filter.position();
  o.v_world_mps = t.stationary ? Vec3::Zero() : t.filter.velocity();
  // A new track's velocity is its prior (zero, sigma 1 m/s) until measurements narrow it.
  o.velocity_known = t.stationary || filterVelocityKnown(t);
  o.p_camera = input.T_world_camera.inverse() * o.p_world;
  fillViewGeometry(o);
  o.points = int(t.pixels.size());
  o.covariance = t.filter.covariance();
  const Vec3 camera_world = input.T_world_camera.translation();
  if (t.ranged_scale_sigma > 0.0)
    o.covariance +=
        statureCovariance(o.p_world, t.filter.velocity(), camera_world, t.ranged_scale_sigma);
  o.missed_frames = t.missed;
  o.motion_inliers = t.inliers;
  o.restarted = t.restarted;
  o.reanchored = t.reanchored;
  if (!t.stationary) {
    o.predicted_path = t.filter.predictPath(config_.path_horizon_s, config_.path_step_s);
    // The stature's error along the predicted ray (an upper bound of the largest eigenvalue).
    if (t.ranged_scale_sigma > 0.0)
      for (PathPoint& p : o.predicted_path)
        p.sigma_m = std::hypot(p.sigma_m, t.ranged_scale_sigma * (p.p_world - camera_world).norm());
  }
  return o;
}

}  // namespace dynanav
