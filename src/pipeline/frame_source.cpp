#include "pipeline/frame_source.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/error.hpp"

namespace dynanav {
namespace {

RgbdFrame blackFrame(const RgbdFrame& like, const PinholeCamera& camera) {
  RgbdFrame f = like;
  const cv::Size size = like.bgr.empty() ? cv::Size(camera.width, camera.height) : like.bgr.size();
  f.bgr = cv::Mat::zeros(size, CV_8UC3);
  f.depth_m = cv::Mat::zeros(size, CV_32F);
  return f;
}

}  // namespace

PassStep passStep(size_t delivered, size_t per_pass) {
  PassStep step;
  if (per_pass == 0) return step;
  step.pass = static_cast<int>(delivered / per_pass);
  step.backward = step.pass % 2 == 1;
  const size_t position = delivered % per_pass;
  step.index = step.backward ? per_pass - 1 - position : position;
  return step;
}

double passStamp(double stamp_s, const PassStep& step, double first_s, double last_s,
                 double span_s) {
  const double pass_start_s = first_s + step.pass * span_s;
  return pass_start_s + (step.backward ? last_s - stamp_s : stamp_s - first_s);
}

SequenceSource::SequenceSource(const SequenceSourceOptions& options)
    : options_(options),
      sequence_(TumSequence::open(options.dir, options.io, options.fallback_camera)) {
  total_ = sequence_.size();
  if (options.max_frames > 0) total_ = std::min<size_t>(total_, options.max_frames);
  if (total_ > 0) {
    const auto& pairs = sequence_.pairs();
    first_s_ = pairs.front().rgb.stamp_s;
    last_s_ = pairs[total_ - 1].rgb.stamp_s;
    if (total_ > 1) pass_span_s_ = (last_s_ - first_s_) * double(total_) / double(total_ - 1);
  }
  prefetch();
}

void SequenceSource::prefetch() {
  if (delivered_ >= expected()) return;
  const size_t index = passStep(delivered_, total_).index;
  next_ = std::async(std::launch::async, [this, index] { return sequence_.load(index); });
}

std::optional<RgbdFrame> SequenceSource::next() {
  while (delivered_ < expected()) {
    const PassStep step = passStep(delivered_, total_);
    const int index = static_cast<int>(step.index);
    RgbdFrame frame;
    try {
      frame = next_.get();
    } catch (const InputError& e) {
      ++skipped_;
      spdlog::warn("frame {} skipped: {}", index, e.what());
      ++delivered_;
      prefetch();
      continue;
    }
    frame.index = static_cast<int>(delivered_);  // the place in the played stream
    ++delivered_;
    prefetch();
    const auto& blackout = options_.blackout;
    if (blackout && index >= blackout->first && index <= blackout->second)
      frame = blackFrame(frame, camera());
    if (step.pass > 0) {
      frame.stamp_s = passStamp(frame.stamp_s, step, first_s_, last_s_, pass_span_s_);
      frame.depth_stamp_s = passStamp(frame.depth_stamp_s, step, first_s_, last_s_, pass_span_s_);
    }
    return frame;
  }
  return std::nullopt;
}

std::string SequenceSource::describe() const {
  return sequence_.dir().string();
}

}  // namespace dynanav
