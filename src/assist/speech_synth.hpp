#pragma once
// Speech through the espeak-ng library (issue 14): the PCM its synthesis callback delivers, no
// subprocess. espeak-ng is one process-wide engine; every SpeechSynth shares it behind a lock.
#include <cstdint>
#include <string>
#include <vector>

namespace dynanav {

/// Mono 16-bit speech at espeak-ng's own rate (22.05 kHz); the mix resamples it.
struct SpeechPcm {
  std::vector<int16_t> samples;
  int rate_hz = 0;
  [[nodiscard]] double durationS() const {
    return rate_hz > 0 ? double(samples.size()) / rate_hz : 0.0;
  }
};

struct SpeechOptions {
  std::string voice = "en";  ///< espeak-ng voice name (en, de, en-us, ...)
  int rate_wpm = 190;
};

/// The espeak-ng voice for a message language ("en", "de"); `configured` wins unless "auto".
/// InputError naming audio.voice for a language without a voice.
std::string speechVoice(const std::string& configured, const std::string& language);

class SpeechSynth {
 public:
  /// InputError naming the voice when espeak-ng cannot initialise or does not know it.
  explicit SpeechSynth(SpeechOptions options);
  /// The text (UTF-8, already in the voice's language) as PCM, leading and trailing silence
  /// trimmed. The same text always gives the same PCM within a run (cached): espeak-ng's output
  /// for a text otherwise depends slightly on what it spoke before.
  [[nodiscard]] SpeechPcm speak(const std::string& text);
  [[nodiscard]] const SpeechOptions& options() const { return options_; }

 private:
  SpeechOptions options_;
  std::vector<std::pair<std::string, SpeechPcm>> cache_;  // small, newest last
};

}  // namespace dynanav
