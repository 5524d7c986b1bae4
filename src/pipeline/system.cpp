#include "pipeline/system.hpp"

#include <opencv2/imgproc.hpp>
#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "dynamics/dynamic_filter.hpp"

#include "slam/frame.hpp"
#include "slam/loop_closer.hpp"
#include "slam/loop_places.hpp"
#include "slam/relocaliser.hpp"
#include "slam/map.hpp"
#include "slam/mapping_stage.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/tracker.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"

namespace dynanav {

System::System(const Config& config, const PinholeCamera& camera, const std::filesystem::path& sequence_dir)
    : config_(config),
      camera_(std::make_shared<const PinholeCamera>(camera)),
      scales_(std::make_shared<const PyramidScales>(PyramidScales::fromConfig(config.orb))),
      extractor_(std::make_unique<OrbExtractor>(config.orb)),
      map_(std::make_unique<Map>()),
      mapping_(std::make_unique<MappingStage>(*map_, config.mapping, !config.run.deterministic, &timers_)),
      tracker_(std::make_unique<Tracker>(*map_, *mapping_, config.tracking)) {
  dynamics_ = std::make_unique<DynamicFilter>(config_, sequence_dir, &timers_);
  tracker_->setMoverFilter([this](Frame& frame) { dynamics_->rejectMovers(frame); });  // step 5
  setUpPlaceRecognition();
}

void System::setUpPlaceRecognition() {
  const LoopConfig& loop = config_.loop;
  if (!loop.relocalisation && !loop.loop_closing) return;
  try {
    vocabulary_ = std::make_shared<const Vocabulary>(Vocabulary::load(findVocabulary(loop.vocabulary).string()));
  } catch (const InputError& e) {
    spdlog::warn("relocalisation and loop closing disabled: {}", e.what());
    return;
  }
  places_ = std::make_unique<PlaceIndex>(vocabulary_, loop);
  // The loop closer also feeds the keyframe database, which relocalisation needs on its own.
  loop_closer_ = std::make_unique<LoopCloser>(*map_, *places_, loop, config_.mapping.covisibility_min_weight,
                                              !config_.run.deterministic);
  mapping_->setKeyFrameSink([this](const KeyFramePtr& kf) { loop_closer_->process(kf); });
  if (loop.relocalisation) {
    relocaliser_ = std::make_unique<Relocaliser>(*places_, loop, config_.tracking);
    tracker_->setRelocaliser(relocaliser_.get());
  }
}

System::~System() { finish(); }

FrameResult System::process(const RgbdFrame& input) {
  ScopedTimer latency(timers_, "frame");
  const Instances instances = dynamics_->segment(input);  // 2. segment (or propagate masks)
  Frame frame = extractFeatures(input, dynamics_->extractionMask(instances));  // 3. ORB off prior movers
  dynamics_->labelKeypoints(frame, instances);
  TrackOutcome outcome;
  {
    ScopedTimer timer(timers_, "tracking");
    outcome = tracker_->track(frame);  // 4-6. initial pose, depth test (mover filter), local map
  }
  dynamics_->verifyPriors(input, instances, frame, outcome.state == TrackingState::kOk);  // 7. scene flow
  mapping_->runPending();                             // 10. local mapping (inline when deterministic)
  if (outcome.state == TrackingState::kOk && outcome.reference)
    anchors_.push_back({input.stamp_s, outcome.reference, frame.T_camera_world * outcome.reference->T_world_camera()});
  FrameResult result = makeResult(input, frame, outcome);
  result.latency_ms = latency.stop();
  return result;                                      // 11. writers consume the result
}

void System::finish() {
  if (mapping_) mapping_->finish();
  if (loop_closer_) loop_closer_->finish();  // joins a running global BA
}

Frame System::extractFeatures(const RgbdFrame& input, const cv::Mat& allowed) {
  ScopedTimer timer(timers_, "extraction");
  cv::Mat gray;
  if (input.bgr.channels() == 3) cv::cvtColor(input.bgr, gray, cv::COLOR_BGR2GRAY);
  else gray = input.bgr;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor_->extract(gray, allowed, keypoints, descriptors);
  return Frame(next_frame_id_++, input.stamp_s,
               makeFeatures(std::move(keypoints), descriptors, input.depth_m,
                            config_.tracking.depth_max_m, camera_, scales_));
}

FrameResult System::makeResult(const RgbdFrame& input, const Frame& frame, const TrackOutcome& outcome) const {
  FrameResult r;
  r.index = input.index;
  r.stamp_s = input.stamp_s;
  r.state = outcome.state;
  r.tracked = outcome.state == TrackingState::kOk;
  r.T_world_camera = frame.T_camera_world.inverse();
  r.keyframe = outcome.new_keyframe != nullptr;
  r.recovered = outcome.recovered;
  r.keypoints = frame.size();
  r.inliers = outcome.inliers;
  r.map_points = numMapPoints();
  r.map_keyframes = numKeyFrames();
  return r;
}

std::vector<StampedPose> System::keyframePoses() const {
  std::unique_lock lock(map_->mutex());
  std::vector<StampedPose> poses;
  for (const auto& [id, kf] : map_->keyframes()) {
    if (!kf->bad) poses.push_back({kf->stamp_s, kf->T_world_camera()});
  }
  return poses;
}

std::vector<LoopEvent> System::loops() const {
  return loop_closer_ ? loop_closer_->loops() : std::vector<LoopEvent>{};
}

nlohmann::json System::dynamicsSummary() const { return dynamics_->summary(); }

std::vector<StampedPose> System::refinedTrajectory() const {
  std::unique_lock lock(map_->mutex());
  std::vector<StampedPose> poses;
  poses.reserve(anchors_.size());
  for (const auto& a : anchors_)
    poses.push_back({a.stamp_s, anchoredPose(*a.reference, a.T_frame_reference).inverse()});
  return poses;
}

LocalMapperStats System::mappingStats() const { return mapping_->stats(); }

size_t System::numMapPoints() const {
  std::unique_lock lock(map_->mutex());
  return map_->numPoints();
}

size_t System::numKeyFrames() const {
  std::unique_lock lock(map_->mutex());
  return map_->numKeyFrames();
}

}  // namespace dynanav
