#include "pipeline/audio_stage.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace dynanav {
namespace {
constexpr int kMixRateHz = 48000;
/// Blocks queued on a live device to cover the render lead (audio_sinks.cpp starts at 4).
constexpr double kLiveBlocks = 4.0;
}  // namespace

AudioStage::AudioStage(const Config& config, const std::filesystem::path& out_dir,
                       const std::string& language)
    : realtime_(config.run.realtime) {
  const AudioConfig& audio = config.audio;
  const bool live = audio.output == "live";
  if (live && !realtime_)
    throw InputError("--audio live",
                     "needs --realtime (a deterministic run is not paced to the clock; listen to "
                     "feedback.wav, which --audio writes)");
  options_.speech = {speechVoice(audio.voice, language), audio.speech_rate_wpm};
  options_.scheduler = {audio.gap_s, audio.stale_after_s};
  options_.earcon_gain = audio.earcon_gain;
  AudioStreamOptions& stream = options_.stream;
  stream.mixer = {kMixRateHz, audio.hrtf, audio.speech_gain};
  stream.threaded = realtime_;
  stream.lead_s = live ? audio.live_buffer_ms / 1000.0 : 0.0;
  stream.tick_s = live ? stream.lead_s / kLiveBlocks : 0.1;
  stream.paced_tail = live;
  stream.queue_messages = size_t(audio.queue_messages);
  const SpeechSynth check(options_.speech);  // a voice espeak-ng lacks fails here
  sinks_.push_back(std::make_unique<WavFileSink>(out_dir / "feedback.wav", kMixRateHz));
  if (live) {
    auto playback = std::make_unique<LivePlayback>(kMixRateHz, stream.tick_s);
    live_ = playback.get();
    sinks_.push_back(std::move(playback));
  }
  output_ = audio.output;
}

void AudioStage::start(std::chrono::steady_clock::time_point epoch) {
  options_.stream.epoch = epoch;
  feedback_ = std::make_unique<AudioFeedback>(options_, std::move(sinks_));
}

double AudioStage::clockS() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - options_.stream.epoch)
      .count();
}

void AudioStage::process(FrameResult& result) {
  const auto begin = std::chrono::steady_clock::now();
  if (realtime_) {
    now_s_ = std::max(now_s_, clockS());
    feedback_->schedule(result.events, now_s_, result.arrival_s);
  } else {
    if (!first_stamp_s_) first_stamp_s_ = result.stamp_s;
    now_s_ = std::max(now_s_, result.stamp_s - *first_stamp_s_);
    feedback_->advanceTo(now_s_);  // deterministic: the rendering is part of this stage
    feedback_->schedule(result.events, now_s_, now_s_);
  }
  stage_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count());
}

AudioFeedbackStats AudioStage::finish(bool interrupted) {
  if (realtime_) now_s_ = std::max(now_s_, clockS());
  AudioFeedbackStats stats = feedback_->finish(now_s_, interrupted);
  stats.output = output_;
  stats.stage_ms = stage_ms_;
  if (live_) {
    stats.live_device = live_->deviceName();
    stats.live_underruns = live_->underruns();
  }
  return stats;
}

}  // namespace dynanav
