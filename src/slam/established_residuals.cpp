#include "slam/established_residuals.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "slam/frame_tracker.hpp"
#include "slam/observation_noise.hpp"

namespace dynanav {

namespace {
/// A match to a live map point, outlier or not.
bool anyMatch(const Frame& frame, int i) {
  const MapPointPtr& point = frame.map_points[i];
  return point && !point->bad && frame.features.usable[i];
}

bool usableMatch(const Frame& frame, int i) {
  return anyMatch(frame, i) && !frame.outlier[i];
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
/// Residuals of the matches `measured` accepts under the frame's pose refitted to the matches
/// `reference` accepts (all invalid with fewer than `min_matches` reference inliers).
std::vector<MapResidual> residualsUnderPoseOver(const Frame& frame, const TrackingConfig& config,
                                                int min_matches,
                                                const std::function<bool(int)>& reference,
                                                const std::function<bool(int)>& measured) {
  std::vector<MapResidual> residuals(frame.size());
  const Features& f = frame.features;
  if (!f.camera || !f.scales) return residuals;
  SE3 T_reference;
  std::vector<uint8_t> outlier;
  if (optimizePoseOver(frame, config, reference, T_reference, outlier) < std::max(1, min_matches))
    return residuals;
  for (int i = 0; i < frame.size(); ++i) {
    if (!measured(i)) continue;
    const Eigen::Vector2d r = residualPx(frame, i, T_reference);
    if (!std::isfinite(r.x())) continue;
    MapResidual& out = residuals[i];
    out.valid = true;
    out.young = isYoung(*frame.map_points[i]);
    out.outlier = frame.outlier[i] != 0;
    out.du_px = static_cast<float>(r.x());
    out.dv_px = static_cast<float>(r.y());
    out.sigma_px = std::sqrt(f.scales->sigma2[f.keypoints[i].octave]);
    const Eigen::Vector2d blur = blurSigmaPx(f, i);
    out.blurred = !blur.isZero();
    if (out.blurred) {
      const Eigen::Matrix3d W =
          measurementSqrtInformation(f.scales->inv_sigma2[f.keypoints[i].octave], blur, false);
      out.whitened = (W.topLeftCorner<2, 2>() * r).cast<float>();
    }
  }
  return residuals;
}
}  // namespace

std::vector<MapResidual> residualsToEstablishedPoints(const Frame& frame,
                                                      const TrackingConfig& config,
                                                      int min_established) {
  // The frame's pose refitted (robustly) to the established points alone. (A pose refitted to
  // the young points, to absorb their keyframe's common error, was tried: it absorbs a near
  // mover among them too, as the frame's own pose does.)
  const auto established = [&](int i) {
    return usableMatch(frame, i) && !isYoung(*frame.map_points[i]);
  };
  return residualsUnderPoseOver(frame, config, min_established, established,
                                [&](int i) { return usableMatch(frame, i); });
}

std::vector<MapResidual> residualsToBackground(const Frame& frame, const TrackingConfig& config,
                                               int min_established) {
  // The frame's own optimisation may have rejected the background (the object won): its
  // outliers are refitted too, and the object's rejected matches are measured.
  const auto background = [&](int i) {
    return anyMatch(frame, i) && !isYoung(*frame.map_points[i]) &&
           i < static_cast<int>(frame.features.instance_id.size()) &&
           frame.features.instance_id[i] == 0;
  };
  return residualsUnderPoseOver(frame, config, min_established, background,
                                [&](int i) { return anyMatch(frame, i); });
}

}  // namespace dynanav
