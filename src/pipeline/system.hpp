#pragma once
// The per-frame pipeline (DESIGN.md §1, "the per-frame story"): System::process() in system.cpp
// reads as the algorithm, one named call per step. The same calls run in deterministic mode (one
// thread, local mapping inline) and in real-time mode (segmentation, local mapping and loop
// closing in their own threads; see realtime_runner.hpp).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/frame.hpp"
#include "core/timer.hpp"
#include "io/trajectory.hpp"
#include "perception/frame_prep.hpp"
#include "perception/segmenter.hpp"
#include "pipeline/frame_result.hpp"
#include "slam/local_mapper.hpp"

namespace dynanav {

class SlamSystem;
class PriorVerifier;
class ObjectTracker;
class FeedbackStage;
struct Frame;
struct LoopEvent;
struct TrackOutcome;
struct InitialPose;

class System {
 public:
  /// `sequence_dir` serves the `masks` segmenter (SEQ_DIR/masks); empty for the others. Throws
  /// InputError for a missing model file or masks folder.
  System(const Config& config, const PinholeCamera& camera,
         const std::filesystem::path& sequence_dir = {});
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  FrameResult process(const RgbdFrame& input);
  /// Lets local mapping and loop closing finish so the map is final (idempotent).
  void finish();

  [[nodiscard]] const SlamSystem& slam() const { return *slam_; }
  [[nodiscard]] const StageTimers& timers() const { return timers_; }
  /// "off" with dynamics off, else the segmenter's name ("dnn", "dnn/async", ...).
  [[nodiscard]] const std::string& segmenterName() const { return segmenter_name_; }

 private:
  PreparedFrame prepare(const RgbdFrame& input);
  Instances segment(const RgbdFrame& input);
  cv::Mat extractionMask(const RgbdFrame& input, FrameResult& result);
  Frame extractFeatures(const PreparedFrame& prep, const RgbdFrame& input, const cv::Mat& allowed,
                        const Instances& instances);
  void rejectMovers(const RgbdFrame& input, const InitialPose& initial, Frame& frame,
                    const Instances& instances, FrameDynamics& record);
  void verifyPriors(const PreparedFrame& prep, const RgbdFrame& input, const Frame& frame,
                    const TrackOutcome& outcome, FrameResult& result);
  void trackObjects(const PreparedFrame& prep, const RgbdFrame& input, const Frame& frame,
                    const TrackOutcome& outcome, FrameResult& result);
  void giveFeedback(const RgbdFrame& input, const Frame& frame, const TrackOutcome& outcome,
                    FrameResult& result);
  void fillResult(const Frame& frame, const TrackOutcome& outcome, FrameResult& result) const;

  Config config_;
  PinholeCamera camera_;
  bool dynamic_ = false;
  StageTimers timers_;
  FramePrep prep_;
  std::unique_ptr<Segmenter> segmenter_;  // null with dynamics off
  std::string segmenter_name_ = "off";
  std::unique_ptr<SlamSystem> slam_;
  std::unique_ptr<PriorVerifier> verifier_;
  std::unique_ptr<ObjectTracker> tracker_;   // null with dynamics or object tracking off
  std::unique_ptr<FeedbackStage> feedback_;  // null without tracker_ or with assist off
  std::vector<uint16_t>
      depth_voted_;  // this frame's non-prior instances the depth test found moving
};

}  // namespace dynanav
