#pragma once
// The dynamics stage of the per-frame pipeline (DESIGN.md §1 steps 2, 3, 5, 7): it owns the
// segmenter and the per-frame bookkeeping, and offers one call per step so that pipeline/System
// reads as the algorithm:
//   segment()         2. instances of this frame (or propagated ones, --segment-every k)
//   extractionMask()  3. where ORB may look: everything but prior-dynamic objects, dilated
//   labelKeypoints()  3. instance id per keypoint
//   rejectMovers()    5. depth-difference test + instance vote after the initial pose
//   verifyPriors()    7. scene flow of prior objects (static or dynamic) after tracking
// With dynamics off (the baseline) every call is a no-op and nothing is segmented.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/config.hpp"
#include "core/frame.hpp"
#include "core/timer.hpp"
#include "dynamics/keypoint_dynamics.hpp"
#include "perception/segmenter.hpp"
#include "slam/frame.hpp"

namespace dynanav {

/// What the dynamics stage decided for one frame (stats.json series).
struct FrameDynamics {
  int keypoints = 0;          ///< extracted (already outside prior-dynamic masks)
  int dynamic_keypoints = 0;  ///< made unusable by the depth test / instance vote
  int static_keypoints = 0;   ///< usable after the test
  int prior_instances = 0;    ///< people etc. in this frame (cut out of extraction)
  int moving_instances = 0;   ///< non-prior instances voted moving by depth difference
  int prior_moving = 0;       ///< prior instances whose scene flow says moving
  int prior_static = 0;       ///< prior instances whose scene flow says static
  int culled_points = 0;      ///< map points removed: on a moving object, or vanished
  double masked_share = 0.0;  ///< image share cut out of extraction
  std::vector<uint16_t> moving_ids;  ///< moving instance ids (depth vote and scene flow)
};

class DynamicFilter {
 public:
  /// Builds the segmenter named by config.run.segmenter when config.run.dynamic is on; throws
  /// InputError for a missing model file or masks folder. `sequence_dir` serves `masks`.
  DynamicFilter(const Config& config, const std::filesystem::path& sequence_dir, StageTimers* timers);
  ~DynamicFilter();

  [[nodiscard]] bool enabled() const { return enabled_; }
  Instances segment(const RgbdFrame& input);
  /// Uses the depth of the frame last given to segment().
  [[nodiscard]] cv::Mat extractionMask(const Instances& instances);
  void labelKeypoints(Frame& frame, const Instances& instances) const;
  void rejectMovers(Frame& frame);
  /// Scene flow of the previous frame's prior objects into this frame (needs both poses);
  /// closes this frame's record.
  void verifyPriors(const RgbdFrame& input, const Instances& instances, const Frame& frame, bool tracked);

  [[nodiscard]] const std::vector<FrameDynamics>& history() const { return history_; }
  /// Means over frames plus the per-frame series, for stats.json.
  [[nodiscard]] nlohmann::json summary() const;

 private:
  struct Previous;
  Config config_;
  bool enabled_ = false;
  StageTimers* timers_ = nullptr;
  std::unique_ptr<Segmenter> segmenter_;
  std::string segmenter_name_ = "off";
  FrameDynamics current_;
  std::vector<uint16_t> depth_voted_;  // this frame's instances voted moving by the depth test
  cv::Mat current_depth_m_;  // the frame segment() saw (shallow copy)
  std::vector<FrameDynamics> history_;
  std::unique_ptr<Previous> previous_;
};

}  // namespace dynanav
