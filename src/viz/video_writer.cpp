#include "viz/video_writer.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <opencv2/imgproc.hpp>

namespace dynanav {

VideoOutput::VideoOutput(std::filesystem::path dir, std::string stem, double fps)
    : dir_(std::move(dir)), stem_(std::move(stem)), fps_(fps > 0 ? fps : 30.0) {}

bool VideoOutput::write(const cv::Mat& bgr) {
  if (!tried_) {
    tried_ = true;
    size_ = bgr.size();
    const struct {
      const char* fourcc;
      const char* ext;
    } choices[] = {{"avc1", ".mp4"}, {"mp4v", ".mp4"}, {"MJPG", ".avi"}};
    // x264's default preset costs more per frame than our tracking; "ultrafast" keeps the video
    // near the run-time budget on 2 cores, at a larger file (~2x). $OPENCV_FFMPEG_WRITER_OPTIONS,
    // when set by the user, wins.
    setenv("OPENCV_FFMPEG_WRITER_OPTIONS", "preset;ultrafast", /*overwrite=*/0);
    for (const auto& c : choices) {
      const std::filesystem::path path = dir_ / (stem_ + c.ext);
      writer_.open(path.string(),
                   cv::VideoWriter::fourcc(c.fourcc[0], c.fourcc[1], c.fourcc[2], c.fourcc[3]),
                   fps_, size_);
      if (writer_.isOpened()) {
        path_ = path;
        fourcc_ = c.fourcc;
        break;
      }
      std::error_code ec;
      std::filesystem::remove(path, ec);  // a failed open may leave an empty file behind
    }
    if (!writer_.isOpened()) spdlog::warn("no video encoder could be opened; no {} video", stem_);
  }
  if (!writer_.isOpened()) return false;
  if (bgr.size() == size_) {
    writer_.write(bgr);
  } else {
    cv::Mat resized;
    cv::resize(bgr, resized, size_);
    writer_.write(resized);
  }
  ++frames_;
  return true;
}

void VideoOutput::close() {
  writer_.release();
}

}  // namespace dynanav
