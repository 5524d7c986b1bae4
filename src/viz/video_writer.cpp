#include "viz/video_writer.hpp"

#include <spdlog/spdlog.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "core/error.hpp"

namespace dynanav {

EncoderOptions videoEncoderOptions(const std::string& text) {
  try {
    return parseEncoderOptions(text);
  } catch (const std::invalid_argument& e) {
    throw ConfigError("outputs.video_encoder_options", e.what());
  }
}

VideoOutput::VideoOutput(std::filesystem::path dir, std::string stem, double fps,
                         EncoderOptions h264_options)
    : dir_(std::move(dir)),
      stem_(std::move(stem)),
      fps_(fps > 0 ? fps : 30.0),
      h264_options_(std::move(h264_options)) {}

VideoOutput::~VideoOutput() {
  close();
}

void VideoOutput::openFirst(cv::Size size) {
  size_ = size;
  const std::filesystem::path mp4 = dir_ / (stem_ + ".mp4");
  std::string why;
  h264_ = H264File::open(mp4, size_, fps_, h264_options_, &why);
  if (h264_) {
    path_ = mp4;
    fourcc_ = "avc1";
    return;
  }
  spdlog::warn("{}: no H.264 ({}); trying OpenCV's encoders", stem_, why);
  const struct {
    const char* fourcc;
    const char* ext;
  } fallbacks[] = {{"mp4v", ".mp4"}, {"MJPG", ".avi"}};
  for (const auto& c : fallbacks) {
    const std::filesystem::path path = dir_ / (stem_ + c.ext);
    writer_.open(path.string(),
                 cv::VideoWriter::fourcc(c.fourcc[0], c.fourcc[1], c.fourcc[2], c.fourcc[3]), fps_,
                 size_);
    if (writer_.isOpened()) {
      path_ = path;
      fourcc_ = c.fourcc;
      return;
    }
    std::error_code ec;
    std::filesystem::remove(path, ec);  // a failed open may leave an empty file behind
  }
  spdlog::warn("no video encoder could be opened; no {} video", stem_);
}

bool VideoOutput::write(const cv::Mat& bgr) {
  if (!tried_) {
    tried_ = true;
    openFirst(bgr.size());
  }
  if (!h264_ && !writer_.isOpened()) return false;
  const cv::Mat* frame = &bgr;
  if (bgr.size() != size_) {
    cv::resize(bgr, resized_, size_);
    frame = &resized_;
  }
  if (h264_) {
    if (!h264_->write(*frame)) return false;
  } else {
    writer_.write(*frame);
  }
  ++frames_;
  return true;
}

void VideoOutput::close() {
  if (h264_) h264_->close();
  writer_.release();
}

}  // namespace dynanav
