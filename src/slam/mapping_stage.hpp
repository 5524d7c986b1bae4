#pragma once
// Local mapping as a pipeline stage fed with keyframes by tracking. Deterministic mode: keyframes
// wait in `pending` and run inline when the caller says so (same thread, same order every run).
// Threaded mode: a bounded queue feeds one worker thread; insert() blocks while the queue is
// full (visible back-pressure instead of unbounded growth); finish() drains and joins.
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include "core/config/mapping.hpp"
#include "core/heap.hpp"
#include "core/timer.hpp"
#include "slam/local_mapper.hpp"

namespace dynanav {

class MappingStage {
 public:
  MappingStage(Map& map, const MappingConfig& config, bool threaded, StageTimers* timers);
  ~MappingStage();
  MappingStage(const MappingStage&) = delete;
  MappingStage& operator=(const MappingStage&) = delete;

  void insert(KeyFramePtr keyframe);
  /// Deterministic mode: processes the waiting keyframes now. Threaded mode: nothing.
  void runPending();
  /// No keyframe waiting or being processed.
  [[nodiscard]] bool idle() const;
  /// The queue has room for another keyframe.
  [[nodiscard]] bool accepts() const;
  /// Processes everything still queued, stops the worker and runs the final whole-map bundle
  /// adjustment (idempotent): stop() then finalBundleAdjustment().
  void finish();
  /// Processes everything still queued and stops the worker (idempotent); nothing is inserted
  /// after.
  void stop() { drain(); }
  /// The whole-map bundle adjustment that ends a run (once; call after stop()).
  void finalBundleAdjustment();
  /// Counters of the local mapper (read after finish() in threaded mode).
  [[nodiscard]] LocalMapperStats stats() const { return mapper_.stats(); }
  /// Issue 4: called with each keyframe once local mapping is done with it (loop closing), on the
  /// mapping thread in threaded mode. Set before the first insert().
  void setKeyFrameSink(std::function<void(const KeyFramePtr&)> sink) { sink_ = std::move(sink); }

 private:
  void workerLoop();
  void drain();

  LocalMapper mapper_;
  /// After a keyframe, on the mapping thread (the frame's own in deterministic runs, where
  /// timing does not matter): the allocator's free pages go back every 10 s (core/heap.hpp), so
  /// a long run's resident memory follows its live heap more closely.
  PeriodicHeapRelease release_heap_{10.0};
  const bool threaded_;
  const size_t capacity_;
  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<KeyFramePtr> queue_;
  bool busy_ = false;
  bool stopping_ = false;
  bool final_done_ = false;
  std::thread worker_;
  std::function<void(const KeyFramePtr&)> sink_;
};

}  // namespace dynanav
