// feedback.wav as the audio stage renders it (issue 14), read back with libsndfile: the earcon
// is louder on the object's side, each spoken message lasts at least 0.5 s, messages are
// separated by silence, they start where their audio_start_s says, an urgent one cuts a
// playing one. The events are built here (the message policy is another stage).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "assist/audio_feedback.hpp"
#include "assist/earcon.hpp"
#include "support/test_support.hpp"
#include "wav_reader.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;
using P = FeedbackPriority;

constexpr int kRate = 48000;
constexpr double kFps = 30.0;
constexpr int kSilence = 16;  // |sample| below this is silence (the mix is exactly 0 there)

FeedbackEvent event(P priority, const std::string& text, double bearing_deg,
                    double distance_m = 2.0) {
  FeedbackEvent e;
  e.priority = priority;
  e.text = text;
  e.bearing_deg = bearing_deg;
  e.distance_m = distance_m;
  e.kind = "test";
  return e;
}

struct Rendered {
  test::Wav wav;
  std::vector<FeedbackEvent> events;  // as stamped, in the order raised
  AudioFeedbackStats stats;
};

/// Frames at 30 Hz for `length_s`; `raise(t)` gives the events of the frame at stream time t.
/// Renders inline (deterministic mode) into DIR/feedback.wav.
template <class Raise>
Rendered render(const fs::path& dir, double length_s, Raise raise, bool hrtf = true) {
  AudioFeedbackOptions options;
  options.stream.mixer.hrtf = hrtf;
  std::vector<std::unique_ptr<PcmSink>> sinks;
  sinks.push_back(std::make_unique<WavFileSink>(dir / "feedback.wav", kRate));
  Rendered out;
  {
    AudioFeedback feedback(options, std::move(sinks));
    for (int i = 0; i / kFps <= length_s; ++i) {
      const double t = i / kFps;
      std::vector<FeedbackEvent> events = raise(t);
      feedback.advanceTo(t);
      feedback.schedule(events, t, t);
      out.events.insert(out.events.end(), events.begin(), events.end());
    }
    out.stats = feedback.finish(length_s, false);
  }
  out.wav = test::readWav(dir / "feedback.wav");
  return out;
}

/// One event at `at_s`.
auto once(double at_s, FeedbackEvent e) {
  return [at_s, e](double t) {
    return std::abs(t - at_s) < 0.5 / kFps ? std::vector<FeedbackEvent>{e}
                                           : std::vector<FeedbackEvent>{};
  };
}

double earconS(P p) {
  return earconPattern(p).durationS();
}

TEST(FeedbackWav, IsA48kHz16BitStereoWavOfTheRunsLength) {
  const fs::path dir = test::scratchDir("wav_format");
  const Rendered r = render(dir, 2.0, [](double) { return std::vector<FeedbackEvent>{}; });
  EXPECT_EQ(r.wav.rate_hz, 48000);
  EXPECT_EQ(r.wav.channels, 2);
  EXPECT_EQ(r.wav.format, SF_FORMAT_WAV | SF_FORMAT_PCM_16);
  EXPECT_NEAR(r.wav.durationS(), 2.0, 1.0 / kFps);
  EXPECT_EQ(r.wav.peak(0, 2.0), 0);  // no message: silence
}

TEST(FeedbackWav, EarconIsLouderOnTheSideOfTheObject) {
  const fs::path dir = test::scratchDir("wav_sides");
  for (const P priority : {P::kInfo, P::kAdvisory, P::kUrgent}) {
    for (const double bearing : {-60.0, 60.0}) {
      const Rendered r = render(dir, 2.0, once(0.5, event(priority, "Person", bearing)));
      ASSERT_EQ(r.events.size(), 1u);
      const double start = r.events[0].audio_start_s;
      ASSERT_NEAR(start, 0.5, 1e-9);
      const double left = r.wav.rms(0, start, start + earconS(priority));
      const double right = r.wav.rms(1, start, start + earconS(priority));
      const double db = 20.0 * std::log10(left / right);  // > 0: louder on the left
      std::printf("earcon %-8s at %+4.0f deg: left - right = %+5.1f dB\n",
                  priority == P::kUrgent     ? "urgent"
                  : priority == P::kAdvisory ? "advisory"
                                             : "info",
                  bearing, db);
      SCOPED_TRACE("priority " + std::to_string(int(priority)) + ", bearing " +
                   std::to_string(bearing) + ": left/right " + std::to_string(db) + " dB");
      EXPECT_GT(std::min(left, right), 0.0);
      if (bearing < 0) {
        EXPECT_GT(db, 3.0);
      } else {
        EXPECT_LT(db, -3.0);
      }
    }
  }
}

