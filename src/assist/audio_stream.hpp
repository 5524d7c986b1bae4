#pragma once
// The one audio stream of a run (issue 14): messages start at given samples, the mixer renders,
// the sinks (feedback.wav, live device) get every frame in order. Deterministic mode renders
// inline as frame stamps advance; real-time mode renders in its own thread following the
// steady clock, fed by a bounded queue of messages, so the pipeline never waits on audio.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "assist/audio_mixer.hpp"
#include "assist/audio_sinks.hpp"

namespace dynanav {

struct AudioStreamOptions {
  MixerOptions mixer;
  bool threaded = false;  ///< real time: an audio thread follows the clock from `epoch`
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
  double lead_s = 0.0;      ///< threaded: rendered this far ahead of the clock (a device's queue)
  double tick_s = 0.1;      ///< threaded: the rendering period
  bool paced_tail = false;  ///< threaded finish(): the tail at the clock's pace (live) or at once
  size_t queue_messages = 16;  ///< threaded: messages waiting for the audio thread
};

class AudioStream {
 public:
  AudioStream(AudioStreamOptions options, std::vector<std::unique_ptr<PcmSink>> sinks);
  ~AudioStream();
  AudioStream(const AudioStream&) = delete;
  AudioStream& operator=(const AudioStream&) = delete;

  /// Inline mode: renders up to stream time `t_s` (earlier times: nothing).
  void advanceTo(double t_s);
  /// Starts `sound` at the first sample at or after `not_before_s` that is not yet rendered
  /// (cutting a message that still plays). Returns that start (stream seconds), exactly where
  /// the stream will have it; nullopt when the audio thread's queue is full (not played).
  std::optional<double> play(double not_before_s, MessageSound sound);
  /// Renders up to `end_s` (at least what is rendered already) and finishes the sinks.
  /// Rethrows an error of the audio thread (e.g. the disk full). Later calls do nothing.
  void finish(double end_s);

  [[nodiscard]] double renderedS() const;
  [[nodiscard]] const AudioMixer& mixer() const { return *mixer_; }
  [[nodiscard]] int rateHz() const { return options_.mixer.rate_hz; }

 private:
  struct Start {
    int64_t sample;
    MessageSound sound;
  };
  [[nodiscard]] int64_t toSample(double t_s) const;
  [[nodiscard]] int64_t clockSample() const;
  void renderTo(int64_t target);  // the rendering side only
  void threadLoop();

  AudioStreamOptions options_;
  std::unique_ptr<AudioMixer> mixer_;
  std::vector<std::unique_ptr<PcmSink>> sinks_;
  std::vector<int16_t> chunk_;
  std::atomic<int64_t> position_{0};  // samples rendered and written

  mutable std::mutex mutex_;  // guards what follows
  std::condition_variable wake_;
  std::deque<Start> starts_;  // in sample order
  int64_t claimed_ = 0;       // the renderer may have rendered up to here: starts go after it
  std::optional<int64_t> end_sample_;
  bool finished_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace dynanav
