#pragma once
// The binaural mix (issue 14): OpenAL-soft renders through its loopback device
// (ALC_SOFT_loopback), so the stream is computed sample by sample on our thread without a sound
// card, with its HRTF (ALC_SOFT_HRTF) placing each earcon at the object's direction. Speech is
// centred and bypasses the HRTF (AL_SOFT_direct_channels); OpenAL-soft's own resampler (the
// best of AL_SOFT_source_resampler's) brings espeak-ng's 22.05 kHz to the mix rate.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "assist/speech_synth.hpp"

struct ALCdevice_struct;
struct ALCcontext_struct;

namespace dynanav {

/// One message's sound: the earcon at the object's place, then the speech.
struct MessageSound {
  std::vector<float> earcon;     ///< mono at the mix rate
  SpeechPcm speech;              ///< mono at espeak-ng's rate
  double speech_offset_s = 0.0;  ///< speech starts this long after the earcon
  double bearing_deg = 0.0;      ///< wearer's frame: 0 ahead, positive to the right
  double distance_m = 0.0;
  int mix_rate_hz = 48000;
  [[nodiscard]] double durationS() const;
};

struct MixerOptions {
  int rate_hz = 48000;
  bool hrtf = true;
  double speech_gain = 1.0;
};

/// One loopback device and context. Calls must not overlap (one thread at a time); each call
/// makes its context current for the calling thread only (ALC_EXT_thread_local_context), so the
/// mixer does not disturb other OpenAL users in the process.
class AudioMixer {
 public:
  /// InputError when OpenAL-soft offers no loopback device or not the 16-bit stereo format.
  explicit AudioMixer(MixerOptions options);
  ~AudioMixer();
  AudioMixer(const AudioMixer&) = delete;
  AudioMixer& operator=(const AudioMixer&) = delete;

  /// Starts `sound` at the next rendered sample, cutting the message still playing (if any).
  void play(const MessageSound& sound);
  /// The next `frames` stereo frames, interleaved L R, rounded to 16 bits, appended to `out`.
  void render(size_t frames, std::vector<int16_t>& out);

  [[nodiscard]] bool hrtfEnabled() const { return hrtf_enabled_; }
  [[nodiscard]] const std::string& hrtfName() const { return hrtf_name_; }
  [[nodiscard]] const std::string& resamplerName() const { return resampler_name_; }
  [[nodiscard]] int rateHz() const { return options_.rate_hz; }
  /// Clears the calling thread's OpenAL context (before a thread that used OpenAL ends).
  static void releaseThread();

 private:
  void setUp();  // HRTF status, resampler, sources
  void close();
  void makeCurrent() const;
  void stopAndRelease();

  MixerOptions options_;
  ALCdevice_struct* device_ = nullptr;
  ALCcontext_struct* context_ = nullptr;
  unsigned earcon_source_ = 0;
  unsigned speech_source_ = 0;
  unsigned earcon_buffer_ = 0;  // of the current message (0 = none)
  unsigned speech_buffer_ = 0;
  std::vector<float> mix_;  // one render call's float output
  int resampler_ = 0;
  bool hrtf_enabled_ = false;
  std::string hrtf_name_;
  std::string resampler_name_;
};

}  // namespace dynanav
