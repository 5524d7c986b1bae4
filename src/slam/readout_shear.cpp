#include "slam/readout_shear.hpp"

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
    const double inv_z = 1.0 / p.z();
    const double du = camera.fx * inv_z * (dp_per_s.x() - p.x() * inv_z * dp_per_s.z());
    const double dv = camera.fy * inv_z * (dp_per_s.y() - p.y() * inv_z * dp_per_s.z());
    const double d_inv_z = -inv_z * inv_z * dp_per_s.z();
    obs.readout_px_per_s = row_offset * Vec3(du, dv, du - camera.bf() * d_inv_z);
  }
}

bool adoptReadout(Map& map, const BaProblem& problem, const BaResult& result) {
  if (!problem.estimate_readout || !(result.readout_sigma_s <= map.readout.adopt_sigma_s))
    return false;
  map.readout.readout_s = problem.readout_s;
  map.readout.sigma_s = result.readout_sigma_s;
  map.readout.window_keyframes = static_cast<int>(problem.keyframes.size());
  ++map.readout.adopted;
  return true;
}

}  // namespace dynanav
