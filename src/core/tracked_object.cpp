#include "core/tracked_object.hpp"

#include <cmath>

namespace dynanav {

void fillViewGeometry(TrackedObject& object) {
  const Vec3& p = object.p_camera;
  object.distance_m = p.norm();
  object.bearing_deg = std::atan2(p.x(), p.z()) * 180.0 / M_PI;
  // 30 degrees per hour; 0 and 12 are the same direction (straight ahead).
  int clock = int(std::lround(object.bearing_deg / 30.0));
  clock = ((clock % 12) + 12) % 12;
  object.clock = clock == 0 ? 12 : clock;
  const Vec3& v = object.v_world_mps;
  object.speed_mps = v.norm();
  object.heading_deg = object.speed_mps > 0.0 ? std::atan2(v.x(), v.z()) * 180.0 / M_PI : 0.0;
}

}  // namespace dynanav
