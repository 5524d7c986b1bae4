#include "perception/instance_memory.hpp"

#include <algorithm>
#include <chrono>

#include "core/timer.hpp"

namespace dynanav {
namespace {
// Consecutive boxes of one object overlap far more than this; two different people of one class
// side by side rarely do. Lenient on purpose: a false "seen again" only costs the memory.
constexpr double kCounterpartIou = 0.1;

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double inter = (a & b).area();
  const double uni = double(a.area()) + double(b.area()) - inter;
  return uni > 0.0 ? inter / uni : 0.0;
}

uint16_t freeId(const Instances& instances, uint16_t wanted) {
  if (!instances.find(wanted)) return wanted;
  uint16_t id = 1;
  for (const Instance& i : instances.items) id = std::max<uint16_t>(id, uint16_t(i.id + 1));
  return id;
}
}  // namespace

bool hasCounterpart(const Instance& old, const Instances& fresh, double min_iou) {
  return std::any_of(fresh.items.begin(), fresh.items.end(), [&](const Instance& i) {
    return i.class_name == old.class_name && iou(i.box, old.box) >= min_iou;
  });
}

RememberingSegmenter::RememberingSegmenter(std::unique_ptr<Segmenter> inner, int memory_frames,
                                           const PerceptionConfig& config)
    : inner_(std::move(inner)), memory_frames_(std::max(0, memory_frames)), propagator_(config) {}

Instances RememberingSegmenter::segment(const RgbdFrame& frame) {
  Instances out = inner_->segment(frame);
  timing_ = inner_->lastTiming();
  const auto start = std::chrono::steady_clock::now();
  auto framesCarried = [&](uint16_t id) {
    const auto it = carried_frames_.find(id);
    return it == carried_frames_.end() ? 0 : it->second;
  };
  std::vector<const Instance*> lost;
  for (const Instance& old : last_items_) {
    if (framesCarried(old.id) < memory_frames_ && !hasCounterpart(old, out, kCounterpartIou))
      lost.push_back(&old);
  }
  std::map<uint16_t, int> carried_now;
  if (!lost.empty() && propagator_.hasReference()) {
    const Instances moved = propagator_.propagate(frame);  // the whole last output, carried by flow
    out.labels = out.labels.clone();  // the wrapped segmenter may still hold this image
    for (const Instance* old : lost) {
      const Instance* carried = moved.find(old->id);
      if (!carried) continue;  // left the view or lost its depth layer
      const cv::Mat free_pixels =
          (moved.labels(carried->box) == old->id) & (out.labels(carried->box) == 0);
      if (cv::countNonZero(free_pixels) == 0) continue;
      Instance item = *carried;
      item.id = freeId(out, old->id);
      item.mask_source = "memory";
      out.labels(carried->box).setTo(cv::Scalar(item.id), free_pixels);
      out.items.push_back(item);
      carried_now[item.id] = framesCarried(old->id) + 1;
      ++carried_total_;
    }
    std::sort(out.items.begin(), out.items.end(),
              [](const Instance& a, const Instance& b) { return a.id < b.id; });
    tightenToLabels(out);
  }
  propagator_.setReference(frame, out);
  last_items_ = out.items;
  carried_frames_ = std::move(carried_now);
  timing_["memory"] = msSince(start);
  return out;
}

}  // namespace dynanav
