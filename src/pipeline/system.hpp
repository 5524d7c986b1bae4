#pragma once
// The whole per-frame pipeline (DESIGN.md §1, "the per-frame story"), as far as it exists:
// extract ORB -> track (motion model / reference keyframe, then local map) -> keyframe decision
// and local mapping -> result. Deterministic mode runs local mapping inline after tracking;
// threaded mode runs it in its own thread beside tracking.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/frame.hpp"
#include "core/timer.hpp"
#include "io/trajectory.hpp"
#include "pipeline/frame_result.hpp"
#include "slam/local_mapper.hpp"

namespace dynanav {

class OrbExtractor;
class Map;
class MappingStage;
class Tracker;
class KeyFrame;
class DynamicFilter;
class Vocabulary;
class PlaceIndex;
class Relocaliser;
class LoopCloser;
struct LoopEvent;
struct Frame;
struct PyramidScales;

class System {
 public:
  /// `sequence_dir` serves the `masks` segmenter (SEQ_DIR/masks); empty for the others.
  System(const Config& config, const PinholeCamera& camera, const std::filesystem::path& sequence_dir = {});
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  FrameResult process(const RgbdFrame& input);
  /// Lets local mapping finish its queue (threaded mode) so the map is final.
  void finish();

  /// Keyframe poses (T_world_camera) ordered by time, as optimised so far.
  [[nodiscard]] std::vector<StampedPose> keyframePoses() const;
  /// Every tracked frame's pose re-anchored on its reference keyframe as that is now (after
  /// later bundle adjustments), as ORB-SLAM2 saves its trajectory.
  [[nodiscard]] std::vector<StampedPose> refinedTrajectory() const;
  [[nodiscard]] const StageTimers& timers() const { return timers_; }
  [[nodiscard]] LocalMapperStats mappingStats() const;
  [[nodiscard]] size_t numMapPoints() const;
  [[nodiscard]] size_t numKeyFrames() const;
  /// Issue 7: dynamic keypoints and instances, means and per-frame series (stats.json "dynamics").
  [[nodiscard]] nlohmann::json dynamicsSummary() const;
  /// Loops closed so far (issue 4); empty when loop closing is off or has no vocabulary.
  [[nodiscard]] std::vector<LoopEvent> loops() const;

 private:
  /// `allowed` (CV_8U, empty = everywhere): where ORB may look (issue 7 cuts out people).
  Frame extractFeatures(const RgbdFrame& input, const cv::Mat& allowed);
  /// Issue 4: vocabulary, keyframe database, relocaliser and loop closer, if the vocabulary loads.
  void setUpPlaceRecognition();
  FrameResult makeResult(const RgbdFrame& input, const Frame& frame, const TrackOutcome& outcome) const;

  Config config_;
  std::shared_ptr<const PinholeCamera> camera_;
  std::shared_ptr<const PyramidScales> scales_;
  StageTimers timers_;
  std::unique_ptr<OrbExtractor> extractor_;
  std::unique_ptr<Map> map_;
  std::unique_ptr<MappingStage> mapping_;
  std::unique_ptr<Tracker> tracker_;
  std::unique_ptr<DynamicFilter> dynamics_;  // issue 7
  // Place recognition (issue 4); declared after the map and stages so they go first.
  std::shared_ptr<const Vocabulary> vocabulary_;
  std::unique_ptr<PlaceIndex> places_;
  std::unique_ptr<Relocaliser> relocaliser_;
  std::unique_ptr<LoopCloser> loop_closer_;
  uint64_t next_frame_id_ = 0;
  struct FrameAnchor {
    double stamp_s;
    std::shared_ptr<KeyFrame> reference;
    SE3 T_frame_reference;
  };
  std::vector<FrameAnchor> anchors_;  ///< one per tracked frame
};

}  // namespace dynanav
