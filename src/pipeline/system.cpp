#include "pipeline/system.hpp"

#include <algorithm>
#include <optional>

#include "assist/feedback_stage.hpp"
#include "dynamics/depth_tolerance.hpp"
#include "dynamics/keypoint_dynamics.hpp"
#include "dynamics/object_tracker.hpp"
#include "dynamics/prior_verifier.hpp"
#include "dynamics/residual_movers.hpp"
#include "perception/async_segmenter.hpp"
#include "slam/frame.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {

System::System(const Config& config, const PinholeCamera& camera,
               const std::filesystem::path& sequence_dir)
    : config_(config),
      camera_(camera),
      dynamic_(config.run.dynamic),
      prep_({.half = config.run.dynamic,
             .flow = config.run.dynamic && config.objects.enabled,
             .flow_finest_scale = config.objects.flow_finest_scale,
             .flow_refinement_iterations = config.objects.flow_refinement_iterations}) {
  if (dynamic_) {
    SegmenterRequest request;
    request.name = config.run.segmenter;
    request.segment_every = std::max(1, config.run.segment_every);
    request.sequence_dir = sequence_dir;
    PerceptionConfig perception = config.perception;
    if (config.run.realtime) {  // the real lag replaces a replayed one
      perception.emulated_lag_frames = 0;
      perception.replay_arrivals.clear();
    }
    segmenter_ = makeSegmenter(request, perception);
    // Real time: the segmenter runs in its own thread on the newest frame; its masks are
    // carried to the current frame by optical flow.
    if (config.run.realtime && request.name != "none")
      segmenter_ =
          std::make_unique<AsyncSegmenter>(std::move(segmenter_), config.perception, &timers_);
    segmenter_name_ = segmenter_->name();
    verifier_ = std::make_unique<PriorVerifier>(config.dynamics);
    if (config.objects.enabled)
      tracker_ = std::make_unique<ObjectTracker>(config.objects, config.dynamics.sample_step_px,
                                                 config.dynamics.prior_dynamic_classes);
    if (config.objects.enabled && config.assist.enabled)
      feedback_ = std::make_unique<FeedbackStage>(config.assist);
  }
  slam_ = std::make_unique<SlamSystem>(config, camera, &timers_);
}

System::~System() {
  finish();
}

void System::finish() {
  slam_->finish();
}

FrameResult System::process(const RgbdFrame& input) {
  ScopedTimer processing(timers_, "frame");
  FrameResult result;
  const PreparedFrame prep = prepare(input);              // 1. grey images (and flow), once
  result.instances = segment(input);                      // 2. segment (or propagate)
  const cv::Mat allowed = extractionMask(input, result);  // 3. ORB off prior and known movers
  Frame frame = extractFeatures(prep, input, allowed, result.instances);
  TrackOutcome outcome;
  {
    ScopedTimer timer(timers_, "tracking");
    InitialPose initial = slam_->initialPose(frame);  // 4. initial pose
    if (initial.ok)
      rejectMovers(input, initial, frame, result.instances, *result.dynamics);  // 5. movers out
    outcome = slam_->trackLocalMap(frame, std::move(initial));  // 6. local map, static points
  }
  verifyPriors(prep, input, frame, outcome, result);  // 7. scene flow: moving or not
  trackObjects(prep, input, frame, outcome, result);  // 8. object ids, motion, speed
  giveFeedback(input, frame, outcome, result);        // 9. hazards -> messages (issue 14)
  slam_->finishFrame(frame, outcome);                 // 10. local mapping, anchors
  fillResult(frame, outcome, result);
  result.index = input.index;
  result.stamp_s = input.stamp_s;
  result.latency_ms = processing.stop();
  return result;  // 11. sinks consume it
}

PreparedFrame System::prepare(const RgbdFrame& input) {
  ScopedTimer timer(timers_, "prep");
  return prep_.prepare(input);
}

Instances System::segment(const RgbdFrame& input) {
  if (!dynamic_) return Instances::none(input.bgr.size());
  ScopedTimer timer(timers_, "segmentation");
  Instances instances = segmenter_->segment(input);
  if (instances.segmented_index < 0) instances.segmented_index = input.index;  // in time
  for (const auto& [step, ms] : segmenter_->lastTiming()) timers_.add("segmentation." + step, ms);
  return instances;
}

cv::Mat System::extractionMask(const RgbdFrame& input, FrameResult& result) {
  if (!dynamic_) return {};
  FrameDynamics& record = result.dynamics.emplace();
  for (const Instance& instance : result.instances.items)
    record.prior_instances += isPriorDynamic(instance, config_.dynamics) ? 1 : 0;
  cv::Mat allowed = staticExtractionMask(result.instances, config_.dynamics, input.depth_m);
  // A non-prior object found moving in the last frame is still moving now: cut it out before
  // its keypoints reach the pose or the map.
  record.moving_ids =
      cutOutMovingObjects(allowed, result.instances, verifier_->movingMask(), config_.dynamics);
  record.moving_instances = static_cast<int>(record.moving_ids.size());
  if (!allowed.empty())
    record.masked_share = 1.0 - double(cv::countNonZero(allowed)) / double(allowed.total());
  return allowed;
}

Frame System::extractFeatures(const PreparedFrame& prep, const RgbdFrame& input,
                              const cv::Mat& allowed, const Instances& instances) {
  ScopedTimer timer(timers_, "extraction");
  Frame frame = slam_->extract(prep.grey, input.depth_m, input.stamp_s, allowed);
  if (dynamic_) labelKeypoints(frame.features, instances.labels);
  return frame;
}

