#pragma once
// Video files with the first encoder this build can open (issue 15): H.264 as fourcc 'avc1' in
// .mp4 through FFmpeg directly (viz/h264_file: libx264 with options we choose); MPEG-4 part 2
// ('mp4v', .mp4) through OpenCV's VideoWriter next; MJPG in .avi, OpenCV's own writer, always.
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

#include "viz/h264_file.hpp"

namespace dynanav {

/// `outputs.video_encoder_options` parsed; a ConfigError naming that key when it does not parse.
EncoderOptions videoEncoderOptions(const std::string& text);

class VideoOutput {
 public:
  /// Opens DIR/STEM.mp4 (H.264 with H264_OPTIONS, e.g. the parsed
  /// `outputs.video_encoder_options`; else MPEG-4) or DIR/STEM.avi (MJPG) on the first frame.
  VideoOutput(std::filesystem::path dir, std::string stem, double fps, EncoderOptions h264_options);
  ~VideoOutput();
  VideoOutput(const VideoOutput&) = delete;
  VideoOutput& operator=(const VideoOutput&) = delete;
  /// Writes a BGR frame; the first one fixes the size (later ones are resized to it). False when
  /// no encoder could be opened.
  bool write(const cv::Mat& bgr);
  void close();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }  ///< empty if none
  [[nodiscard]] const std::string& fourcc() const { return fourcc_; }
  [[nodiscard]] int frames() const { return frames_; }

 private:
  void openFirst(cv::Size size);

  std::filesystem::path dir_;
  std::string stem_;
  double fps_;
  EncoderOptions h264_options_;
  std::unique_ptr<H264File> h264_;
  cv::VideoWriter writer_;  ///< the fall-backs
  std::filesystem::path path_;
  std::string fourcc_;
  cv::Size size_;
  cv::Mat resized_;
  bool tried_ = false;
  int frames_ = 0;
};

}  // namespace dynanav
