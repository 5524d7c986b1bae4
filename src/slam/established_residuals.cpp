#include "slam/established_residuals.hpp"

#include <algorithm>
#include <cmath>

#include "slam/pose_optimizer.hpp"

namespace dynanav {

namespace {
bool usableMatch(const Frame& frame, int i) {
  const MapPointPtr& point = frame.map_points[i];
  return point && !frame.outlier[i] && !point->bad && frame.features.usable[i];
}

bool isYoung(const MapPoint& point) {
  return point.observations.size() < 2;
}

/// The frame's pose refitted (robustly, from its current pose) to the matches whose point is
/// young (`young`) or established; false if fewer than `min_matches` are inliers. (A pose refitted
/// to the young points was tried to absorb their keyframe's common error: it absorbs a near
/// mover among them too, as the frame's own pose does.)
bool refitPose(const Frame& frame, bool young, const TrackingConfig& config, int min_matches,
               SE3& T_camera_world) {
  const Features& f = frame.features;
  std::vector<PoseObservation> observations;
  for (int i = 0; i < frame.size(); ++i) {
    if (!usableMatch(frame, i) || isYoung(*frame.map_points[i]) != young) continue;
    PoseObservation obs;
    obs.p_world = frame.map_points[i]->p_world;
    obs.u = f.points[i].x;
    obs.v = f.points[i].y;
    obs.u_right = f.u_right[i];
    obs.inv_sigma2 = f.scales->inv_sigma2[f.keypoints[i].octave];
    observations.push_back(obs);
  }
  if (static_cast<int>(observations.size()) < min_matches) return false;
  const PinholeCamera& cam = *f.camera;
  const PoseCamera camera{cam.fx, cam.fy, cam.cx, cam.cy, cam.bf()};
  PoseOptimizerOptions options;
  options.rounds = config.pose_rounds;
  options.iterations_per_round = config.pose_iterations;
  T_camera_world = frame.T_camera_world;
  std::vector<uint8_t> outlier;
  return optimizePose(observations, camera, options, T_camera_world, outlier) >= min_matches;
}

Eigen::Vector2d residualPx(const Frame& frame, int i, const SE3& T_camera_world) {
  const Vec3 p_camera = T_camera_world * frame.map_points[i]->p_world;
  if (!(p_camera.z() > 0.0)) return {NAN, NAN};
  const Eigen::Vector2d uv = frame.features.camera->project(p_camera);
  return {frame.features.points[i].x - uv.x(), frame.features.points[i].y - uv.y()};
}
}  // namespace

std::vector<MapResidual> residualsToEstablishedPoints(const Frame& frame,
                                                      const TrackingConfig& config,
                                                      int min_established) {
  std::vector<MapResidual> residuals(frame.size());
  const Features& f = frame.features;
  const int min_matches = std::max(1, min_established);
  SE3 T_established;
  if (!f.camera || !f.scales || !refitPose(frame, false, config, min_matches, T_established))
    return residuals;
  for (int i = 0; i < frame.size(); ++i) {
    if (!usableMatch(frame, i)) continue;
    const Eigen::Vector2d r = residualPx(frame, i, T_established);
    if (!std::isfinite(r.x())) continue;
    MapResidual& out = residuals[i];
    out.valid = true;
    out.young = isYoung(*frame.map_points[i]);
    out.du_px = static_cast<float>(r.x());
    out.dv_px = static_cast<float>(r.y());
    out.sigma_px = std::sqrt(f.scales->sigma2[f.keypoints[i].octave]);
  }
  return residuals;
}

}  // namespace dynanav
