#pragma once
// Loop closing as a consumer of the keyframes local mapping has finished (ORB-SLAM2 LoopClosing):
// each keyframe gets its bag of words and enters the keyframe database; loop candidates are
// detected, verified, and a verified loop is corrected (loop_correction.hpp). A global bundle
// adjustment follows: inline in deterministic mode, in its own thread otherwise (joined by
// finish(); no new loop is searched while it runs).
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/config/loop.hpp"
#include "slam/loop_detector.hpp"
#include "slam/loop_places.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct LoopEvent {
  uint64_t keyframe_id = 0;
  uint64_t frame_id = 0;  ///< frame that became the keyframe closing the loop
  double stamp_s = 0.0;
  uint64_t loop_keyframe_id = 0;
  uint64_t loop_frame_id = 0;
  int matches = 0;
  double correction_m = 0.0;  ///< how far the current keyframe moved
};

class LoopCloser {
 public:
  LoopCloser(Map& map, PlaceIndex& places, const LoopConfig& config, int covisibility_min_weight,
             bool threaded);
  ~LoopCloser();
  LoopCloser(const LoopCloser&) = delete;
  LoopCloser& operator=(const LoopCloser&) = delete;

  /// A keyframe local mapping has finished with (takes the map lock itself).
  void process(const KeyFramePtr& keyframe);
  /// Waits for a running global bundle adjustment (idempotent).
  void finish();
  [[nodiscard]] std::vector<LoopEvent> loops() const;
  [[nodiscard]] int globalBundleAdjustments() const { return global_bas_; }

 private:
  void globalBundleAdjustment();

  Map& map_;
  PlaceIndex& places_;
  LoopConfig config_;
  int covisibility_min_weight_;
  bool threaded_;
  LoopDetector detector_;
  uint64_t last_loop_keyframe_ = 0;
  mutable std::mutex events_mutex_;
  std::vector<LoopEvent> events_;
  std::thread global_ba_thread_;
  std::atomic<bool> global_ba_running_{false};
  std::atomic<int> global_bas_{0};
};

}  // namespace dynanav
