#pragma once
// The audio stage of a run (issue 14): between System::process and the writers, it gives each
// message of a FrameResult its start in the audio stream (FeedbackEvent::audio_start_s), so
// events.jsonl can say when the wearer heard it, and renders the stream into feedback.wav (and
// the sound device with --audio live).
// Stream time: deterministic mode = seconds since the first frame's stamp (the stream follows
// the stamps, so the WAV is identical run to run); real time = the steady clock of
// FrameResult::arrival_s (seconds since the run began).
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assist/audio_feedback.hpp"
#include "core/config.hpp"
#include "pipeline/frame_result.hpp"

namespace dynanav {

class AudioStage {
 public:
  /// Opens OUT/feedback.wav (and the default sound device for `audio.output: live`) and checks
  /// the voice for `language` (the messages' language), so a bad setup fails before the run:
  /// InputError naming the option, file or device.
  AudioStage(const Config& config, const std::filesystem::path& out_dir,
             const std::string& language);
  /// The run's clock starts (real time: `epoch` is FrameResult::arrival_s's origin).
  void start(std::chrono::steady_clock::time_point epoch);
  /// Stamps the result's events with their audio start (-1: dropped).
  void process(FrameResult& result);
  /// Ends the stream (`interrupted`: a playing message is cut, not finished).
  AudioFeedbackStats finish(bool interrupted);

 private:
  [[nodiscard]] double clockS() const;

  AudioFeedbackOptions options_;
  std::vector<std::unique_ptr<PcmSink>> sinks_;  // handed to the stream by start()
  std::string output_;
  const LivePlayback* live_ = nullptr;  // among the sinks (--audio live)
  bool realtime_ = false;
  std::optional<double> first_stamp_s_;
  double now_s_ = 0.0;
  std::unique_ptr<AudioFeedback> feedback_;
  std::vector<double> stage_ms_;  // per frame
};

}  // namespace dynanav
