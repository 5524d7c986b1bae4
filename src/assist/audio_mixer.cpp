#define AL_ALEXT_PROTOTYPES
#include "assist/audio_mixer.hpp"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace dynanav {
namespace {

// Distance cue: closer is louder (inverse distance, clamped), gently, so a far object is still
// heard: 1 m and nearer full level, 3 m half, 8 m and beyond a fifth.
constexpr float kReferenceDistanceM = 1.0f;
constexpr float kRolloff = 0.5f;
constexpr float kMaxDistanceM = 8.0f;
/// An object without a distance is placed this far, so that it still has a direction.
constexpr double kMinDistanceM = 0.5;

int16_t toPcm16(double v) {
  return static_cast<int16_t>(std::lround(std::clamp(v, -1.0, 1.0) * 32767.0));
}

}  // namespace

double MessageSound::durationS() const {
  return std::max(double(earcon.size()) / mix_rate_hz, speech_offset_s + speech.durationS());
}

AudioMixer::AudioMixer(MixerOptions options) : options_(options) {
  if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") ||
      !alcIsExtensionPresent(nullptr, "ALC_EXT_thread_local_context"))
    throw InputError("OpenAL",
                     "no ALC_SOFT_loopback or ALC_EXT_thread_local_context: the audio mix needs "
                     "OpenAL-soft");
  device_ = alcLoopbackOpenDeviceSOFT(nullptr);
  if (!device_) throw InputError("OpenAL", "cannot open a loopback device");
  // Float, rounded to 16 bits here: OpenAL-soft's own 16-bit output is dithered, and silence
  // between messages should be digital silence.
  if (!alcIsRenderFormatSupportedSOFT(device_, options_.rate_hz, ALC_STEREO_SOFT, ALC_FLOAT_SOFT)) {
    alcCloseDevice(device_);
    throw InputError("OpenAL", "the loopback device cannot render float stereo at " +
                                   std::to_string(options_.rate_hz) + " Hz");
  }
  const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                               ALC_STEREO_SOFT,
                               ALC_FORMAT_TYPE_SOFT,
                               ALC_FLOAT_SOFT,
                               ALC_FREQUENCY,
                               options_.rate_hz,
                               ALC_HRTF_SOFT,
                               options_.hrtf ? ALC_TRUE : ALC_FALSE,
                               0};
  context_ = alcCreateContext(device_, attributes);
  if (!context_) {
    alcCloseDevice(device_);
    throw InputError("OpenAL", "cannot create a context on the loopback device");
  }
  try {
    setUp();
  } catch (...) {
    close();
    throw;
  }
}

void AudioMixer::setUp() {
  makeCurrent();
  ALCint hrtf_status = ALC_HRTF_DISABLED_SOFT;
  alcGetIntegerv(device_, ALC_HRTF_STATUS_SOFT, 1, &hrtf_status);
  hrtf_enabled_ = hrtf_status == ALC_HRTF_ENABLED_SOFT;
  if (hrtf_enabled_) hrtf_name_ = alcGetString(device_, ALC_HRTF_SPECIFIER_SOFT);
  if (options_.hrtf && !hrtf_enabled_)
    spdlog::warn(
        "OpenAL-soft did not enable its HRTF (status {}): earcons are placed by plain stereo "
        "panning (the HRTF data comes with libopenal-data)",
        hrtf_status);
  // The highest-numbered resampler is OpenAL-soft's best (a long sinc in 1.19).
  const ALint resamplers = alGetInteger(AL_NUM_RESAMPLERS_SOFT);
  resampler_ = std::max(0, resamplers - 1);
  if (resamplers > 0) resampler_name_ = alGetStringiSOFT(AL_RESAMPLER_NAME_SOFT, resampler_);
  alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
  ALuint sources[2] = {0, 0};
  alGenSources(2, sources);
  earcon_source_ = sources[0];
  speech_source_ = sources[1];
  alSourcei(earcon_source_, AL_SOURCE_RELATIVE, AL_TRUE);  // positions in the wearer's frame
  alSourcef(earcon_source_, AL_REFERENCE_DISTANCE, kReferenceDistanceM);
  alSourcef(earcon_source_, AL_ROLLOFF_FACTOR, kRolloff);
  alSourcef(earcon_source_, AL_MAX_DISTANCE, kMaxDistanceM);
  alSourcei(speech_source_, AL_SOURCE_RELATIVE, AL_TRUE);
  alSourcei(speech_source_, AL_DIRECT_CHANNELS_SOFT, AL_TRUE);
  alSourcef(speech_source_, AL_ROLLOFF_FACTOR, 0.0f);
  if (resamplers > 0) alSourcei(speech_source_, AL_SOURCE_RESAMPLER_SOFT, resampler_);
  if (alGetError() != AL_NO_ERROR)
    throw InputError("OpenAL", "cannot set up the sources of the mix");
}