void System::rejectMovers(const RgbdFrame& input, const InitialPose& initial, Frame& frame,
                          const Instances& instances, FrameDynamics& record) {
  depth_voted_.clear();
  if (!dynamic_) return;
  // The depth test looks as far as the camera's motion may have misregistered a keypoint.
  const double exposure_s =
      camera_.exposure_s > 0.0 ? camera_.exposure_s : config_.dynamics.assumed_exposure_ms * 1e-3;
  const DepthTestMotion motion{input.depth_m, initial.motion_since_last,
                               depthTestTimeSpread(exposure_s, input.stamp_s, input.depth_stamp_s),
                               initial.retime ? initial.readout_s : 0.0};
  const DynamicsConfig& dynamics = config_.dynamics;
  // Objects found by the segmenter but not (yet) found moving: judged against the background.
  const bool judge_instances =
      dynamics.residual_movers && dynamics.residual_instances &&
      std::any_of(instances.items.begin(), instances.items.end(),
                  [&](const Instance& instance) { return !isPriorDynamic(instance, dynamics); });
  const MapPointChecks checks = slam_->moverChecks(
      frame, dynamics.moving_evidence,
      dynamics.residual_movers ? dynamics.residual_min_established : 0, judge_instances);
  MoverVerdict verdict =
      findDepthMovers(frame, checks.predicted_depth_m, dynamics, motion, checks.moving_evidence);
  if (dynamics.residual_movers) {  // movers the segmenter missed, moving sideways
    const ResidualMovers residual = findResidualMovers(frame, checks.residuals, dynamics);
    addDrops(verdict.drop, residual.keypoints, false);
    record.residual_regions += residual.regions;
  }
  if (judge_instances) {  // objects pushed sideways
    const ResidualInstances moved =
        findResidualInstances(frame, checks.background_residuals, instances, dynamics);
    addDrops(verdict.drop, moved.keypoints, dynamics.cull_moving_object_points);
    auto& ids = verdict.moving_instances;
    ids.insert(ids.end(), moved.ids.begin(), moved.ids.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  record.culled_points += slam_->applyDrop(frame, verdict.drop);
  record.dynamic_keypoints += static_cast<int>(verdict.drop.drop.size());
  record.moving_instances += static_cast<int>(verdict.moving_instances.size());
  record.moving_ids.insert(record.moving_ids.end(), verdict.moving_instances.begin(),
                           verdict.moving_instances.end());
  depth_voted_ = verdict.moving_instances;
}

void System::verifyPriors(const PreparedFrame& prep, const RgbdFrame& input, const Frame& frame,
                          const TrackOutcome& outcome, FrameResult& result) {
  if (!dynamic_) return;
  FrameDynamics& record = *result.dynamics;
  record.keypoints = frame.size();
  for (int i = 0; i < frame.size(); ++i)
    record.static_keypoints += frame.features.usable[i] ? 1 : 0;
  ScopedTimer timer(timers_, "scene_flow");
  const bool tracked = outcome.state == TrackingState::kOk;
  const PriorVerdicts verdicts = verifier_->verify(
      {prep.grey_half, input.depth_m, result.instances, frame.T_camera_world, tracked, camera_},
      depth_voted_);
  depth_voted_.clear();
  record.prior_moving = verdicts.prior_moving;
  record.prior_static = verdicts.prior_static;
  record.static_ids = verdicts.static_ids;
  auto& ids = record.moving_ids;
  ids.insert(ids.end(), verdicts.moving_ids.begin(), verdicts.moving_ids.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (const Instance& instance : result.instances.items) {
    InstanceVerdict& v = result.verdicts.emplace_back();
    v.id = instance.id;
    v.prior_dynamic = isPriorDynamic(instance, config_.dynamics);
    v.moving = std::binary_search(ids.begin(), ids.end(), instance.id);
    v.verified_static =
        std::binary_search(record.static_ids.begin(), record.static_ids.end(), instance.id);
  }
}

void System::trackObjects(const PreparedFrame& prep, const RgbdFrame& input, const Frame& frame,
                          const TrackOutcome& outcome, FrameResult& result) {
  if (!tracker_) return;
  ScopedTimer timer(timers_, "objects");
  const SE3 T_world_camera = frame.T_camera_world.inverse();
  result.objects = tracker_->track({input.index, input.stamp_s, result.instances, *result.dynamics,
                                    prep.flow_half, input.depth_m, T_world_camera,
                                    outcome.state == TrackingState::kOk, camera_, prep.grey_half});
}

void System::giveFeedback(const RgbdFrame& input, const Frame& frame, const TrackOutcome& outcome,
                          FrameResult& result) {
  if (!feedback_) return;
  ScopedTimer timer(timers_, "feedback");
  result.events = feedback_->process({input.stamp_s, frame.T_camera_world.inverse(),
                                      outcome.state == TrackingState::kOk, result.objects});
}

void System::fillResult(const Frame& frame, const TrackOutcome& outcome,
                        FrameResult& result) const {
  result.state = outcome.state;
  result.tracked = outcome.state == TrackingState::kOk;
  result.T_world_camera = frame.T_camera_world.inverse();
  result.keyframe = outcome.new_keyframe != nullptr;
  result.recovered = outcome.recovered;
  result.keypoints = frame.size();
  result.inliers = outcome.inliers;
  result.map_points = slam_->numMapPoints();
  result.map_keyframes = slam_->numKeyFrames();
}

}  // namespace dynanav
