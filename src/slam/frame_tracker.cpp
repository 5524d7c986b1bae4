#include "slam/frame_tracker.hpp"

#include <functional>

#include "slam/matcher.hpp"
#include "slam/observation_noise.hpp"
#include "slam/persistent_pose.hpp"
#include "slam/pose_optimizer.hpp"

namespace dynanav {

PoseObservation poseObservation(const Frame& frame, int keypoint) {
  const Features& f = frame.features;
  PoseObservation obs;
  obs.p_world = frame.map_points[keypoint]->p_world;
  obs.u = f.points[keypoint].x;
  obs.v = f.points[keypoint].y;
  obs.u_right = f.u_right[keypoint];
  obs.inv_sigma2 = f.scales->inv_sigma2[f.keypoints[keypoint].octave];
  obs.blur_sigma_px = blurSigmaPx(f, keypoint);
  return obs;
}

PoseCamera poseCamera(const PinholeCamera& cam) {
  return {cam.fx, cam.fy, cam.cx, cam.cy, cam.bf()};
}

int optimizePoseOver(const Frame& frame, const TrackingConfig& config,
                     const std::function<bool(int)>& use, SE3& T_camera_world,
                     std::vector<uint8_t>& outlier) {
  const Features& f = frame.features;
  const PinholeCamera& cam = *f.camera;
  std::vector<PoseObservation> observations;
  std::vector<int> keypoint_of;
  outlier.assign(frame.size(), 0);
  for (int i = 0; i < frame.size(); ++i) {
    const MapPointPtr& point = frame.map_points[i];
    if (!point || !use(i)) continue;
    observations.push_back(poseObservation(frame, i));
    keypoint_of.push_back(i);
  }
  const PoseCamera camera = poseCamera(cam);
  PoseOptimizerOptions options;
  options.rounds = config.pose_rounds;
  options.iterations_per_round = config.pose_iterations;
  T_camera_world = frame.T_camera_world;
  std::vector<uint8_t> used_outlier;
  DepthAlignment depth;
  if (config.depth_alignment_samples > 0.0) {
    depth.surface = &frame.depth_surface;
    depth.points_world = &frame.depth_reference_world;
    depth.effective_samples = config.depth_alignment_samples;
    depth.min_sigma_m = config.depth_alignment_min_sigma_m;
  }
  const int inliers =
      optimizePose(observations, camera, options, T_camera_world, used_outlier, depth);
  for (size_t k = 0; k < keypoint_of.size(); ++k) outlier[keypoint_of[k]] = used_outlier[k];
  return inliers;
}

int optimizeFramePose(Frame& frame, const TrackingConfig& config) {
  return optimizePoseOver(
      frame, config, [](int) { return true; }, frame.T_camera_world, frame.outlier);
}

int discardOutliers(Frame& frame) {
  int map_matches = 0;
  for (int i = 0; i < frame.size(); ++i) {
    if (!frame.map_points[i]) continue;
    if (frame.outlier[i]) {
      frame.map_points[i].reset();
      frame.outlier[i] = 0;
    } else if (frame.map_points[i]->numObservations() > 0) {
      ++map_matches;
    }
  }
  return map_matches;
}

bool trackWithMotionModel(Frame& current, const Frame& last, const SE3& T_current_last,
                          const TrackingConfig& config) {
  current.T_camera_world = orthonormalized(T_current_last * last.T_camera_world);
  current.clearMatches();
  int matches = matcher::matchLastFrame(current, last, config.motion_search_radius_px, true);
  if (matches < config.motion_min_matches) {  // retry with a wider window
    current.clearMatches();
    matches = matcher::matchLastFrame(current, last, 2.0f * config.motion_search_radius_px, true);
  }
  if (matches < config.motion_min_matches) return false;
  optimizeFramePose(current, config);
  return discardOutliers(current) >= config.min_map_matches;
}

bool trackReferenceKeyFrame(Frame& current, const KeyFrame& reference, const SE3& initial_pose,
                            const TrackingConfig& config) {
  current.clearMatches();
  const int matches = matcher::matchKeyFrame(reference, current, 0.7f, true);
  if (matches < config.reference_min_matches) return false;
  current.T_camera_world = initial_pose;
  optimizeFramePose(current, config);
  return discardOutliers(current) >= config.min_map_matches;
}

int trackLocalMap(Frame& frame, const std::map<uint64_t, KeyFramePtr>& keyframes,
                  const TrackingConfig& config, LocalMap& local) {
  updateLocalMap(frame, keyframes, config.max_local_keyframes, local);
  // Points already matched count as seen; the others are searched where they project.
  for (auto& point : frame.map_points) {
    if (!point) continue;
    if (point->bad) {
      point.reset();
      continue;
    }
    ++point->visible;
    point->last_seen_frame = frame.id;
    point->track_in_view = false;
  }
  const Vec3 center = frame.center();
  int to_match = 0;
  for (const auto& point : local.points) {
    if (point->last_seen_frame == frame.id || point->bad) continue;
    if (prepareProjection(frame, center, *point)) {
      ++point->visible;
      ++to_match;
    }
  }
  if (to_match > 0) {
    matcher::matchLocalPoints(frame, local.points,
                              static_cast<float>(config.local_search_radius_factor),
                              static_cast<float>(config.local_nn_ratio));
  }
  // Movers nobody masked can outnumber the static points: the pose is found on the part of the
  // map that has stayed put for a while when enough of it is in view (slam/persistent_pose).
  if (!optimizePoseOnPersistentPoints(frame, config).applied) optimizeFramePose(frame, config);
  int inliers = 0;
  for (int i = 0; i < frame.size(); ++i) {
    const MapPointPtr& point = frame.map_points[i];
    if (!point) continue;
    if (frame.outlier[i]) {
      frame.map_points[i].reset();
      frame.outlier[i] = 0;
      continue;
    }
    ++point->found;
    if (point->numObservations() > 0) ++inliers;
  }
  return inliers;
}

}  // namespace dynanav
