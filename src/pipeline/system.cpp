#include "pipeline/system.hpp"

#include <opencv2/imgproc.hpp>

#include "slam/frame.hpp"
#include "slam/map.hpp"
#include "slam/mapping_stage.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/tracker.hpp"

namespace dynanav {

System::System(const Config& config, const PinholeCamera& camera)
    : config_(config),
      camera_(std::make_shared<const PinholeCamera>(camera)),
      scales_(std::make_shared<const PyramidScales>(PyramidScales::fromConfig(config.orb))),
      extractor_(std::make_unique<OrbExtractor>(config.orb)),
      map_(std::make_unique<Map>()),
      mapping_(std::make_unique<MappingStage>(*map_, config.mapping, !config.run.deterministic, &timers_)),
      tracker_(std::make_unique<Tracker>(*map_, *mapping_, config.tracking)) {}

System::~System() { finish(); }

FrameResult System::process(const RgbdFrame& input) {
  ScopedTimer latency(timers_, "frame");
  Frame frame = extractFeatures(input);               // 3. extract ORB
  TrackOutcome outcome;
  {
    ScopedTimer timer(timers_, "tracking");
    outcome = tracker_->track(frame);                 // 4 + 6. motion model / reference, local map
  }
  mapping_->runPending();                             // 10. local mapping (inline when deterministic)
  FrameResult result = makeResult(input, frame, outcome);
  result.latency_ms = latency.stop();
  return result;                                      // 11. writers consume the result
}

void System::finish() {
  if (mapping_) mapping_->finish();
}

Frame System::extractFeatures(const RgbdFrame& input) {
  ScopedTimer timer(timers_, "extraction");
  cv::Mat gray;
  if (input.bgr.channels() == 3) cv::cvtColor(input.bgr, gray, cv::COLOR_BGR2GRAY);
  else gray = input.bgr;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor_->extract(gray, keypoints, descriptors);
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
