#include "slam/slam_system.hpp"

#include <spdlog/spdlog.h>

#include <mutex>

#include "core/error.hpp"
#include "slam/loop_closer.hpp"
#include "slam/loop_places.hpp"
#include "slam/map.hpp"
#include "slam/mapping_stage.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/relocaliser.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"

namespace dynanav {

namespace {
/// Posing frames on the persistent map and on the static depth outside the masks are part of
/// the dynamic-scene handling: `--dynamic off` is the plain ORB-SLAM2 baseline the dynamic modes
/// are compared with. The depth needs a segmenter: without masks a crowd's depth is most of the
/// view and the alignment follows it (Bonn crowd `--segmenter none`: ATE 0.030 -> 0.20 m,
/// docs/slam.md "Static depth where the keypoints are loose"), where keypoints have their age to
/// tell the static structure by.
TrackingConfig trackingFor(const Config& config) {
  TrackingConfig tracking = config.tracking;
  if (!config.run.dynamic) tracking.persistent_point_age_s = 0.0;
  if (!config.run.dynamic || config.run.segmenter == "none") tracking.depth_alignment_samples = 0.0;
  return tracking;
}
}  // namespace

SlamSystem::SlamSystem(const Config& config, const PinholeCamera& camera, StageTimers* timers)
    : config_(config),
      camera_(std::make_shared<const PinholeCamera>(camera)),
      scales_(std::make_shared<const PyramidScales>(PyramidScales::fromConfig(config.orb))),
      extractor_(std::make_unique<OrbExtractor>(config.orb)),
      map_(std::make_unique<Map>()),
      mapping_(
          std::make_unique<MappingStage>(*map_, config.mapping, !config.run.deterministic, timers)),
      tracker_(std::make_unique<Tracker>(*map_, *mapping_, trackingFor(config))) {
  if (config.tracking.rolling_shutter_online) {
    // Issue 18: bundle adjustment estimates the readout with the map from the configured one on.
    map_->readout.estimate = true;
    map_->readout.readout_s = configuredReadoutS();
    map_->readout.adopt_sigma_s = config.tracking.rolling_shutter_online_max_sigma_ms * 1e-3;
  }
  if (trackingFor(config).depth_alignment_samples > 0.0)
    surfaces_ = std::make_unique<DepthSurfaceMaker>(camera, config.tracking.depth_max_m);
  setUpPlaceRecognition();
}

void SlamSystem::setUpPlaceRecognition() {
  const LoopConfig& loop = config_.loop;
  if (!loop.relocalisation && !loop.loop_closing) {
    place_recognition_off_ = "loop.relocalisation and loop.loop_closing are false";
    return;
  }
  try {
    vocabulary_ = std::make_shared<const Vocabulary>(
        Vocabulary::load(findVocabulary(loop.vocabulary).string()));
  } catch (const InputError& e) {
    spdlog::warn("relocalisation and loop closing disabled: {}", e.what());
    place_recognition_off_ = e.what();
    return;
  }
  places_ = std::make_unique<PlaceIndex>(vocabulary_, loop);
  // The loop closer also feeds the keyframe database, which relocalisation needs on its own.
  loop_closer_ = std::make_unique<LoopCloser>(
      *map_, *places_, loop, config_.mapping.covisibility_min_weight, !config_.run.deterministic);
  mapping_->setKeyFrameSink([this](const KeyFramePtr& kf) { loop_closer_->process(kf); });
  if (loop.relocalisation) {
    relocaliser_ = std::make_unique<Relocaliser>(*places_, loop, config_.tracking);
    tracker_->setRelocaliser(relocaliser_.get());
  }
}

SlamSystem::~SlamSystem() {
  finish();
}

Frame SlamSystem::extract(const cv::Mat& grey, const cv::Mat& depth_m, double stamp_s,
                          const cv::Mat& allowed) {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor_->extract(grey, allowed, keypoints, descriptors);
  Frame frame(next_frame_id_++, stamp_s,
              makeFeatures(std::move(keypoints), descriptors, depth_m, config_.tracking.depth_max_m,
                           camera_, scales_));
  if (surfaces_) frame.depth_surface = surfaces_->make(depth_m, allowed);
  return frame;
}

InitialPose SlamSystem::initialPose(Frame& frame) {
  return tracker_->initialPose(frame);
}

MapPointChecks SlamSystem::moverChecks(const Frame& frame, bool evidence,
                                       int residual_min_established, bool background) const {
  std::unique_lock lock(map_->mutex());  // local BA moves points in real-time mode
  MapPointChecks checks;
  checks.predicted_depth_m = predictedMapPointDepths(frame);
  if (evidence) checks.moving_evidence = mapPointMovingEvidence(frame);
  if (residual_min_established > 0)
    checks.residuals =
        residualsToEstablishedPoints(frame, config_.tracking, residual_min_established);
  if (residual_min_established > 0 && background)
    checks.background_residuals =
        residualsToBackground(frame, config_.tracking, residual_min_established);
  return checks;
}

int SlamSystem::applyDrop(Frame& frame, const KeypointDrop& drop) {
  if (drop.empty()) return 0;
  std::unique_lock lock(map_->mutex());
  return applyKeypointDrop(frame, drop);
}

TrackOutcome SlamSystem::trackLocalMap(Frame& frame, InitialPose initial) {
  return tracker_->trackLocalMap(frame, std::move(initial));
}

void SlamSystem::finishFrame(const Frame& frame, const TrackOutcome& outcome) {
  mapping_->runPending();
  std::unique_lock lock(map_->mutex());  // local BA or a loop correction may be moving keyframes
  // The relative pose as tracked, not recomputed here: local mapping (and in deterministic runs a
  // loop correction) has just moved the reference, and the frame's own pose did not follow.
  if (outcome.state == TrackingState::kOk && outcome.reference)
    anchors_.add(frame.stamp_s, outcome.reference, outcome.T_frame_reference);
  anchors_.reanchorCulled();
}

void SlamSystem::finish() {
  if (finished_) return;
  finished_ = true;
  // Order matters: local mapping hands its last keyframes to the loop closer, a global BA the
  // loop closer started must end before the final whole-map BA touches the same keyframes.
  mapping_->stop();
  if (loop_closer_) loop_closer_->finish();
  mapping_->finalBundleAdjustment();
}

std::vector<StampedPose> SlamSystem::keyframePoses() const {
  std::unique_lock lock(map_->mutex());
  std::vector<StampedPose> poses;
  for (const auto& [id, kf] : map_->keyframes())
    if (!kf->bad) poses.push_back({kf->stamp_s, kf->T_world_camera()});
  return poses;
}

std::vector<StampedPose> SlamSystem::refinedTrajectory() const {
  std::unique_lock lock(map_->mutex());
  return anchors_.poses();
}

std::vector<LoopEvent> SlamSystem::loops() const {
  return loop_closer_ ? loop_closer_->loops() : std::vector<LoopEvent>{};
}

LocalMapperStats SlamSystem::mappingStats() const {
  return mapping_->stats();
}

size_t SlamSystem::numMapPoints() const {
  std::unique_lock lock(map_->mutex());
  return map_->numPoints();
}

size_t SlamSystem::numKeyFrames() const {
  std::unique_lock lock(map_->mutex());
  return map_->numKeyFrames();
}

}  // namespace dynanav