TEST(FeedbackWav, EarconAheadIsBalancedAndPanningWorksWithoutHrtf) {
  const fs::path dir = test::scratchDir("wav_ahead");
  const Rendered ahead = render(dir, 1.5, once(0.2, event(P::kAdvisory, "Person", 0.0)));
  const double s = ahead.events[0].audio_start_s;
  const double e = s + earconS(P::kAdvisory);
  EXPECT_NEAR(20.0 * std::log10(ahead.wav.rms(0, s, e) / ahead.wav.rms(1, s, e)), 0.0, 1.0);
  const Rendered left =
      render(dir, 1.5, once(0.2, event(P::kAdvisory, "Person", -60.0)), /*hrtf=*/false);
  EXPECT_FALSE(left.stats.hrtf);
  EXPECT_GT(left.wav.rms(0, s, e), 1.4 * left.wav.rms(1, s, e));
}

TEST(FeedbackWav, MessagesStartAtTheirAudioStartAndAreSeparatedBySilence) {
  const fs::path dir = test::scratchDir("wav_sequence");
  const std::vector<std::pair<double, FeedbackEvent>> script = {
      {0.5, event(P::kInfo, "Person, 10 o'clock, 4 metres", -60)},
      {3.6, event(P::kAdvisory, "Person, 2 o'clock, 1 metre", 60)},
      {6.8, event(P::kUrgent, "Person ahead, 2 metres, approaching fast", 0)},
  };
  const Rendered r = render(dir, 10.0, [&](double t) {
    std::vector<FeedbackEvent> out;
    for (const auto& [at, e] : script)
      if (std::abs(t - at) < 0.5 / kFps) out.push_back(e);
    return out;
  });
  ASSERT_EQ(r.events.size(), 3u);
  EXPECT_EQ(r.stats.scheduler.played, 3u);
  EXPECT_EQ(r.wav.peak(0.0, r.events[0].audio_start_s), 0);  // silence before the first
  for (size_t i = 0; i < r.events.size(); ++i) {
    const FeedbackEvent& e = r.events[i];
    const double start = e.audio_start_s;
    const double next = i + 1 < r.events.size() ? r.events[i + 1].audio_start_s : 10.0;
    SCOPED_TRACE("message " + std::to_string(i) + " '" + e.text + "' at " + std::to_string(start));
    EXPECT_NEAR(start, script[i].first, 0.5 / kFps);  // on a free channel: at once
    EXPECT_NEAR(r.wav.firstSoundS(start, next, kSilence), start, 0.003);  // the earcon begins
    // The spoken part: from the end of the earcon to the last sound of the message.
    const double speech_from = start + earconS(e.priority);
    const double last_sound = r.wav.lastSoundS(start, next, kSilence);
    EXPECT_GE(last_sound - speech_from, 0.5);
    EXPECT_GT(r.wav.rms(0, speech_from + 0.1, last_sound), 300.0);  // words, not a click
    // Silence after it, at least the gap, up to the next message.
    EXPECT_GE(next - last_sound, 0.25);
    EXPECT_EQ(r.wav.peak(last_sound + 0.01, next), 0);
  }
}

TEST(FeedbackWav, EachPriorityHasItsOwnPitch) {
  const fs::path dir = test::scratchDir("wav_pitch");
  for (const P priority : {P::kInfo, P::kAdvisory, P::kUrgent}) {
    const Rendered r = render(dir, 1.5, once(0.2, event(priority, "Person", 0.0)));
    const double s = r.events[0].audio_start_s;
    const double e = s + earconPattern(priority).beep_s;  // the first beep
    const double own = r.wav.power(earconPattern(priority).pitch_hz, s, e);
    for (const P other : {P::kInfo, P::kAdvisory, P::kUrgent}) {
      if (other != priority) {
        EXPECT_GT(own, 4.0 * r.wav.power(earconPattern(other).pitch_hz, s, e));
      }
    }
  }
}

