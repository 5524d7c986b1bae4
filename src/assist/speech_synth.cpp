#include "assist/speech_synth.hpp"

#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>

#include "core/error.hpp"

namespace dynanav {
namespace {

constexpr size_t kCacheEntries = 64;
/// Below this |sample| espeak-ng's output is silence (its noise floor is 0).
constexpr int kSilenceLevel = 64;
/// Kept around the voiced part so that soft onsets and endings are not cut.
constexpr double kSilenceMarginS = 0.02;

/// espeak-ng's engine: initialised once, used under one lock (it is not reentrant).
struct Engine {
  std::mutex mutex;
  int rate_hz = 0;
  std::string voice;
  int rate_wpm = 0;
  std::vector<int16_t>* target = nullptr;  // where the callback appends
};

Engine& engine() {
  static Engine e;
  return e;
}

int onSynth(short* wav, int count, espeak_EVENT*) {
  if (wav && count > 0 && engine().target)
    engine().target->insert(engine().target->end(), wav, wav + count);
  return 0;  // 0 = go on
}

/// Under the engine lock: initialises espeak-ng on first use and selects voice and rate.
void prepare(Engine& e, const SpeechOptions& options) {
  if (e.rate_hz == 0) {
    // Synchronous output: espeak_Synth returns when the callback has had every sample.
    const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, 0);
    if (rate <= 0)
      throw InputError("espeak-ng",
                       "cannot initialise (its voice data comes with the espeak-ng-data package; "
                       "scripts/setup.sh installs it)");
    espeak_SetSynthCallback(onSynth);
    e.rate_hz = rate;
  }
  if (e.voice != options.voice) {
    if (espeak_SetVoiceByName(options.voice.c_str()) != EE_OK)
      throw InputError("audio.voice", "espeak-ng has no voice '" + options.voice +
                                          "' (`espeak-ng --voices` lists them)");
    e.voice = options.voice;
    e.rate_wpm = 0;  // a new voice resets the rate
  }
  if (e.rate_wpm != options.rate_wpm) {
    espeak_SetParameter(espeakRATE, options.rate_wpm, 0);
    e.rate_wpm = options.rate_wpm;
  }
}

void trimSilence(SpeechPcm& pcm) {
  auto loud = [](int16_t s) { return std::abs(int(s)) >= kSilenceLevel; };
  const auto first = std::find_if(pcm.samples.begin(), pcm.samples.end(), loud);
  if (first == pcm.samples.end()) {
    pcm.samples.clear();
    return;
  }
  const auto last = std::find_if(pcm.samples.rbegin(), pcm.samples.rend(), loud).base();
  const auto margin = static_cast<std::ptrdiff_t>(kSilenceMarginS * pcm.rate_hz);
  const auto begin = first - std::min(margin, first - pcm.samples.begin());
  const auto end = last + std::min(margin, pcm.samples.end() - last);
  pcm.samples = std::vector<int16_t>(begin, end);
}

}  // namespace

std::string speechVoice(const std::string& configured, const std::string& language) {
  if (configured != "auto") return configured;
  if (language == "en" || language == "de") return language;
  throw InputError("audio.voice", "no voice for language '" + language +
                                      "'; name an espeak-ng voice instead of auto");
}

SpeechSynth::SpeechSynth(SpeechOptions options) : options_(std::move(options)) {
  Engine& e = engine();
  std::lock_guard lock(e.mutex);
  prepare(e, options_);  // fails here, before a run starts, for a bad voice or missing data
}

SpeechPcm SpeechSynth::speak(const std::string& text) {
  for (const auto& [cached_text, pcm] : cache_)
    if (cached_text == text) return pcm;
  if (cache_.size() >= kCacheEntries) cache_.erase(cache_.begin());
  SpeechPcm pcm;
  {
    Engine& e = engine();
    std::lock_guard lock(e.mutex);
    prepare(e, options_);
    pcm.rate_hz = e.rate_hz;
    e.target = &pcm.samples;
    espeak_Synth(text.c_str(), text.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr,
                 nullptr);
    e.target = nullptr;
  }
  trimSilence(pcm);
  cache_.emplace_back(text, std::move(pcm));
  return cache_.back().second;
}

}  // namespace dynanav
