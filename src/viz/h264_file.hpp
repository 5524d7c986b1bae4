#pragma once
// H.264 in .mp4 (fourcc avc1) written through FFmpeg's libavcodec/libavformat directly (issue 15).
// OpenCV 4.6's VideoWriter opens libx264 with its own defaults: preset "medium", three frame
// threads plus a lookahead thread, and it does not pass $OPENCV_FFMPEG_WRITER_OPTIONS to the
// encoder (x264's option string in the file shows "subme=7 ... threads=3" with or without it).
// That costs ~20 ms of CPU per 640x480 frame, more than the run's 15 % budget; here the encoder's
// options are ours to choose.
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dynanav {

/// Encoder options as (FFmpeg option name, value), e.g. {"preset", "ultrafast"}.
using EncoderOptions = std::vector<std::pair<std::string, std::string>>;

/// Parses "key=value,key=value" (spaces around items ignored; a value may hold '=' or ':', as
/// x264-params does). Throws std::invalid_argument on an item without '=' or with an empty key.
EncoderOptions parseEncoderOptions(std::string_view text);

class H264File {
 public:
  /// Opens PATH for frames of SIZE (BGR; an odd width or height loses its last column or row, as
  /// 4:2:0 needs even sizes). Null, with the reason in *error, when no H.264 encoder opens or
  /// when the encoder does not know one of OPTIONS (so a typo is not silently ignored).
  static std::unique_ptr<H264File> open(const std::filesystem::path& path, cv::Size size,
                                        double fps, const EncoderOptions& options,
                                        std::string* error);
  ~H264File();
  H264File(const H264File&) = delete;
  H264File& operator=(const H264File&) = delete;

  /// Encodes one 8-bit BGR frame of the size given to open(). False on an encoder error.
  bool write(const cv::Mat& bgr);
  /// Drains the encoder and writes the file's index (moov); the file plays only after this.
  void close();
  [[nodiscard]] const std::string& encoderName() const { return encoder_name_; }

 private:
  struct Impl;
  explicit H264File(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
  std::string encoder_name_;
};

}  // namespace dynanav
