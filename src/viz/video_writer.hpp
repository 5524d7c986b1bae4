#pragma once
// Video files from OpenCV's VideoWriter with the first encoder this build can open (issue 15).
// Debian 12's OpenCV (FFmpeg backend) opens H.264 as fourcc 'avc1' in .mp4 (libx264 or
// libopenh264); MPEG-4 part 2 ('mp4v') next; MJPG in .avi is OpenCV's own writer and always works.
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace dynanav {

class VideoOutput {
 public:
  /// Opens DIR/STEM.mp4 (H.264, else MPEG-4) or DIR/STEM.avi (MJPG) on the first frame written.
  VideoOutput(std::filesystem::path dir, std::string stem, double fps);
  /// Writes a BGR frame; the first one fixes the size (later ones are resized to it). False when
  /// no encoder could be opened.
  bool write(const cv::Mat& bgr);
  void close();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }  ///< empty if none
  [[nodiscard]] const std::string& fourcc() const { return fourcc_; }
  [[nodiscard]] int frames() const { return frames_; }

 private:
  std::filesystem::path dir_;
  std::string stem_;
  double fps_;
  cv::VideoWriter writer_;
  std::filesystem::path path_;
  std::string fourcc_;
  cv::Size size_;
  bool tried_ = false;
  int frames_ = 0;
};

}  // namespace dynanav
