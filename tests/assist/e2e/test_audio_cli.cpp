// `dynanav run ... --audio [live]` end to end (issue 14): feedback.wav is a valid 48 kHz 16-bit
// stereo WAV covering the run (first to last frame; longer when a message still plays), silent
// where no message plays, identical in deterministic runs, playable after an interrupted or
// killed run; --audio live gives a clear exit-2 message without a sound device.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../wav_reader.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 60;  // 2 s at 30 Hz

class AudioCli : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { test::removeScratchDir(dir_); }
  static void SetUpTestSuite() {
    dir_ = test::scratchDir("audio_cli_" + std::to_string(getpid()));
    std::string log;
    ASSERT_EQ(
        test::runCli(
            "simulate --scenario static-room --frames 240 --out " + (dir_ / "seq").string(), &log),
        0)
        << log;
  }
  static std::string run(const std::string& out, const std::string& flags, std::string* log,
                         int* code) {
    *code = test::runCli("run " + (dir_ / "seq").string() + " --out " + (dir_ / out).string() +
                             " --segmenter masks --quiet " + flags,
                         log);
    return (dir_ / out).string();
  }
  static fs::path dir_;
};
fs::path AudioCli::dir_;

/// Sets an environment variable for the CLI runs of one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { setenv(name, value, 1); }
  ~ScopedEnv() { unsetenv(name_); }

 private:
  const char* name_;
};

nlohmann::json stats(const fs::path& out) {
  return nlohmann::json::parse(test::readFile(out / "stats.json"));
}

/// Every message events.jsonl says was heard starts with sound in the WAV; none: all silent.
void expectSoundOnlyWithMessages(const fs::path& out, const test::Wav& wav) {
  std::vector<double> starts;
  std::istringstream lines(test::readFile(out / "events.jsonl"));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) {
      const auto e = nlohmann::json::parse(line);
      if (e.contains("audio_start") && e["audio_start"].is_number() &&
          e["audio_start"].get<double>() >= 0)
        starts.push_back(e["audio_start"].get<double>());
    }
  const auto rendered = stats(out)["feedback_audio"]["rendered"].get<size_t>();
  if (rendered == 0) {
    EXPECT_EQ(wav.peak(0, wav.durationS()), 0);
    return;
  }
  for (const double s : starts) EXPECT_NEAR(wav.firstSoundS(s, s + 0.5, 16), s, 0.003);
}

TEST_F(AudioCli, DeterministicRunWritesAWavOfTheRunsLength) {
  std::string log;
  int code = 0;
  const fs::path out =
      run("det", "--max-frames " + std::to_string(kFrames) + " --audio", &log, &code);
  ASSERT_EQ(code, 0) << log;
  const test::Wav wav = test::readWav(out / "feedback.wav");
  ASSERT_EQ(wav.rate_hz, 48000) << "not a readable WAV";
  EXPECT_EQ(wav.channels, 2);
  EXPECT_EQ(wav.format, SF_FORMAT_WAV | SF_FORMAT_PCM_16);
  // Stream time follows the stamps: first to last frame.
  EXPECT_GE(wav.durationS(), (kFrames - 1) / 30.0 - 1e-3);
  const auto s = stats(out);
  ASSERT_TRUE(s.contains("feedback_audio")) << s.dump();
  ASSERT_TRUE(s.contains("feedback_latency_ms"));
  EXPECT_NEAR(s["feedback_audio"]["stream_s"].get<double>(), wav.durationS(), 1e-3);
  EXPECT_TRUE(s["feedback_audio"]["hrtf"].get<bool>());
  expectSoundOnlyWithMessages(out, wav);
}

TEST_F(AudioCli, DeterministicRunsGiveIdenticalWavs) {
  std::string log;
  int code = 0;
  const std::string flags = "--max-frames 30 --audio --deterministic";
  const fs::path a = run("same_a", flags, &log, &code);
  ASSERT_EQ(code, 0) << log;
  const fs::path b = run("same_b", flags, &log, &code);
  ASSERT_EQ(code, 0) << log;
  const std::string wav_a = test::readFile(a / "feedback.wav");
  EXPECT_GT(wav_a.size(), 44u);
  EXPECT_EQ(wav_a, test::readFile(b / "feedback.wav"));
}

TEST_F(AudioCli, RunWithoutAudioWritesNoWavAndNoAudioStats) {
  std::string log;
  int code = 0;
  const fs::path out = run("none", "--max-frames 10", &log, &code);
  ASSERT_EQ(code, 0) << log;
  EXPECT_FALSE(fs::exists(out / "feedback.wav"));
  EXPECT_FALSE(stats(out).contains("feedback_audio"));
}

