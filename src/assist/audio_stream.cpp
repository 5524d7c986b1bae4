#include "assist/audio_stream.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {
namespace {
/// Frames per mixer call and sink write (0.1 s at 48 kHz).
constexpr int64_t kChunkFrames = 4800;
}  // namespace

AudioStream::AudioStream(AudioStreamOptions options, std::vector<std::unique_ptr<PcmSink>> sinks)
    : options_(options),
      mixer_(std::make_unique<AudioMixer>(options.mixer)),
      sinks_(std::move(sinks)) {
  if (options_.threaded) thread_ = std::thread([this] { threadLoop(); });
}

AudioStream::~AudioStream() {
  try {
    finish(renderedS());
  } catch (...) {  // an error already reported by finish(), or a destructor during unwinding
  }
}

int64_t AudioStream::toSample(double t_s) const {
  return std::llround(std::max(0.0, t_s) * options_.mixer.rate_hz);
}

int64_t AudioStream::clockSample() const {
  const double t_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - options_.epoch).count();
  return toSample(t_s + options_.lead_s);
}

double AudioStream::renderedS() const {
  return double(position_.load()) / options_.mixer.rate_hz;
}

void AudioStream::advanceTo(double t_s) {
  if (options_.threaded) return;  // the audio thread follows the clock
  int64_t target = 0;
  {
    std::lock_guard lock(mutex_);
    if (finished_) return;
    claimed_ = std::max(claimed_, toSample(t_s));
    target = claimed_;
  }
  renderTo(target);
}

std::optional<double> AudioStream::play(double not_before_s, MessageSound sound) {
  std::lock_guard lock(mutex_);
  if (finished_ || error_) return std::nullopt;
  if (options_.threaded && starts_.size() >= options_.queue_messages) return std::nullopt;
  // Rounded up: a message never starts before the time it was decided at (rounding to the
  // nearest sample could place it up to half a sample, 10 us, before its frame's arrival).
  const auto first_sample =
      static_cast<int64_t>(std::ceil(std::max(0.0, not_before_s) * options_.mixer.rate_hz - 1e-9));
  const int64_t sample = std::max(first_sample, claimed_);
  // Starts come in time order (each after the previous message's start); keep it so anyway.
  const auto at = std::upper_bound(starts_.begin(), starts_.end(), sample,
                                   [](int64_t s, const Start& start) { return s < start.sample; });
  starts_.insert(at, Start{sample, std::move(sound)});
  wake_.notify_all();
  return double(sample) / options_.mixer.rate_hz;
}

void AudioStream::renderTo(int64_t target) {
  while (position_.load() < target) {
    std::optional<Start> start;
    {
      std::lock_guard lock(mutex_);
      if (!starts_.empty() && starts_.front().sample <= position_.load()) {
        start = std::move(starts_.front());
        starts_.pop_front();
      }
    }
    if (start) {
      mixer_->play(start->sound);
      continue;
    }
    int64_t stop = std::min(target, position_.load() + kChunkFrames);
    {
      std::lock_guard lock(mutex_);
      if (!starts_.empty()) stop = std::min(stop, starts_.front().sample);
    }
    chunk_.clear();
    const auto frames = static_cast<size_t>(stop - position_.load());
    mixer_->render(frames, chunk_);
    for (auto& sink : sinks_) sink->write(chunk_.data(), frames);
    position_.store(stop);
  }
  // A start exactly at the target sample begins with the next span.
}

void AudioStream::threadLoop() {
  try {
    std::unique_lock lock(mutex_);
    while (true) {
      const auto wake_at = std::chrono::steady_clock::now() +
                           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               std::chrono::duration<double>(options_.tick_s));
      // Finishing unpaced: no more waiting. Otherwise one tick (starts are taken at their sample
      // whenever they come, as long as they are not yet rendered).
      wake_.wait_until(lock, wake_at,
                       [this] { return end_sample_.has_value() && !options_.paced_tail; });
      int64_t target = clockSample();
      if (end_sample_) target = options_.paced_tail ? std::min(*end_sample_, target) : *end_sample_;
      target = std::max(target, position_.load());
      claimed_ = std::max(claimed_, target);
      lock.unlock();
      renderTo(target);
      lock.lock();
      if (end_sample_ && position_.load() >= *end_sample_) break;
    }
  } catch (...) {
    std::lock_guard lock(mutex_);
    error_ = std::current_exception();
  }
  AudioMixer::releaseThread();
}

void AudioStream::finish(double end_s) {
  {
    std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
    end_sample_ = std::max(toSample(end_s), position_.load());
    wake_.notify_all();
  }
  if (thread_.joinable())
    thread_.join();
  else
    renderTo(*end_sample_);
  for (auto& sink : sinks_) sink->finish();
  if (error_) std::rethrow_exception(error_);
}

}  // namespace dynanav
