#pragma once
// The whole per-frame pipeline (DESIGN.md §1, "the per-frame story"), as far as it exists:
// extract ORB -> track (motion model / reference keyframe, then local map) -> keyframe decision
// and local mapping -> result. Deterministic mode runs local mapping inline after tracking;
// threaded mode runs it in its own thread beside tracking.
#include <memory>
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
struct Frame;
struct PyramidScales;

class System {
 public:
  System(const Config& config, const PinholeCamera& camera);
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  FrameResult process(const RgbdFrame& input);
  /// Lets local mapping finish its queue (threaded mode) so the map is final.
  void finish();

  /// Keyframe poses (T_world_camera) ordered by time, as optimised so far.
  [[nodiscard]] std::vector<StampedPose> keyframePoses() const;
  [[nodiscard]] const StageTimers& timers() const { return timers_; }
  [[nodiscard]] LocalMapperStats mappingStats() const;
  [[nodiscard]] size_t numMapPoints() const;
  [[nodiscard]] size_t numKeyFrames() const;

 private:
  Frame extractFeatures(const RgbdFrame& input);
  FrameResult makeResult(const RgbdFrame& input, const Frame& frame, const TrackOutcome& outcome) const;

  Config config_;
  std::shared_ptr<const PinholeCamera> camera_;
  std::shared_ptr<const PyramidScales> scales_;
  StageTimers timers_;
  std::unique_ptr<OrbExtractor> extractor_;
  std::unique_ptr<Map> map_;
  std::unique_ptr<MappingStage> mapping_;
  std::unique_ptr<Tracker> tracker_;
  uint64_t next_frame_id_ = 0;
};

}  // namespace dynanav
