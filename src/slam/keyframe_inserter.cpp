#include "slam/keyframe_inserter.hpp"

#include <algorithm>

namespace dynanav {

bool needNewKeyFrame(const Frame& frame, const KeyFrame& reference, const KeyFrameDecisionInput& in,
                     const TrackingConfig& config) {
  const int min_observations = in.map_keyframes <= 2 ? 2 : 3;
  const int reference_matches = reference.trackedMapPoints(min_observations);
  // Close points (depth under 40 baselines) constrain translation; losing them calls for a
  // keyframe even while many far points are still tracked.
  const Features& f = frame.features;
  const double close_depth = f.camera->closeDepthThreshold();
  int tracked_close = 0, untracked_close = 0;
  for (int i = 0; i < frame.size(); ++i) {
    if (f.depth_m[i] <= 0.f || f.depth_m[i] >= close_depth || !f.usable[i]) continue;
    if (frame.map_points[i] && !frame.outlier[i])
      ++tracked_close;
    else
      ++untracked_close;
  }
  const bool need_close = tracked_close < config.keyframe_close_tracked_min &&
                          untracked_close > config.keyframe_close_untracked_max;
  const double ref_ratio = in.map_keyframes < 2 ? 0.4 : config.keyframe_ref_ratio;
  const bool c1a =
      in.frames_since_last_keyframe >= static_cast<uint64_t>(config.keyframe_max_frames);
  const bool c1b = in.mapper_idle;
  const bool c1c = in.matches_inliers < reference_matches * 0.25 || need_close;
  const bool c2 =
      (in.matches_inliers < reference_matches * ref_ratio || need_close) && in.matches_inliers > 15;
  if (!((c1a || c1b || c1c) && c2)) return false;
  // With mapping busy ORB-SLAM2 still queues RGB-D keyframes while the queue is short.
  return in.mapper_idle || in.mapper_accepts;
}

KeyFramePtr createKeyFrame(Frame& frame, Map& map, const TrackingConfig& config) {
  auto kf = std::make_shared<KeyFrame>(map.nextKeyFrameId(), frame.id, frame.stamp_s,
                                       frame.features, frame.T_camera_world, frame.map_points);
  kf->depth_samples_camera = surfaceSamples(frame.depth_surface, config.depth_alignment_step_px);
  map.addKeyFrame(kf);
  const Features& f = frame.features;
  std::vector<std::pair<float, int>> by_depth;
  for (int i = 0; i < frame.size(); ++i) {
    if (f.depth_m[i] > 0.f && f.usable[i]) by_depth.emplace_back(f.depth_m[i], i);
  }
  std::sort(by_depth.begin(), by_depth.end());
  const SE3 T_wc = kf->T_world_camera();
  const double close_depth = f.camera->closeDepthThreshold();
  int points = 0;
  for (const auto& [depth, i] : by_depth) {
    const MapPointPtr& existing = kf->map_points[i];
    if (!existing || existing->numObservations() < 1) {
      auto point = map.createPoint(T_wc * f.backproject(i), kf.get());
      point->addObservation(kf.get(), i);
      kf->map_points[i] = point;
      point->updateDescriptor();
      point->updateNormalAndDepth(*f.scales);
      frame.map_points[i] = point;
      frame.outlier[i] = 0;
    }
    ++points;
    if (depth > close_depth && points > config.new_points_min) break;
  }
  // Temporary visual-odometry points (no observations) must not enter the keyframe.
  for (auto& p : kf->map_points) {
    if (p && (p->bad || p->numObservations() == 0)) p.reset();
  }
  return kf;
}

}  // namespace dynanav