TEST(FeedbackWav, UrgentMessageCutsAPlayingInfoMessage) {
  const fs::path dir = test::scratchDir("wav_interrupt");
  const FeedbackEvent info =
      event(P::kInfo, "Person, 10 o'clock, 4 metres, walking slowly to the left", -60);
  const FeedbackEvent urgent = event(P::kUrgent, "Stop, person ahead", 0);
  const Rendered r = render(dir, 5.0, [&](double t) {
    if (std::abs(t - 0.2) < 0.5 / kFps) return std::vector<FeedbackEvent>{info};
    if (std::abs(t - 1.0) < 0.5 / kFps) return std::vector<FeedbackEvent>{urgent};
    return std::vector<FeedbackEvent>{};
  });
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.stats.scheduler.interrupted, 1u);
  const double cut = r.events[1].audio_start_s;
  EXPECT_NEAR(cut, 1.0, 0.5 / kFps);
  EXPECT_GT(r.wav.rms(0, 0.6, cut), 100.0);  // the info message was speaking
  // Right after the cut: the urgent earcon's pitch, not the info speech.
  const double beep = earconPattern(P::kUrgent).beep_s;
  EXPECT_GT(r.wav.power(earconPattern(P::kUrgent).pitch_hz, cut, cut + beep),
            4.0 * r.wav.power(earconPattern(P::kInfo).pitch_hz, cut, cut + beep));
  // The stream ends with the urgent message, long before the info text would have.
  EXPECT_LT(r.wav.lastSoundS(cut, 5.0, kSilence), cut + r.stats.message_s.back() + 0.01);
}

TEST(FeedbackWav, StartsAreMonotonicAndDroppedMessagesHaveNone) {
  const fs::path dir = test::scratchDir("wav_monotonic");
  // An event on every 10th frame, priorities cycling: many find the channel busy.
  const P cycle[] = {P::kInfo, P::kUrgent, P::kAdvisory, P::kUrgent};
  int n = 0;
  const Rendered r = render(dir, 8.0, [&](double t) {
    const int frame = int(std::lround(t * kFps));
    if (frame % 10 != 0) return std::vector<FeedbackEvent>{};
    return std::vector<FeedbackEvent>{
        event(cycle[n++ % 4], "Person, " + std::to_string(frame % 12 + 1) + " o'clock", 30)};
  });
  double last = -1.0;
  size_t played = 0;
  for (const FeedbackEvent& e : r.events) {
    if (e.audio_start_s < 0) continue;
    EXPECT_GE(e.audio_start_s, last);
    last = e.audio_start_s;
    ++played;
  }
  const SchedulerCounts& c = r.stats.scheduler;
  EXPECT_EQ(played, c.played);
  EXPECT_EQ(c.offered, r.events.size());
  EXPECT_EQ(c.played + c.dropped_busy + c.dropped_stale, c.offered);
  EXPECT_GT(c.dropped_busy, 0u);
  EXPECT_GT(c.played, 3u);
  EXPECT_EQ(r.stats.latency_ms.size(), c.played);
}

TEST(FeedbackWav, MessagesOfOneFrameGoUrgentFirst) {
  const fs::path dir = test::scratchDir("wav_same_frame");
  const Rendered r = render(dir, 4.0, [](double t) {
    if (std::abs(t - 0.5) > 0.5 / kFps) return std::vector<FeedbackEvent>{};
    return std::vector<FeedbackEvent>{event(P::kInfo, "Chair, 12 o'clock", 0),
                                      event(P::kUrgent, "Person ahead, stop", 0)};
  });
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_LT(r.events[0].audio_start_s, 0);  // the info message found the channel taken
  EXPECT_NEAR(r.events[1].audio_start_s, 0.5, 0.5 / kFps);
}

}  // namespace
}  // namespace dynanav
