#pragma once
// Where the mixed stream goes (issue 14): feedback.wav, and the default sound device with
// `--audio live`. Both get the same 16-bit stereo frames in stream order.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

struct sf_private_tag;
struct ALCdevice_struct;
struct ALCcontext_struct;

namespace dynanav {

class PcmSink {
 public:
  virtual ~PcmSink() = default;
  /// `frames` interleaved stereo frames (L R) at the stream's rate.
  virtual void write(const int16_t* interleaved, size_t frames) = 0;
  /// End of stream (the file is closed, the device drained).
  virtual void finish() = 0;
};

/// A 48 kHz 16-bit stereo WAV written with libsndfile. The header is rewritten after every
/// write (SFC_SET_UPDATE_HEADER_AUTO), so the file is playable at any moment: an interrupted or
/// killed run leaves a valid WAV of what was rendered.
class WavFileSink final : public PcmSink {
 public:
  /// InputError naming the file when it cannot be created.
  WavFileSink(std::filesystem::path path, int rate_hz);
  ~WavFileSink() override;
  void write(const int16_t* interleaved, size_t frames) override;
  void finish() override;

 private:
  std::filesystem::path path_;
  sf_private_tag* file_ = nullptr;
};

/// Plays the stream on the default OpenAL device through a queue of short buffers (the stream
/// is already binaural: no HRTF here, direct channels).
class LivePlayback final : public PcmSink {
 public:
  /// InputError when there is no device, naming what was tried and the devices OpenAL lists.
  LivePlayback(int rate_hz, double block_s);
  ~LivePlayback() override;
  void write(const int16_t* interleaved, size_t frames) override;
  void finish() override;
  /// Times the device ran dry and was restarted (the renderer fell behind).
  [[nodiscard]] size_t underruns() const { return underruns_; }
  [[nodiscard]] const std::string& deviceName() const { return device_name_; }

 private:
  void queueBlock();
  void makeCurrent() const;

  int rate_hz_;
  size_t block_frames_;
  ALCdevice_struct* device_ = nullptr;
  ALCcontext_struct* context_ = nullptr;
  unsigned source_ = 0;
  std::vector<unsigned> free_buffers_;
  std::vector<unsigned> all_buffers_;
  std::vector<int16_t> pending_;  // interleaved, less than one block
  size_t underruns_ = 0;
  bool started_ = false;
  std::string device_name_;
};

}  // namespace dynanav
