#include "perception/lagged_segmenter.hpp"

namespace dynanav {

LaggedSegmenter::LaggedSegmenter(std::unique_ptr<Segmenter> inner, int lag_frames,
                                 const PerceptionConfig& config)
    : inner_(std::move(inner)),
      lag_frames_(std::max(0, lag_frames)),
      carrier_(config, config.carry_history_frames) {}

std::string LaggedSegmenter::name() const {
  return inner_->name() + "/lag" + std::to_string(lag_frames_);
}

Instances LaggedSegmenter::segment(const RgbdFrame& frame) {
  timing_.clear();
  if (!started_) {
    started_ = true;
    Instances first = inner_->segment(frame);
    timing_ = inner_->lastTiming();
    carrier_.reset(frame, first);
    return first;
  }
  std::optional<InFlight> arrived;
  if (in_flight_ && frame.index >= in_flight_->ready_at) arrived.swap(in_flight_);
  if (!in_flight_) {
    // The idle worker takes the newest frame: this one.
    RgbdFrame copy = frame;
    copy.bgr = frame.bgr.clone();
    Instances instances = inner_->segment(frame);
    for (const auto& [step, ms] : inner_->lastTiming()) timing_["worker." + step] = ms;
    in_flight_ = InFlight{std::move(copy), std::move(instances), frame.index + lag_frames_};
    // Lag 0: in time, no carrying needed.
    if (lag_frames_ == 0) arrived.swap(in_flight_);
  }
  Instances carried =
      arrived ? carrier_.carry(frame, &arrived->instances, &arrived->frame) : carrier_.carry(frame);
  const PropagationTiming& t = carrier_.lastTiming();
  timing_["propagation"] = t.flow_ms + t.warp_ms + t.depth_ms;
  return carried;
}

}  // namespace dynanav
