#define AL_ALEXT_PROTOTYPES
#include "assist/audio_sinks.hpp"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>
#include <sndfile.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

#include "core/error.hpp"

namespace dynanav {

WavFileSink::WavFileSink(std::filesystem::path path, int rate_hz) : path_(std::move(path)) {
  SF_INFO info{};
  info.samplerate = rate_hz;
  info.channels = 2;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  file_ = sf_open(path_.c_str(), SFM_WRITE, &info);
  if (!file_)
    throw InputError(path_.string(), std::string("cannot write: ") + sf_strerror(nullptr));
  sf_command(file_, SFC_SET_UPDATE_HEADER_AUTO, nullptr, SF_TRUE);
}

WavFileSink::~WavFileSink() {
  finish();
}

void WavFileSink::write(const int16_t* interleaved, size_t frames) {
  if (!file_ || frames == 0) return;
  const sf_count_t written = sf_writef_short(file_, interleaved, sf_count_t(frames));
  if (written != sf_count_t(frames))
    throw InputError(path_.string(), std::string("cannot write: ") + sf_strerror(file_));
}

void WavFileSink::finish() {
  if (!file_) return;
  sf_close(file_);
  file_ = nullptr;
}

namespace {

/// The devices OpenAL lists, for the message when none opens.
std::string listedDevices() {
  const char* list = alcIsExtensionPresent(nullptr, "ALC_ENUMERATE_ALL_EXT")
                         ? alcGetString(nullptr, ALC_ALL_DEVICES_SPECIFIER)
                         : alcGetString(nullptr, ALC_DEVICE_SPECIFIER);
  std::string names;
  for (const char* p = list; p && *p; p += std::strlen(p) + 1)
    names += (names.empty() ? "'" : ", '") + std::string(p) + "'";
  return names.empty() ? "none" : names;
}

constexpr size_t kQueuedBlocks = 4;

}  // namespace

LivePlayback::LivePlayback(int rate_hz, double block_s)
    : rate_hz_(rate_hz),
      block_frames_(std::max<size_t>(64, size_t(std::lround(block_s * rate_hz)))) {
  const char* default_name = alcGetString(nullptr, ALC_DEFAULT_DEVICE_SPECIFIER);
  device_ = alcOpenDevice(nullptr);
  if (!device_)
    throw InputError("--audio live",
                     "no sound device: OpenAL-soft could not open its default output device '" +
                         std::string(default_name ? default_name : "") + "' (devices it lists: " +
                         listedDevices() + "); use --audio to write feedback.wav instead");
  const ALCint attributes[] = {ALC_FREQUENCY, rate_hz_, ALC_HRTF_SOFT, ALC_FALSE, 0};
  context_ = alcCreateContext(device_, attributes);
  if (!context_) {
    alcCloseDevice(device_);
    throw InputError("--audio live", "cannot create an OpenAL context on the default device");
  }
  device_name_ = alcGetString(device_, ALC_DEVICE_SPECIFIER);
  makeCurrent();
  alGenSources(1, &source_);
  alSourcei(source_, AL_SOURCE_RELATIVE, AL_TRUE);
  alSourcei(source_, AL_DIRECT_CHANNELS_SOFT, AL_TRUE);
  alSourcef(source_, AL_ROLLOFF_FACTOR, 0.0f);
  spdlog::info("--audio live: playing on '{}'", device_name_);
}

LivePlayback::~LivePlayback() {
  makeCurrent();
  alSourceStop(source_);
  alSourcei(source_, AL_BUFFER, 0);
  alDeleteSources(1, &source_);
  for (ALuint b : all_buffers_) alDeleteBuffers(1, &b);
  alcSetThreadContext(nullptr);
  alcDestroyContext(context_);
  alcCloseDevice(device_);
}

void LivePlayback::makeCurrent() const {
  alcSetThreadContext(context_);
}

void LivePlayback::queueBlock() {
  ALint processed = 0;
  alGetSourcei(source_, AL_BUFFERS_PROCESSED, &processed);
  while (processed-- > 0) {
    ALuint b = 0;
    alSourceUnqueueBuffers(source_, 1, &b);
    free_buffers_.push_back(b);
  }
  ALuint buffer = 0;
  if (free_buffers_.empty()) {  // the device is slower than the clock: one more buffer
    alGenBuffers(1, &buffer);
    all_buffers_.push_back(buffer);
  } else {
    buffer = free_buffers_.back();
    free_buffers_.pop_back();
  }
  alBufferData(buffer, AL_FORMAT_STEREO16, pending_.data(),
               ALsizei(pending_.size() * sizeof(int16_t)), rate_hz_);
  alSourceQueueBuffers(source_, 1, &buffer);
  pending_.clear();
  ALint state = AL_STOPPED;
  alGetSourcei(source_, AL_SOURCE_STATE, &state);
  ALint queued = 0;
  alGetSourcei(source_, AL_BUFFERS_QUEUED, &queued);
  // Start once a few blocks are queued; a stopped source after that is an underrun.
  if (state != AL_PLAYING && (started_ || queued >= ALint(kQueuedBlocks))) {
    if (started_) ++underruns_;
    alSourcePlay(source_);
    started_ = true;
  }
}

void LivePlayback::write(const int16_t* interleaved, size_t frames) {
  makeCurrent();
  for (size_t i = 0; i < frames; ++i) {
    pending_.push_back(interleaved[2 * i]);
    pending_.push_back(interleaved[2 * i + 1]);
    if (pending_.size() == 2 * block_frames_) queueBlock();
  }
}

void LivePlayback::finish() {
  makeCurrent();
  if (!pending_.empty()) queueBlock();
  if (!started_) {
    alSourcePlay(source_);
    started_ = true;
  }
  // Let what is queued play out (at most a few blocks), then stop.
  ALint queued = 0;
  alGetSourcei(source_, AL_BUFFERS_QUEUED, &queued);
  std::this_thread::sleep_for(
      std::chrono::duration<double>(double(queued) * double(block_frames_) / double(rate_hz_)));
}

}  // namespace dynanav
