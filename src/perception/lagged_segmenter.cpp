#include "perception/lagged_segmenter.hpp"

#include <algorithm>

namespace dynanav {

LaggedSegmenter::LaggedSegmenter(std::unique_ptr<Segmenter> inner, int lag_frames,
                                 const PerceptionConfig& config)
    : inner_(std::move(inner)),
      lag_frames_(std::max(0, lag_frames)),
      carrier_(config, config.carry_history_frames) {}

LaggedSegmenter::LaggedSegmenter(std::unique_ptr<Segmenter> inner, std::map<int, int> arrivals,
                                 const PerceptionConfig& config)
    : inner_(std::move(inner)),
      lag_frames_(0),
      carrier_(config, config.carry_history_frames),
      arrivals_(std::move(arrivals)) {}

std::string LaggedSegmenter::name() const {
  if (!arrivals_.empty()) return inner_->name() + "/replay";
  return inner_->name() + "/lag" + std::to_string(lag_frames_);
}

Instances LaggedSegmenter::segment(const RgbdFrame& frame) {
  timing_.clear();
  if (!started_) {
    started_ = true;
    Instances first = inner_->segment(frame);
    timing_ = inner_->lastTiming();
    first.segmented_index = frame.index;
    carrier_.reset(frame, first);
    return first;
  }
  const auto scheduled = arrivals_.find(frame.index);
  // Fixed lag: the worker is idle once its last result is due.
  const bool busy = std::any_of(in_flight_.begin(), in_flight_.end(),
                                [&](const InFlight& f) { return f.ready_at > frame.index; });
  const bool start = arrivals_.empty() ? !busy : scheduled != arrivals_.end();
  if (start) {
    // The idle worker takes the newest frame: this one.
    RgbdFrame copy = frame;
    copy.bgr = frame.bgr.clone();
    Instances instances = inner_->segment(frame);
    instances.segmented_index = frame.index;
    for (const auto& [step, ms] : inner_->lastTiming()) timing_["worker." + step] = ms;
    const int ready_at = arrivals_.empty() ? frame.index + lag_frames_ : scheduled->second;
    in_flight_.push_back({std::move(copy), std::move(instances), ready_at});
  }
  // Of the results due now the newest is used (the real worker keeps only its newest result).
  std::optional<InFlight> arrived;
  for (auto it = in_flight_.begin(); it != in_flight_.end();) {
    if (it->ready_at > frame.index) {
      ++it;
      continue;
    }
    if (!arrived || it->frame.index > arrived->frame.index) arrived = std::move(*it);
    it = in_flight_.erase(it);
  }
  Instances carried =
      arrived ? carrier_.carry(frame, &arrived->instances, &arrived->frame) : carrier_.carry(frame);
  const PropagationTiming& t = carrier_.lastTiming();
  timing_["propagation"] = t.flow_ms + t.warp_ms + t.depth_ms;
  return carried;
}

}  // namespace dynanav
