// AudioStream (issue 14) in its real-time form: an audio thread renders on the clock; a message
// starts exactly at the sample play() returned, whatever the thread was doing; finish() closes
// a valid WAV. No timing is asserted: only that the stream is where it says.
#include <gtest/gtest.h>

#include "assist/audio_feedback.hpp"
#include "assist/earcon.hpp"
#include "support/test_support.hpp"
#include "wav_reader.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

MessageSound tone(FeedbackPriority priority) {
  MessageSound s;
  s.mix_rate_hz = 48000;
  s.earcon = synthesiseEarcon(priority, 48000, 0.5);
  s.bearing_deg = -45;
  s.distance_m = 1.5;
  return s;
}

TEST(AudioStream, ThreadedStartsLandWhereTheyAreReported) {
  const fs::path dir = test::scratchDir("stream_threaded");
  AudioStreamOptions options;
  options.threaded = true;
  options.tick_s = 0.01;
  std::vector<std::unique_ptr<PcmSink>> sinks;
  sinks.push_back(std::make_unique<WavFileSink>(dir / "feedback.wav", 48000));
  std::vector<double> starts;
  {
    AudioStream stream(options, std::move(sinks));
    for (int i = 0; i < 4; ++i) {
      const auto start = stream.play(0.0, tone(FeedbackPriority::kAdvisory));
      ASSERT_TRUE(start.has_value());
      if (!starts.empty()) {
        EXPECT_GE(*start, starts.back());
      }
      starts.push_back(*start);
      // The next start comes after this earcon has played (in stream time, not wall time).
      while (stream.renderedS() < *start + 0.5)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    stream.finish(starts.back() + 0.5);
  }
  const test::Wav wav = test::readWav(dir / "feedback.wav");
  ASSERT_EQ(wav.rate_hz, 48000);
  EXPECT_GE(wav.durationS(), starts.back() + 0.5 - 1e-3);
  const double earcon_s = earconPattern(FeedbackPriority::kAdvisory).durationS();
  for (const double start : starts) {
    EXPECT_EQ(wav.peak(start - 0.05, start), 0) << "sound before the start at " << start;
    EXPECT_NEAR(wav.firstSoundS(start, start + 0.5, 16), start, 0.002);
    EXPECT_GT(wav.rms(0, start, start + earcon_s), wav.rms(1, start, start + earcon_s));
  }
}

TEST(AudioStream, FullQueueRefusesAMessageInsteadOfWaiting) {
  const fs::path dir = test::scratchDir("stream_queue");
  AudioStreamOptions options;
  options.threaded = true;
  options.tick_s = 5.0;  // the thread sleeps: queued starts in the future stay queued
  options.queue_messages = 2;
  std::vector<std::unique_ptr<PcmSink>> sinks;
  sinks.push_back(std::make_unique<WavFileSink>(dir / "feedback.wav", 48000));
  AudioStream stream(options, std::move(sinks));
  EXPECT_TRUE(stream.play(100.0, tone(FeedbackPriority::kInfo)).has_value());
  EXPECT_TRUE(stream.play(101.0, tone(FeedbackPriority::kInfo)).has_value());
  EXPECT_FALSE(stream.play(102.0, tone(FeedbackPriority::kInfo)).has_value());
  stream.finish(0.0);
}

TEST(AudioStream, InlineStreamIsIdenticalRunToRun) {
  // Deterministic mode: the same starts at the same stream times give the same bytes.
  std::vector<std::string> files;
  for (int run = 0; run < 2; ++run) {
    const fs::path dir = test::scratchDir("stream_inline_" + std::to_string(run));
    std::vector<std::unique_ptr<PcmSink>> sinks;
    sinks.push_back(std::make_unique<WavFileSink>(dir / "feedback.wav", 48000));
    AudioStream stream(AudioStreamOptions{}, std::move(sinks));
    for (int frame = 0; frame < 60; ++frame) {
      stream.advanceTo(frame / 30.0);
      if (frame % 20 == 5) (void)stream.play(frame / 30.0, tone(FeedbackPriority::kUrgent));
    }
    stream.finish(2.0);
    files.push_back(test::readFile(dir / "feedback.wav"));
  }
  EXPECT_GT(files[0].size(), 44u + 4u * 48000u);
  EXPECT_EQ(files[0], files[1]);
}

}  // namespace
}  // namespace dynanav
