#pragma once
// Real-time mode (issue 12): the segmenter runs in its own thread on the newest frame it was
// given, and every call returns at once with the newest segmentation carried to the current
// frame by mask propagation. One frame waits at most (a queue of capacity 1, newest wins);
// the worker is joined in the destructor. Deterministic runs use the inner segmenter directly.
// The worker records its own time (stage "segmenter_thread", and its steps under
// "segmenter_thread.STEP") into `timers`; lastTiming() is the caller's propagation.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "core/timer.hpp"
#include "perception/mask_carrier.hpp"

namespace dynanav {

class AsyncSegmenter final : public Segmenter {
 public:
  AsyncSegmenter(std::unique_ptr<Segmenter> inner, const PerceptionConfig& config,
                 StageTimers* timers = nullptr);
  ~AsyncSegmenter() override;
  AsyncSegmenter(const AsyncSegmenter&) = delete;
  AsyncSegmenter& operator=(const AsyncSegmenter&) = delete;

  /// Hands the frame to the worker if it is idle and returns the newest finished segmentation
  /// propagated to this frame. The first frame is segmented in the caller's thread (the map is
  /// initialised from it). Rethrows, once,
  /// an exception the inner segmenter threw.
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override { return inner_->name() + "/async"; }
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }
  /// Segmentations finished by the worker so far.
  [[nodiscard]] long finished() const;

 private:
  struct Result {
    RgbdFrame frame;
    Instances instances;
  };
  void work();

  std::unique_ptr<Segmenter> inner_;
  StageTimers* timers_;
  int nice_;
  MaskCarrier carrier_;                   // used by the caller's thread only
  std::map<std::string, double> timing_;  // the caller's last propagation
  bool started_ = false;                  // the first frame was segmented in the caller's thread
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<RgbdFrame> pending_;  // given to the worker, not yet taken
  std::optional<Result> done_;        // newest finished, not yet collected
  std::exception_ptr error_;
  long finished_ = 0;
  bool stop_ = false;
  std::thread worker_;  // last: starts after the members above exist
};

}  // namespace dynanav
