#include "assist/audio_feedback.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "assist/earcon.hpp"

namespace dynanav {

AudioFeedback::AudioFeedback(AudioFeedbackOptions options,
                             std::vector<std::unique_ptr<PcmSink>> sinks)
    : options_(std::move(options)),
      speech_(options_.speech),
      scheduler_(options_.scheduler),
      stream_(options_.stream, std::move(sinks)) {
  stats_.hrtf = stream_.mixer().hrtfEnabled();
  stats_.hrtf_name = stream_.mixer().hrtfName();
  stats_.resampler = stream_.mixer().resamplerName();
  stats_.voice = options_.speech.voice;
}

void AudioFeedback::schedule(std::vector<FeedbackEvent>& events, double now_s, double reference_s) {
  // Urgent first: within one frame an urgent message must not find the channel taken by an
  // info message raised beside it.
  std::vector<size_t> order(events.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return int(events[a].priority) > int(events[b].priority);
  });
  for (const size_t i : order) {
    FeedbackEvent& event = events[i];
    const auto begin = std::chrono::steady_clock::now();
    event.audio_start_s = -1.0;
    const ScheduleDecision decision = scheduler_.decide(event.priority, reference_s, now_s);
    if (!decision.plays()) {
      scheduler_.drop(decision);
      continue;
    }
    MessageSound sound;
    sound.mix_rate_hz = stream_.rateHz();
    sound.earcon = synthesiseEarcon(event.priority, sound.mix_rate_hz, options_.earcon_gain);
    sound.speech = speech_.speak(event.text);
    sound.speech_offset_s =
        double(sound.earcon.size()) / sound.mix_rate_hz + options_.earcon_to_speech_s;
    sound.bearing_deg = event.bearing_deg;
    sound.distance_m = event.distance_m;
    const double duration_s = sound.durationS();
    const std::optional<double> start_s = stream_.play(decision.start_s, std::move(sound));
    if (!start_s) {
      ++stats_.dropped_queue;  // the scheduler does not count it: it never plays
      continue;
    }
    scheduler_.commit(event.priority, decision, *start_s, duration_s);
    event.audio_start_s = *start_s;
    stats_.latency_ms.push_back(1000.0 * (*start_s - reference_s));
    stats_.message_s.push_back(duration_s);
    stats_.prepare_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
            .count());
  }
}

AudioFeedbackStats AudioFeedback::finish(double end_s, bool cut) {
  if (!cut) end_s = std::max(end_s, scheduler_.busyUntilS());
  stream_.finish(end_s);
  AudioFeedbackStats stats = stats_;
  stats.scheduler = scheduler_.counts();
  stats.stream_s = stream_.renderedS();
  return stats;
}

}  // namespace dynanav
