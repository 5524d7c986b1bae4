#include "perception/mask_carrier.hpp"

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "core/timer.hpp"

namespace dynanav {
namespace {
using Clock = std::chrono::steady_clock;

/// `total` (i → k) extended by `step` (k → j): total(x) += step(x + total(x)).
void appendStep(cv::Mat& total, const cv::Mat& step) {
  cv::Mat map(total.size(), CV_32FC2);
  for (int y = 0; y < total.rows; ++y) {
    const auto* t = total.ptr<cv::Vec2f>(y);
    auto* m = map.ptr<cv::Vec2f>(y);
    for (int x = 0; x < total.cols; ++x) m[x] = {float(x) + t[x][0], float(y) + t[x][1]};
  }
  cv::Mat sampled;
  cv::remap(step, sampled, map, cv::Mat(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  total += sampled;
}
}  // namespace

MaskCarrier::MaskCarrier(const PerceptionConfig& config, int history_frames)
    : config_(config),
      history_frames_(std::max(1, history_frames)),
      dis_(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_FAST)) {}

void MaskCarrier::reset(const RgbdFrame& frame, const Instances& instances) {
  grey_ = flowGrey(frame.bgr, config_.flow_scale);
  reference_ = instances;
  steps_.clear();
  steps_.push_back({frame.index, frame.index, {}});  // marks where the history starts
}

cv::Mat MaskCarrier::chainedFlowTo(int index) const {
  cv::Mat total;
  for (auto it = steps_.rbegin(); it != steps_.rend(); ++it) {
    if (it->flow.empty()) return {};  // the history starts after `index`
    if (total.empty())
      total = it->flow.clone();
    else
      appendStep(total, it->flow);
    if (it->previous_index == index) return total;
    if (it->previous_index < index) return {};  // `index` was not a processed frame
  }
  return {};
}

Instances MaskCarrier::carry(const RgbdFrame& frame, const Instances* arrived,
                             const RgbdFrame* arrived_frame) {
  timing_ = {};
  if (arrived && arrived_frame && arrived_frame->index == frame.index) {
    reset(frame, *arrived);
    return *arrived;
  }
  const auto t0 = Clock::now();
  const cv::Mat grey = flowGrey(frame.bgr, config_.flow_scale);
  if (grey_.empty() || grey.size() != grey_.size() ||
      reference_.labels.size() != frame.bgr.size()) {
    reset(frame, Instances::none(frame.bgr.size()));  // nothing to carry
    return reference_;
  }
  // Flow from the new frame to the last one: where each new pixel came from.
  cv::Mat flow;
  dis_->calc(grey, grey_, flow);
  steps_.push_back({frame.index, steps_.empty() ? frame.index : steps_.back().index, flow});
  while (static_cast<int>(steps_.size()) > history_frames_) steps_.pop_front();

  const Instances* source = &reference_;
  cv::Mat source_flow = flow;
  if (arrived && arrived_frame) {
    source = arrived;
    source_flow = chainedFlowTo(arrived_frame->index);
    if (!source_flow.empty()) {
      ++chained_;
    } else {
      ++direct_;
      dis_->calc(grey, flowGrey(arrived_frame->bgr, config_.flow_scale), source_flow);
    }
  }
  timing_.flow_ms = msSince(t0);
  Instances out =
      warpInstances(*source, source_flow, frame, config_, buffers_, timing_, config_.carry_grow_px);
  grey_ = grey;
  reference_ = out;
  return out;
}

}  // namespace dynanav
