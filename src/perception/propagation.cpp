#include "perception/propagation.hpp"

#include <chrono>
#include <opencv2/imgproc.hpp>

#include "core/timer.hpp"
#include "perception/depth_masks.hpp"

namespace dynanav {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

void growWithinDepth(cv::Mat& labels, const cv::Mat& depth_m, uint16_t id, int grow_px,
                     double bin_m, double band_m) {
  const cv::Rect all(0, 0, labels.cols, labels.rows);
  const cv::Mat own = labels == id;
  const cv::Rect box = cv::boundingRect(own);
  if (box.area() == 0) return;
  const cv::Rect grown = cv::Rect(box.x - grow_px, box.y - grow_px, box.width + 2 * grow_px,
                                  box.height + 2 * grow_px) &
                         all;
  cv::Mat region = own(grown);
  const float mode = depthMode(depth_m(grown), region, bin_m);
  if (mode <= 0.f) return;
  cv::Mat reach;
  cv::dilate(region, reach,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * grow_px + 1, 2 * grow_px + 1}));
  cv::Mat roi = labels(grown);
  const cv::Mat z = depth_m(grown);
  const float band = float(band_m);
  for (int y = 0; y < roi.rows; ++y) {
    auto* l = roi.ptr<uint16_t>(y);
    const uchar* r = reach.ptr<uchar>(y);
    const uchar* o = region.ptr<uchar>(y);
    const float* d = z.ptr<float>(y);
    for (int x = 0; x < roi.cols; ++x) {
      const bool near = validDepth(d[x]) && std::abs(d[x] - mode) <= band;
      if (o[x] && validDepth(d[x]) && !near)
        l[x] = 0;  // flow put it on the background
      else if (!o[x] && r[x] && l[x] == 0 && near)
        l[x] = id;  // the part flow left behind
    }
  }
}

Instances warpInstances(const Instances& reference, const cv::Mat& flow_small,
                        const RgbdFrame& frame, const PerceptionConfig& config,
                        WarpBuffers& buffers, PropagationTiming& timing, int grow_px) {
  auto t0 = Clock::now();
  cv::Mat& flow = buffers.flow;
  cv::Mat& map = buffers.map;
  cv::resize(flow_small, flow, frame.bgr.size(), 0, 0, cv::INTER_LINEAR);
  const float to_full = float(frame.bgr.cols) / float(flow_small.cols);
  map.create(flow.size(), CV_32FC2);
  for (int y = 0; y < map.rows; ++y) {
    auto* m = map.ptr<cv::Vec2f>(y);
    const auto* f = flow.ptr<cv::Vec2f>(y);
    for (int x = 0; x < map.cols; ++x)
      m[x] = {float(x) + to_full * f[x][0], float(y) + to_full * f[x][1]};
  }
  Instances out;
  cv::remap(reference.labels, out.labels, map, cv::Mat(), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
            cv::Scalar());
  out.items = reference.items;
  out.segmented_index = reference.segmented_index;
  tightenToLabels(out);
  timing.warp_ms = msSince(t0);

  t0 = Clock::now();
  for (Instance& item : out.items) {
    item.mask_source = "flow";
    const cv::Mat mask = out.labels(item.box) == item.id;
    if (item.keypoints) {
      // Keypoints move with the mean flow of their instance (pixel = source - flow).
      const cv::Scalar mean_flow = cv::mean(flow(item.box), mask) * double(to_full);
      for (Keypoint& k : item.keypoints->points)
        k.pixel -= cv::Point2f(float(mean_flow[0]), float(mean_flow[1]));
    }
    if (frame.depth_m.empty()) continue;
    if (grow_px > 0) {
      growWithinDepth(out.labels, frame.depth_m, item.id, grow_px, config.depth_bin_m,
                      config.propagation_depth_band_m);
      continue;
    }
    cv::Mat kept = mask.clone();
    refineMaskByDepth(kept, frame.depth_m(item.box), config.depth_bin_m,
                      config.propagation_depth_band_m);
    out.labels(item.box).setTo(cv::Scalar(0), mask & ~kept);
  }
  tightenToLabels(out);
  timing.depth_ms = msSince(t0);
  return out;
}

MaskPropagator::MaskPropagator(const PerceptionConfig& config)
    : config_(config), dis_(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_FAST)) {}

cv::Mat flowGrey(const cv::Mat& bgr, double scale) {
  cv::Mat grey, small;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  if (scale >= 1.0) return grey;
  cv::resize(grey, small, cv::Size(), scale, scale, cv::INTER_AREA);
  return small;
}

void MaskPropagator::setReference(const RgbdFrame& frame, const Instances& instances) {
  reference_grey_ = flowGrey(frame.bgr, config_.flow_scale);
  reference_ = instances;
}

Instances MaskPropagator::propagate(const RgbdFrame& frame) {
  auto t0 = Clock::now();
  const cv::Mat grey = flowGrey(frame.bgr, config_.flow_scale);
  if (reference_grey_.empty() || grey.size() != reference_grey_.size() ||
      reference_.labels.size() != frame.bgr.size()) {
    setReference(frame, Instances::none(frame.bgr.size()));  // nothing to carry
    return reference_;
  }
  // Flow from the new frame to the reference: where each new pixel came from.
  dis_->calc(grey, reference_grey_, flow_small_);
  timing_.flow_ms = msSince(t0);

  Instances out = warpInstances(reference_, flow_small_, frame, config_, buffers_, timing_);
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
