#include "perception/async_segmenter.hpp"

#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace dynanav {

AsyncSegmenter::AsyncSegmenter(std::unique_ptr<Segmenter> inner, const PerceptionConfig& config,
                               StageTimers* timers)
    : inner_(std::move(inner)),
      timers_(timers),
      nice_(config.segmenter_nice),
      carrier_(config, config.carry_history_frames),
      worker_([this] { work(); }) {}

AsyncSegmenter::~AsyncSegmenter() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

long AsyncSegmenter::finished() const {
  std::lock_guard lock(mutex_);
  return finished_;
}

void AsyncSegmenter::work() {
  // The segmenter uses what tracking leaves of the CPU: a late mask is carried by flow, a late
  // pose is a dropped frame. Linux gives each thread its own nice value.
  if (nice_ > 0 && setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), nice_) != 0)
    spdlog::warn("segmenter thread: cannot set nice {}: it competes with tracking", nice_);
  for (;;) {
    RgbdFrame frame;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || pending_.has_value(); });
      if (stop_) return;
      frame = std::move(*pending_);
      pending_.reset();
    }
    Result result{frame, {}};
    std::exception_ptr error;
    try {
      std::optional<ScopedTimer> timer;
      if (timers_) timer.emplace(*timers_, "segmenter_thread");
      result.instances = inner_->segment(frame);
      result.instances.segmented_index = frame.index;
      if (timers_)
        for (const auto& [step, ms] : inner_->lastTiming())
          timers_->add("segmenter_thread." + step, ms);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(mutex_);
    if (error) {
      error_ = error;
    } else {
      done_ = std::move(result);
      ++finished_;
    }
  }
}

Instances AsyncSegmenter::segment(const RgbdFrame& frame) {
  if (!started_) {
    // The first frame is segmented here, before the worker has anything: SLAM initialises its
    // map from this frame, and must not take the people in it for scenery.
    started_ = true;
    Instances first;
    {
      std::optional<ScopedTimer> timer;
      if (timers_) timer.emplace(*timers_, "segmenter_thread");
      first = inner_->segment(frame);
    }
    first.segmented_index = frame.index;
    carrier_.reset(frame, first);
    return first;
  }
  std::optional<Result> result;
  {
    std::lock_guard lock(mutex_);
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    result.swap(done_);
    // Newest wins: a frame still waiting is replaced. The worker gets its own deep copy, so
    // the caller may reuse its buffers.
    RgbdFrame copy = frame;
    copy.bgr = frame.bgr.clone();
    copy.depth_m = frame.depth_m.clone();
    pending_ = std::move(copy);
  }
  wake_.notify_one();
  if (!carrier_.hasReference()) return Instances::none(frame.bgr.size());
  Instances carried =
      result ? carrier_.carry(frame, &result->instances, &result->frame) : carrier_.carry(frame);
  const PropagationTiming& t = carrier_.lastTiming();
  timing_ = {{"propagation", t.flow_ms + t.warp_ms + t.depth_ms}, {"propagation_flow", t.flow_ms}};
  return carried;
}

}  // namespace dynanav
