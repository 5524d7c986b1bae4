#include "perception/async_segmenter.hpp"

namespace dynanav {

AsyncSegmenter::AsyncSegmenter(std::unique_ptr<Segmenter> inner, const PerceptionConfig& config)
    : inner_(std::move(inner)), propagator_(config), worker_([this] { work(); }) {}

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
      result.instances = inner_->segment(frame);
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
  if (result) {
    if (result->frame.index == frame.index) {
      propagator_.setReference(frame, result->instances);
      return result->instances;
    }
    propagator_.setReference(result->frame, result->instances);
  }
  if (!propagator_.hasReference()) return Instances::none(frame.bgr.size());
  return propagator_.propagate(frame);
}

}  // namespace dynanav
