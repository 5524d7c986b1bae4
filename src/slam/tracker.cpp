#include "slam/tracker.hpp"

#include <algorithm>
#include <mutex>

#include <spdlog/spdlog.h>

#include "slam/frame_tracker.hpp"
#include "slam/keyframe_inserter.hpp"
#include "slam/pose_optimizer.hpp"
#include "slam/rolling_shutter.hpp"

namespace dynanav {

bool Tracker::initialise(Frame& frame, TrackOutcome& outcome) {
  const Features& f = frame.features;
  int with_depth = 0;
  for (int i = 0; i < frame.size(); ++i) with_depth += f.hasDepth(i) && f.usable[i];
  if (with_depth < config_.init_min_depth_features) return false;
  // The first frame defines the world frame (DESIGN.md §2); every keypoint with depth seeds a
  // point.
  frame.T_camera_world = SE3::Identity();
  frame.clearMatches();
  auto kf = std::make_shared<KeyFrame>(map_.nextKeyFrameId(), frame.id, frame.stamp_s, f,
                                       frame.T_camera_world, frame.map_points);
  kf->depth_samples_camera = surfaceSamples(frame.depth_surface, config_.depth_alignment_step_px);
  map_.addKeyFrame(kf);
  for (int i = 0; i < frame.size(); ++i) {
    if (!f.hasDepth(i) || !f.usable[i]) continue;
    auto point = map_.createPoint(f.backproject(i), kf.get());
    point->addObservation(kf.get(), i);
    kf->map_points[i] = point;
    frame.map_points[i] = point;
    point->updateDescriptor();
    point->updateNormalAndDepth(*f.scales);
  }
  reference_ = kf;
  local_.keyframes = {kf};
  local_.points.clear();
  for (const auto& p : kf->map_points)
    if (p) local_.points.push_back(p);
  local_.reference = kf;
  last_keyframe_frame_id_ = frame.id;
  outcome.new_keyframe = kf;
  awaiting_motion_ = kf;
  outcome.reference = kf;
  outcome.T_frame_reference = frame.T_camera_world * kf->T_world_camera();
  outcome.inliers = with_depth;
  return true;
}

void Tracker::updateLastFrame() {
  if (!last_reference_) return;
  last_.T_camera_world = orthonormalized(T_last_reference_ * last_reference_->T_camera_world());
  if (last_is_keyframe_) return;
  const Features& f = last_.features;
  std::vector<std::pair<float, int>> by_depth;
  for (int i = 0; i < last_.size(); ++i)
    if (f.hasDepth(i) && f.usable[i]) by_depth.emplace_back(f.depth_m[i], i);
  std::sort(by_depth.begin(), by_depth.end());
  const SE3 T_wc = last_.T_camera_world.inverse();
  const double close_depth = f.camera->closeDepthThreshold();
  int points = 0;
  for (const auto& [depth, i] : by_depth) {
    const MapPointPtr& p = last_.map_points[i];
    if (!p || p->numObservations() < 1) {
      auto temporary = map_.createTemporaryPoint(T_wc * f.backproject(i));
      temporary->descriptor = f.descriptors.row(i);
      last_.map_points[i] = temporary;
      last_.outlier[i] = 0;
    }
    ++points;
    if (depth > close_depth && points > config_.new_points_min) break;
  }
}

void Tracker::placeReferenceDepth(Frame& frame) const {
  frame.depth_reference_world.clear();
  if (!(config_.depth_alignment_samples > 0.0)) return;
  // The reference keyframe's depth, not the last frame's: its pose is held by the map (local
  // bundle adjustment), so no frame-to-frame drift builds up along what the depth fixes, and in
  // the frames since it was taken a walker has moved far enough that its depth no longer lies on
  // the surface where it stood (Bonn crowd without masks, the last frame's depth: the pose
  // followed the walkers, ATE 0.030 -> 0.276 m; docs/slam.md).
  const SE3& T_world_reference = reference_->T_world_camera();
  frame.depth_reference_world.reserve(reference_->depth_samples_camera.size());
  for (const Vec3& p : reference_->depth_samples_camera)
    frame.depth_reference_world.push_back(T_world_reference * p);
}

int Tracker::refineWithOwnMotion(Frame& frame, const InitialPose& initial) const {
  // The first re-timing used the last pair's motion, a prediction; the pose now gives this
  // frame's own motion since the last one (fr1_xyz at 20 ms: ATE 0.0068 -> 0.0053 m, RPE
  // 0.0066 -> 0.0045 m/frame against the prediction alone; docs/slam.md).
  const CameraVelocity own =
      CameraVelocity::of(orthonormalized(frame.T_camera_world * last_.T_camera_world.inverse()),
                         frame.stamp_s - last_.stamp_s);
  if (initial.retime) {
    initial.as_read.restoreInto(frame.features);
    compensateRollingShutter(frame.features, own, initial.readout_s);
  }
  if (initial.blur)
    measureMotionBlur(frame.features, own, initial.exposure_s, config_.motion_blur_share);
  optimizeFramePose(frame, config_);
  // Local-map tracking counted every match it kept as found; new outliers take that back.
  for (int i = 0; i < frame.size(); ++i)
    if (frame.map_points[i] && frame.outlier[i]) --frame.map_points[i]->found;
  return discardOutliers(frame);
}

void Tracker::rememberAsLast(const Frame& frame) {
  last_ = frame;
  last_reference_ = reference_;
  T_last_reference_ = frame.T_camera_world * reference_->T_world_camera();
}

double Tracker::readoutFor(const Frame& frame) {
  const double configured_s = config_.rolling_shutter_readout_ms >= 0.0
                                  ? config_.rolling_shutter_readout_ms * 1e-3
                                  : frame.features.camera->readout_s;
  if (!config_.rolling_shutter_online) return configured_s;
  // Online: bundle adjustment estimates the readout with the map (slam/readout_shear.hpp) and
  // local mapping adopts each well-determined estimate; tracking re-times with the latest.
  const MapReadout& readout = map_.readout;
  if (readout.adopted > adopted_seen_) {
    adopted_seen_ = readout.adopted;
    online_stages_.push_back(
        {int64_t(frame.id), readout.readout_s, readout.sigma_s, readout.window_keyframes});
    readout_estimator_.restart();  // the tracking residuals' own estimate, at the new readout
  }
  // A readout longer than the frame interval would overlap the next frame's.
  online_readout_s_ = std::clamp(readout.readout_s, 0.0, velocity_interval_s_);
  return online_stages_.empty() ? configured_s : online_readout_s_;
}

TrackOutcome Tracker::track(Frame& frame) {
  InitialPose initial = initialPose(frame);
  if (initial.finished) return initial.outcome;
  return trackLocalMap(frame, std::move(initial));
}

InitialPose Tracker::initialPose(Frame& frame) {
  std::unique_lock lock(map_.mutex());
  InitialPose initial;
  if (state_ == TrackingState::kNotInitialised) {
    initial.finished = true;
    TrackOutcome& outcome = initial.outcome;
    if (initialise(frame, outcome)) {
      state_ = TrackingState::kOk;
      last_is_keyframe_ = true;
      rememberAsLast(frame);
      lock.unlock();  // never wait for queue room while holding the map
      mapping_.insert(outcome.new_keyframe);
    }
    outcome.state = state_;
    return initial;
  }
  if (reference_->bad) {  // culled by local mapping: fall back to the newest keyframe
    reference_ = map_.keyframes().rbegin()->second;
  }
  initial.was_lost = state_ == TrackingState::kLost;
  bool ok = false;
  initial.readout_s = readoutFor(frame);
  initial.retime = !initial.was_lost && has_velocity_ && initial.readout_s > 0.0;
  initial.as_read = KeypointMeasurements::of(frame.features);
  if (initial.retime) {
    compensateRollingShutter(frame.features, CameraVelocity::of(velocity_, velocity_interval_s_),
                             initial.readout_s);
  }
  initial.exposure_s =
      config_.exposure_ms >= 0.0 ? config_.exposure_ms * 1e-3 : frame.features.camera->exposure_s;
  initial.blur = !initial.was_lost && has_velocity_ && initial.exposure_s > 0.0 &&
                 config_.motion_blur_share > 0.0;
  if (initial.blur) {
    measureMotionBlur(frame.features, CameraVelocity::of(velocity_, velocity_interval_s_),
                      initial.exposure_s, config_.motion_blur_share);
  }
  if (!initial.was_lost) {
    updateLastFrame();
    placeReferenceDepth(frame);
    if (has_velocity_) ok = trackWithMotionModel(frame, last_, velocity_, config_);
    if (!ok) ok = trackReferenceKeyFrame(frame, *reference_, last_.T_camera_world, config_);
  } else {
    if (relocaliser_) ok = relocaliser_->relocalise(frame, map_).ok;  // issue 4
    if (!ok) ok = trackReferenceKeyFrame(frame, *reference_, last_.T_camera_world, config_);
  }
  spdlog::debug("frame {}: initial pose {} ({} matches)", frame.id, ok ? "ok" : "failed",
                std::count_if(frame.map_points.begin(), frame.map_points.end(),
                              [](const auto& p) { return p != nullptr; }));
  initial.ok = ok;
  if (ok && !initial.was_lost && frame.stamp_s > last_.stamp_s)
    initial.motion_since_last = CameraVelocity::of(
        frame.T_camera_world * last_.T_camera_world.inverse(), frame.stamp_s - last_.stamp_s);
  return initial;
}

TrackOutcome Tracker::trackLocalMap(Frame& frame, InitialPose initial) {
  if (initial.finished) return initial.outcome;
  std::unique_lock lock(map_.mutex());
  TrackOutcome outcome;
  const bool was_lost = initial.was_lost;
  bool ok = initial.ok;
  if (ok) {
    outcome.inliers = dynanav::trackLocalMap(frame, map_.keyframes(), config_, local_);
    spdlog::debug("frame {}: local map {} kfs {} points -> {} inliers", frame.id,
                  local_.keyframes.size(), local_.points.size(), outcome.inliers);
    // After a loss ORB-SLAM2 asks for more support before trusting the pose again.
    const int needed = was_lost ? 50 : config_.local_map_min_inliers;
    ok = outcome.inliers >= needed;
  }
  if (!ok) {
    state_ = TrackingState::kLost;
    has_velocity_ = false;
    frame.clearMatches();
    outcome.state = state_;
    return outcome;
  }
  if (initial.retime || initial.blur) outcome.inliers = refineWithOwnMotion(frame, initial);
  const double readout_used_s = initial.retime ? initial.readout_s : 0.0;
  CameraVelocity own_motion;  // interval 0: not known
  ReadoutEvidence evidence;
  if (!was_lost && frame.stamp_s > last_.stamp_s) {
    own_motion =
        CameraVelocity::of(orthonormalized(frame.T_camera_world * last_.T_camera_world.inverse()),
                           frame.stamp_s - last_.stamp_s);
    // The map's first keyframe had no motion yet: the next interval's stands in for it.
    if (awaiting_motion_) awaiting_motion_->motion = own_motion;
    awaiting_motion_.reset();
    evidence = readoutEvidence(frame, initial.as_read, own_motion, readout_used_s);
    readout_estimator_.add(evidence);
  }
  state_ = TrackingState::kOk;
  outcome.recovered = was_lost;
  if (!was_lost) {
    velocity_ = orthonormalized(frame.T_camera_world * last_.T_camera_world.inverse());
    velocity_interval_s_ = frame.stamp_s - last_.stamp_s;
    has_velocity_ = true;
  }
  if (local_.reference) reference_ = local_.reference;
  // Temporary visual-odometry points served the motion model only.
  for (int i = 0; i < frame.size(); ++i) {
    if (frame.map_points[i] && frame.map_points[i]->numObservations() < 1) {
      frame.map_points[i].reset();
      frame.outlier[i] = 0;
    }
  }
  KeyFrameDecisionInput decision;
  decision.frames_since_last_keyframe = frame.id - last_keyframe_frame_id_;
  decision.matches_inliers = outcome.inliers;
  decision.mapper_idle = mapping_.idle();
  decision.mapper_accepts = mapping_.accepts();
  decision.map_keyframes = map_.numKeyFrames();
  last_is_keyframe_ = false;
  if (!was_lost && needNewKeyFrame(frame, *reference_, decision, config_)) {
    outcome.new_keyframe = createKeyFrame(frame, map_, config_);
    outcome.new_keyframe->motion = own_motion;
    outcome.new_keyframe->readout_used_s = readout_used_s;
    if (evidence.valid) outcome.new_keyframe->pose_shift_per_readout = evidence.pose_shift_per_s;
    reference_ = outcome.new_keyframe;
    last_keyframe_frame_id_ = frame.id;
    last_is_keyframe_ = true;
  }
  rememberAsLast(frame);
  outcome.reference = reference_;
  outcome.T_frame_reference = T_last_reference_;
  lock.unlock();
  if (outcome.new_keyframe) mapping_.insert(outcome.new_keyframe);
  outcome.state = state_;
  return outcome;
}

}  // namespace dynanav