AudioMixer::~AudioMixer() {
  close();
}

void AudioMixer::close() {
  makeCurrent();
  if (earcon_source_) {
    stopAndRelease();
    const ALuint sources[2] = {earcon_source_, speech_source_};
    alDeleteSources(2, sources);
  }
  alcSetThreadContext(nullptr);
  alcDestroyContext(context_);
  alcCloseDevice(device_);
}

void AudioMixer::releaseThread() {
  alcSetThreadContext(nullptr);
}

void AudioMixer::makeCurrent() const {
  alcSetThreadContext(context_);
}

void AudioMixer::stopAndRelease() {
  const ALuint sources[2] = {earcon_source_, speech_source_};
  alSourceStopv(2, sources);
  alSourcei(earcon_source_, AL_BUFFER, 0);
  alSourcei(speech_source_, AL_BUFFER, 0);
  ALuint buffers[2] = {earcon_buffer_, speech_buffer_};
  for (ALuint b : buffers)
    if (b) alDeleteBuffers(1, &b);
  earcon_buffer_ = speech_buffer_ = 0;
}

void AudioMixer::play(const MessageSound& sound) {
  makeCurrent();
  stopAndRelease();
  // Earcon: mono, so the HRTF places it.
  std::vector<int16_t> earcon(sound.earcon.size());
  std::transform(sound.earcon.begin(), sound.earcon.end(), earcon.begin(),
                 [](float v) { return toPcm16(v); });
  // Speech: stereo (both channels the same) with direct channels, so it bypasses the HRTF and
  // sounds centred; leading silence makes it start speech_offset_s after the earcon, so both
  // sources start together.
  const int speech_rate = sound.speech.rate_hz > 0 ? sound.speech.rate_hz : sound.mix_rate_hz;
  const auto lead = static_cast<size_t>(std::lround(sound.speech_offset_s * speech_rate));
  std::vector<int16_t> speech(2 * (lead + sound.speech.samples.size()), 0);
  for (size_t i = 0; i < sound.speech.samples.size(); ++i)
    speech[2 * (lead + i)] = speech[2 * (lead + i) + 1] =
        toPcm16(options_.speech_gain * sound.speech.samples[i] / 32768.0);
  ALuint buffers[2] = {0, 0};
  alGenBuffers(2, buffers);
  earcon_buffer_ = buffers[0];
  speech_buffer_ = buffers[1];
  if (!earcon.empty())
    alBufferData(earcon_buffer_, AL_FORMAT_MONO16, earcon.data(),
                 ALsizei(earcon.size() * sizeof(int16_t)), sound.mix_rate_hz);
  if (!speech.empty())
    alBufferData(speech_buffer_, AL_FORMAT_STEREO16, speech.data(),
                 ALsizei(speech.size() * sizeof(int16_t)), speech_rate);
  // OpenAL's frame: x right, y up, z backwards (the listener looks along -z).
  const double distance_m = std::max(kMinDistanceM, sound.distance_m);
  const double bearing_rad = sound.bearing_deg * std::numbers::pi / 180.0;
  alSource3f(earcon_source_, AL_POSITION, float(distance_m * std::sin(bearing_rad)), 0.0f,
             float(-distance_m * std::cos(bearing_rad)));
  std::vector<ALuint> start;
  if (!earcon.empty()) {
    alSourcei(earcon_source_, AL_BUFFER, ALint(earcon_buffer_));
    start.push_back(earcon_source_);
  }
  if (!speech.empty()) {
    alSourcei(speech_source_, AL_BUFFER, ALint(speech_buffer_));
    start.push_back(speech_source_);
  }
  if (!start.empty()) alSourcePlayv(ALsizei(start.size()), start.data());  // same sample
  if (const ALenum error = alGetError(); error != AL_NO_ERROR)
    spdlog::warn("OpenAL error {:#x} while starting a message", error);
}

void AudioMixer::render(size_t frames, std::vector<int16_t>& out) {
  if (frames == 0) return;
  makeCurrent();
  mix_.resize(2 * frames);
  alcRenderSamplesSOFT(device_, mix_.data(), ALCsizei(frames));
  out.reserve(out.size() + mix_.size());
  for (float v : mix_) out.push_back(toPcm16(v));
}

}  // namespace dynanav
