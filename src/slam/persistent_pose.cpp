#include "slam/persistent_pose.hpp"

#include "slam/frame_tracker.hpp"

namespace dynanav {
namespace {

// chi-square at 99.9 % with 2 (u, v) and 3 (u, v, u_right) degrees of freedom: the judgement
// against a pose fitted to part of the matches is looser than pose optimisation's 95 %, so that
// only what that pose clearly cannot explain is left out.
constexpr double kChi2Mono999 = 13.82;
constexpr double kChi2Stereo999 = 16.27;

}  // namespace

bool isPersistentMatch(const Frame& frame, int keypoint, double min_age_s) {
  const MapPointPtr& point = frame.map_points[keypoint];
  return point && !point->bad && point->numObservations() > 0 &&
         frame.stamp_s - point->first_mapped_s >= min_age_s;
}

PersistentPose optimizePoseOnPersistentPoints(Frame& frame, const TrackingConfig& config) {
  PersistentPose result;
  const double age_s = config.persistent_point_age_s;
  if (!(age_s > 0.0)) return result;
  std::vector<uint8_t> persistent(frame.size(), 0);
  for (int i = 0; i < frame.size(); ++i) {
    persistent[i] = isPersistentMatch(frame, i, age_s);
    result.persistent += persistent[i];
  }
  if (result.persistent < config.persistent_min_matches) return result;
  // The pose on the persistent matches alone.
  SE3 T_persistent;
  std::vector<uint8_t> outlier;
  optimizePoseOver(
      frame, config, [&](int i) { return persistent[i] != 0; }, T_persistent, outlier);
  // Every other match judged against it; a persistent match that fit rejected stays out too
  // (a person who stood for seconds and walks off).
  const PoseCamera camera = poseCamera(*frame.features.camera);
  std::vector<uint8_t> rejected(frame.size(), 0);
  for (int i = 0; i < frame.size(); ++i) {
    if (persistent[i]) {
      rejected[i] = outlier[i];
      continue;
    }
    if (!frame.map_points[i]) continue;
    const PoseObservation obs = poseObservation(frame, i);
    const double threshold = obs.u_right >= 0.0 ? kChi2Stereo999 : kChi2Mono999;
    rejected[i] = reprojectionChi2(obs, camera, T_persistent) > threshold;
    result.rejected += rejected[i];
  }
  // Refined from there on everything that passed.
  frame.T_camera_world = T_persistent;
  SE3 T_final;
  optimizePoseOver(
      frame, config, [&](int i) { return rejected[i] == 0; }, T_final, outlier);
  frame.T_camera_world = T_final;
  for (int i = 0; i < frame.size(); ++i) frame.outlier[i] = rejected[i] || outlier[i];
  result.applied = true;
  return result;
}

}  // namespace dynanav
