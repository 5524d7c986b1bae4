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

SequenceSource::SequenceSource(const SequenceSourceOptions& options)
    : options_(options),
      sequence_(TumSequence::open(options.dir, options.io, options.fallback_camera)) {
  total_ = sequence_.size();
  if (options.max_frames > 0) total_ = std::min<size_t>(total_, options.max_frames);
  if (total_ > 1) {
    const auto& pairs = sequence_.pairs();
    const double first = pairs.front().rgb.stamp_s, last = pairs[total_ - 1].rgb.stamp_s;
    pass_span_s_ = (last - first) * double(total_) / double(total_ - 1);
  }
  prefetch();
}

void SequenceSource::prefetch() {
  if (position_ >= total_) return;
  next_ = std::async(std::launch::async, [this, i = position_] { return sequence_.load(i); });
}

std::optional<RgbdFrame> SequenceSource::next() {
  for (;;) {
    if (position_ >= total_) {
      if (pass_ + 1 >= options_.passes || total_ == 0) return std::nullopt;
      ++pass_;  // the next pass: the same images, later in time, counted on
      position_ = 0;
      prefetch();
    }
    const int index = static_cast<int>(position_);
    RgbdFrame frame;
    try {
      frame = next_.get();
    } catch (const InputError& e) {
      ++skipped_;
      spdlog::warn("frame {} skipped: {}", index, e.what());
      ++position_;
      prefetch();
      continue;
    }
    ++position_;
    prefetch();
    const auto& blackout = options_.blackout;
    if (blackout && index >= blackout->first && index <= blackout->second)
      frame = blackFrame(frame, camera());
    if (pass_ > 0) {
      frame.index += pass_ * int(total_);
      frame.stamp_s += pass_ * pass_span_s_;
      frame.depth_stamp_s += pass_ * pass_span_s_;
    }
    return frame;
  }
}

std::string SequenceSource::describe() const {
  return sequence_.dir().string();
}

}  // namespace dynanav
