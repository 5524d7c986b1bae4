#include "perception/propagation.hpp"

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "core/timer.hpp"
#include "perception/depth_masks.hpp"

namespace dynanav {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

MaskPropagator::MaskPropagator(const PerceptionConfig& config)
    : config_(config), dis_(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_FAST)) {}

cv::Mat MaskPropagator::smallGrey(const cv::Mat& bgr) const {
  cv::Mat grey, small;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  if (config_.flow_scale >= 1.0) return grey;
  cv::resize(grey, small, cv::Size(), config_.flow_scale, config_.flow_scale, cv::INTER_AREA);
  return small;
}

void MaskPropagator::setReference(const RgbdFrame& frame, const Instances& instances) {
  reference_grey_ = smallGrey(frame.bgr);
  reference_ = instances;
}

Instances MaskPropagator::propagate(const RgbdFrame& frame) {
  auto t0 = Clock::now();
  const cv::Mat grey = smallGrey(frame.bgr);
  if (reference_grey_.empty() || grey.size() != reference_grey_.size() ||
      reference_.labels.size() != frame.bgr.size()) {
    setReference(frame, Instances::none(frame.bgr.size()));  // nothing to carry
    return reference_;
  }
  // Flow from the new frame to the reference: where each new pixel came from.
  dis_->calc(grey, reference_grey_, flow_small_);
  timing_.flow_ms = msSince(t0);

  t0 = Clock::now();
  cv::resize(flow_small_, flow_, frame.bgr.size(), 0, 0, cv::INTER_LINEAR);
  const float to_full = float(frame.bgr.cols) / float(grey.cols);
  map_.create(flow_.size(), CV_32FC2);
  for (int y = 0; y < map_.rows; ++y) {
    auto* m = map_.ptr<cv::Vec2f>(y);
    const auto* f = flow_.ptr<cv::Vec2f>(y);
    for (int x = 0; x < map_.cols; ++x) m[x] = {float(x) + to_full * f[x][0], float(y) + to_full * f[x][1]};
  }
  Instances out;
  cv::remap(reference_.labels, out.labels, map_, cv::Mat(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar());
  out.items = reference_.items;
  tightenToLabels(out);
  timing_.warp_ms = msSince(t0);

  t0 = Clock::now();
  for (Instance& item : out.items) {
    item.mask_source = "flow";
    const cv::Mat mask = out.labels(item.box) == item.id;
    if (item.keypoints) {
      // Keypoints move with the mean flow of their instance (pixel = source - flow).
      const cv::Scalar mean_flow = cv::mean(flow_(item.box), mask) * double(to_full);
      for (Keypoint& k : item.keypoints->points)
        k.pixel -= cv::Point2f(float(mean_flow[0]), float(mean_flow[1]));
    }
    if (frame.depth_m.empty()) continue;
    cv::Mat kept = mask.clone();
    refineMaskByDepth(kept, frame.depth_m(item.box), config_.depth_bin_m, config_.propagation_depth_band_m);
    out.labels(item.box).setTo(cv::Scalar(0), mask & ~kept);
  }
  tightenToLabels(out);
  timing_.depth_ms = msSince(t0);

  reference_grey_ = grey;
  reference_ = out;
  return out;
}

PropagatingSegmenter::PropagatingSegmenter(std::unique_ptr<Segmenter> inner, int every,
                                           const PerceptionConfig& config)
    : inner_(std::move(inner)), every_(std::max(1, every)), propagator_(config) {}

std::string PropagatingSegmenter::name() const {
  return inner_->name() + "/every" + std::to_string(every_);
}

Instances PropagatingSegmenter::segment(const RgbdFrame& frame) {
  const bool key = calls_++ % every_ == 0 || !propagator_.hasReference();
  if (key) {
    Instances out = inner_->segment(frame);
    timing_ = inner_->lastTiming();
    propagator_.setReference(frame, out);
    return out;
  }
  Instances out = propagator_.propagate(frame);
  const PropagationTiming& t = propagator_.lastTiming();
  timing_ = {{"flow", t.flow_ms}, {"warp", t.warp_ms}, {"propagate_depth", t.depth_ms}};
  return out;
}

}  // namespace dynanav
