// AudioStage (issue 14): stream time is the frame stamps' (deterministic) or the run's steady
// clock (real time); each message's audio_start_s is set before the writers see the result and
// the WAV has the message there; an interrupted run cuts the playing message.
#include <gtest/gtest.h>
#include <sndfile.h>

#include "core/error.hpp"
#include "pipeline/audio_stage.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

FrameResult frameAt(int index, double stamp_s) {
  FrameResult r;
  r.index = index;
  r.stamp_s = stamp_s;
  return r;
}

FeedbackEvent message(FeedbackPriority priority, const std::string& text) {
  FeedbackEvent e;
  e.priority = priority;
  e.text = text;
  e.bearing_deg = -30;
  e.distance_m = 2;
  return e;
}

/// Frames of feedback.wav (0 when unreadable).
sf_count_t wavFrames(const fs::path& path, int* rate = nullptr) {
  SF_INFO info{};
  SNDFILE* f = sf_open(path.c_str(), SFM_READ, &info);
  if (!f) return 0;
  sf_close(f);
  if (rate) *rate = info.samplerate;
  return info.frames;
}

Config audioConfig(const std::string& output, bool realtime) {
  Config c;
  c.audio.output = output;
  c.run.realtime = realtime;
  c.run.deterministic = !realtime;
  return c;
}

TEST(AudioStage, DeterministicStreamTimeIsSecondsSinceTheFirstStamp) {
  const fs::path dir = test::scratchDir("audio_stage_det");
  AudioStage stage(audioConfig("file", false), dir, "en");
  stage.start(std::chrono::steady_clock::now());
  std::vector<double> starts;
  for (int i = 0; i < 90; ++i) {
    FrameResult r = frameAt(i, 1000.0 + i / 30.0);
    if (i == 15) r.events.push_back(message(FeedbackPriority::kAdvisory, "Person, 11 o'clock"));
    stage.process(r);
    for (const FeedbackEvent& e : r.events) starts.push_back(e.audio_start_s);
  }
  const AudioFeedbackStats stats = stage.finish(false);
  ASSERT_EQ(starts.size(), 1u);
  EXPECT_NEAR(starts[0], 0.5, 1e-9);  // frame 15 at 30 Hz
  ASSERT_EQ(stats.latency_ms.size(), 1u);
  EXPECT_NEAR(stats.latency_ms[0], 0.0, 1e-6);   // a free channel: no wait
  EXPECT_NEAR(stats.stream_s, 89 / 30.0, 1e-3);  // first to last frame
  int rate = 0;
  EXPECT_EQ(wavFrames(dir / "feedback.wav", &rate), sf_count_t(std::llround(89 / 30.0 * 48000)));
  EXPECT_EQ(rate, 48000);
}

TEST(AudioStage, RealtimeStartsOnTheRunsClockAfterTheFramesArrival) {
  const fs::path dir = test::scratchDir("audio_stage_rt");
  AudioStage stage(audioConfig("file", true), dir, "en");
  const auto epoch = std::chrono::steady_clock::now();
  stage.start(epoch);
  FrameResult r = frameAt(0, 5.0);
  r.arrival_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch).count();
  r.events.push_back(message(FeedbackPriority::kUrgent, "Stop, person ahead"));
  stage.process(r);
  const double start = r.events[0].audio_start_s;
  EXPECT_GE(start, r.arrival_s);
  const AudioFeedbackStats stats = stage.finish(false);
  ASSERT_EQ(stats.latency_ms.size(), 1u);
  EXPECT_NEAR(stats.latency_ms[0], 1000.0 * (start - r.arrival_s), 1e-6);
  // Not cut: the stream lasts until the message has played.
  EXPECT_GE(stats.stream_s, start + stats.message_s[0] - 1e-3);
}

TEST(AudioStage, AnInterruptedRunCutsThePlayingMessage) {
  const fs::path dir = test::scratchDir("audio_stage_cut");
  AudioStage stage(audioConfig("file", false), dir, "en");
  stage.start(std::chrono::steady_clock::now());
  FrameResult first = frameAt(0, 0.0);
  first.events.push_back(message(FeedbackPriority::kInfo, "Person, 9 o'clock, 3 metres, walking"));
  stage.process(first);
  FrameResult second = frameAt(1, 0.1);
  stage.process(second);
  const AudioFeedbackStats stats = stage.finish(/*interrupted=*/true);
  EXPECT_NEAR(stats.stream_s, 0.1, 1e-3);
  EXPECT_GT(stats.message_s[0], 1.0);
}

TEST(AudioStage, LiveOutputNeedsRealtime) {
  const fs::path dir = test::scratchDir("audio_stage_live");
  const std::string error =
      test::errorOf([&] { AudioStage stage(audioConfig("live", false), dir, "en"); });
  EXPECT_NE(error.find("--audio live"), std::string::npos) << error;
  EXPECT_NE(error.find("--realtime"), std::string::npos) << error;
}

}  // namespace
}  // namespace dynanav
