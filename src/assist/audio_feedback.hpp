#pragma once
// The audio stage (issue 14, DESIGN.md §1 step 9 "→ audio"): for each message the policy raised,
// decide when it starts (MessageScheduler), synthesise it (earcon + espeak-ng speech) and start
// it in the stream (AudioStream), and stamp the event's audio_start_s before the writers see it.
// Decisions are made on the caller's thread and cost a speech synthesis per new text (a few ms,
// timed in the stats); rendering runs in the stream's own thread in real time.
#include <memory>
#include <string>
#include <vector>

#include "assist/audio_stream.hpp"
#include "assist/message_scheduler.hpp"
#include "assist/speech_synth.hpp"
#include "core/feedback_event.hpp"

namespace dynanav {

struct AudioFeedbackOptions {
  SpeechOptions speech;
  SchedulerOptions scheduler;
  AudioStreamOptions stream;
  double earcon_gain = 0.5;
  double earcon_to_speech_s = 0.06;  ///< silence between the earcon and the first word
};

/// What the audio did over a run (stats.json "feedback_audio" and "feedback_latency_ms").
struct AudioFeedbackStats {
  SchedulerCounts scheduler;       ///< messages offered = scheduler.offered + dropped_queue
  size_t dropped_queue = 0;        ///< real time: the audio thread's queue was full
  std::vector<double> latency_ms;  ///< per played message: its start minus its reference
  std::vector<double> message_s;   ///< per played message: earcon + speech length
  std::vector<double> prepare_ms;  ///< per played message: synthesis and scheduling time
  std::vector<double> stage_ms;    ///< per frame: the audio stage's time on the pipeline thread
  double stream_s = 0.0;           ///< length of the rendered stream
  bool hrtf = false;
  std::string hrtf_name;
  std::string resampler;
  std::string voice;
  std::string output;         ///< "file" or "live" (set by the run)
  std::string live_device;    ///< --audio live: the device played on
  size_t live_underruns = 0;  ///< --audio live: times the device ran dry
};

class AudioFeedback {
 public:
  /// InputError for a voice espeak-ng lacks or an audio device that cannot be opened.
  AudioFeedback(AudioFeedbackOptions options, std::vector<std::unique_ptr<PcmSink>> sinks);

  /// Deterministic mode: the stream renders up to `now_s` (call before schedule()).
  void advanceTo(double now_s) { stream_.advanceTo(now_s); }
  /// Decides and starts the frame's messages (urgent first, otherwise in order) and sets each
  /// event's audio_start_s (stream seconds; -1 when dropped). `now_s`: stream time now;
  /// `reference_s`: the frame's time on the same clock (its arrival), for the latency.
  void schedule(std::vector<FeedbackEvent>& events, double now_s, double reference_s);
  /// Ends the stream at `end_s`, extended so a message that has started plays to its end
  /// unless `cut` (an interrupted run). Returns the run's audio statistics.
  AudioFeedbackStats finish(double end_s, bool cut);

  /// When the channel is free again (stream seconds; -inf when nothing was played).
  [[nodiscard]] double busyUntilS() const { return scheduler_.busyUntilS(); }

 private:
  AudioFeedbackOptions options_;
  SpeechSynth speech_;
  MessageScheduler scheduler_;
  AudioStream stream_;
  AudioFeedbackStats stats_;
};

}  // namespace dynanav