TEST_F(AudioCli, RealtimeRunWritesAWavOnTheRunsClock) {
  std::string log;
  int code = 0;
  const fs::path out = run("rt", "--audio --realtime", &log, &code);
  ASSERT_EQ(code, 0) << log;
  const test::Wav wav = test::readWav(out / "feedback.wav");
  ASSERT_EQ(wav.rate_hz, 48000);
  const auto s = stats(out);
  EXPECT_EQ(s["mode"], "realtime");
  // The stream runs on the steady clock from the run's start to its end.
  EXPECT_GT(wav.durationS(), 0.5 * (kFrames - 1) / 30.0);
  EXPECT_LE(wav.durationS(), s["wall_s"].get<double>() + 0.05);
  expectSoundOnlyWithMessages(out, wav);
}

TEST_F(AudioCli, LiveNeedsRealtime) {
  std::string log;
  int code = 0;
  run("live_det", "--max-frames 5 --audio live", &log, &code);
  EXPECT_EQ(code, 2) << log;
  EXPECT_NE(log.find("--audio live"), std::string::npos) << log;
  EXPECT_NE(log.find("--realtime"), std::string::npos) << log;
}

TEST_F(AudioCli, LiveWithoutASoundDeviceIsAClearError) {
  // No OpenAL backend at all: the same as a machine without a sound card, on any machine.
  const ScopedEnv no_backend("ALSOFT_DRIVERS", "no-such-backend");
  std::string log;
  int code = 0;
  run("live_none", "--max-frames 5 --audio live --realtime", &log, &code);
  EXPECT_EQ(code, 2) << log;
  EXPECT_NE(log.find("--audio live: no sound device"), std::string::npos) << log;
  EXPECT_NE(log.find("default output device"), std::string::npos) << log;  // what was tried
  EXPECT_NE(log.find("use --audio"), std::string::npos) << log;
}

TEST_F(AudioCli, LiveOnADevicePlaysAndWritesTheWav) {
  // OpenAL-soft's null backend: a device that accepts the stream and discards it.
  const ScopedEnv null_backend("ALSOFT_DRIVERS", "null");
  std::string log;
  int code = 0;
  const fs::path out = run("live_null", "--max-frames 30 --audio live --realtime", &log, &code);
  ASSERT_EQ(code, 0) << log;
  EXPECT_EQ(test::readWav(out / "feedback.wav").rate_hz, 48000);
  EXPECT_EQ(stats(out)["feedback_audio"]["output"], "live");
}

TEST_F(AudioCli, UnknownVoiceIsBadInputNamingTheKey) {
  std::ofstream(dir_ / "voice.yaml") << "audio:\n  voice: xx-nosuchvoice\n";
  std::string log;
  int code = 0;
  run("voice", "--max-frames 5 --audio --config " + (dir_ / "voice.yaml").string(), &log, &code);
  EXPECT_EQ(code, 2) << log;
  EXPECT_NE(log.find("audio.voice"), std::string::npos) << log;
}

TEST_F(AudioCli, InterruptedAndKilledRunsLeaveAPlayableWav) {
  for (const int signal_number : {SIGINT, SIGKILL}) {
    const fs::path out = dir_ / ("signal_" + std::to_string(signal_number));
    // Paced at 30 Hz, 4 passes of the 60 frames take 8 s: the signal comes once a second of
    // audio is on disk (48 kHz, 4 bytes per stereo frame, after the 44-byte header), so a
    // loaded machine that starts the run late does not signal it before it has written any.
    const fs::path wav_path = out / "feedback.wav";
    const auto one_second_written = [&wav_path] {
      std::error_code error;
      const auto size = fs::file_size(wav_path, error);
      return !error && size >= 44 + 48000 * 4;
    };
    const int code = test::runAndSignalWhen(
        {"run", (dir_ / "seq").string(), "--out", out.string(), "--segmenter", "masks",
         "--realtime", "--passes", "4", "--audio", "--quiet"},
        signal_number, one_second_written, std::chrono::seconds(60));
    if (signal_number == SIGINT) {
      EXPECT_EQ(code, 130);
    }
    const test::Wav wav = test::readWav(wav_path);
    SCOPED_TRACE("signal " + std::to_string(signal_number));
    ASSERT_EQ(wav.rate_hz, 48000) << "feedback.wav unreadable";
    EXPECT_GT(wav.durationS(), 0.5);
    EXPECT_LT(wav.durationS(), 4 * kFrames / 30.0);
    // The header agrees with the data: frames = data bytes / 4 (a 44-byte header).
    EXPECT_EQ(wav.frames(), (fs::file_size(out / "feedback.wav") - 44) / 4);
  }
}

}  // namespace
}  // namespace dynanav
