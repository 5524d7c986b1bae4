#include "slam/mapping_stage.hpp"

namespace dynanav {

MappingStage::MappingStage(Map& map, const MappingConfig& config, bool threaded,
                           StageTimers* timers)
    : mapper_(map, config, timers),
      threaded_(threaded),
      capacity_(static_cast<size_t>(std::max(1, config.queue_capacity))) {
  if (threaded_) worker_ = std::thread([this] { workerLoop(); });
}

MappingStage::~MappingStage() {
  finish();
}

void MappingStage::insert(KeyFramePtr keyframe) {
  std::unique_lock lock(queue_mutex_);
  if (threaded_)
    queue_changed_.wait(lock, [this] { return queue_.size() < capacity_ || stopping_; });
  queue_.push_back(std::move(keyframe));
  queue_changed_.notify_all();
}

void MappingStage::runPending() {
  if (threaded_) return;
  while (!queue_.empty()) {
    KeyFramePtr kf = std::move(queue_.front());
    queue_.pop_front();
    mapper_.process(kf, !queue_.empty());
    if (sink_) sink_(kf);
    release_heap_();
  }
}

bool MappingStage::idle() const {
  std::unique_lock lock(queue_mutex_);
  return queue_.empty() && !busy_;
}

bool MappingStage::accepts() const {
  std::unique_lock lock(queue_mutex_);
  return queue_.size() < capacity_;
}

void MappingStage::finish() {
  drain();
  finalBundleAdjustment();
}

void MappingStage::finalBundleAdjustment() {
  if (final_done_) return;
  final_done_ = true;
  mapper_.finalBundleAdjustment();
}

void MappingStage::drain() {
  if (!threaded_) {
    runPending();
    return;
  }
  {
    std::unique_lock lock(queue_mutex_);
    if (stopping_) return;
    stopping_ = true;
    queue_changed_.notify_all();
  }
  if (worker_.joinable()) worker_.join();
}

void MappingStage::workerLoop() {
  for (;;) {
    KeyFramePtr kf;
    bool more_waiting = false;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
      if (queue_.empty()) return;  // stopping and drained
      kf = std::move(queue_.front());
      queue_.pop_front();
      more_waiting = !queue_.empty();
      busy_ = true;
      queue_changed_.notify_all();
    }
    mapper_.process(kf, more_waiting);
    if (sink_) sink_(kf);
    {
      std::unique_lock lock(queue_mutex_);
      busy_ = false;
    }
    release_heap_();
  }
}

}  // namespace dynanav
