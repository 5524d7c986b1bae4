#include "slam/established_residuals.hpp"

#include <algorithm>
#include <cmath>

#include "slam/frame_tracker.hpp"

namespace dynanav {

namespace {
bool usableMatch(const Frame& frame, int i) {
  const MapPointPtr& point = frame.map_points[i];
  return point && !frame.outlier[i] && !point->bad && frame.features.usable[i];
}

bool isYoung(const MapPoint& point) {
  return point.observations.size() < 2;
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
  if (!f.camera || !f.scales) return residuals;
  // The frame's pose refitted (robustly) to the established points alone. (A pose refitted to
  // the young points, to absorb their keyframe's common error, was tried: it absorbs a near
  // mover among them too, as the frame's own pose does.)
  const auto established = [&](int i) {
    return usableMatch(frame, i) && !isYoung(*frame.map_points[i]);
  };
  SE3 T_established;
  std::vector<uint8_t> outlier;
  if (optimizePoseOver(frame, config, established, T_established, outlier) < min_matches)
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
