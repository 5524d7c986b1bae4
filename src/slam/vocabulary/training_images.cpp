#include "slam/vocabulary/training_images.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/error.hpp"

namespace dynanav {
namespace fs = std::filesystem;
namespace {

std::string lowerExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool isImage(const fs::path& p) {
  static const std::vector<std::string> kExt = {".jpg", ".jpeg", ".png", ".bmp", ".pgm",
                                                ".ppm", ".tif", ".tiff", ".webp"};
  return std::find(kExt.begin(), kExt.end(), lowerExtension(p)) != kExt.end();
}

bool isVideo(const fs::path& p) {
  static const std::vector<std::string> kExt = {".avi", ".mp4", ".mkv", ".mov", ".webm",
                                                ".mpg", ".mpeg", ".m4v"};
  return std::find(kExt.begin(), kExt.end(), lowerExtension(p)) != kExt.end();
}

void addVideo(const fs::path& path, int step, std::vector<TrainingImage>& out) {
  cv::VideoCapture video(path.string());
  if (!video.isOpened()) throw InputError(path.string(), "cannot open the video");
  int frames = static_cast<int>(video.get(cv::CAP_PROP_FRAME_COUNT));
  if (frames <= 0) {  // some containers do not say: count by decoding
    frames = 0;
    while (video.grab()) ++frames;
  }
  for (int f = 0; f < frames; f += std::max(step, 1)) out.push_back({path, f});
}

cv::Mat fitCameraSize(const cv::Mat& gray) {
  const double scale = std::min({1.0, 640.0 / gray.cols, 480.0 / gray.rows});
  if (scale >= 1.0) return gray;
  cv::Mat small;
  cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
  return small;
}

}  // namespace

std::string TrainingImage::label() const {
  return frame < 0 ? path.string() : path.string() + "#" + std::to_string(frame);
}

std::vector<TrainingImage> listTrainingImages(const std::vector<std::string>& inputs,
                                              int video_frame_step) {
  std::vector<TrainingImage> out;
  for (const std::string& input : inputs) {
    const fs::path path(input);
    if (fs::is_directory(path)) {
      std::vector<fs::path> files;
      for (const auto& entry : fs::recursive_directory_iterator(path))
        if (entry.is_regular_file() && (isImage(entry.path()) || isVideo(entry.path())))
          files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        if (isVideo(f)) addVideo(f, video_frame_step, out);
        else out.push_back({f, -1});
      }
    } else if (fs::is_regular_file(path) && isVideo(path)) {
      addVideo(path, video_frame_step, out);
    } else if (fs::is_regular_file(path) && isImage(path)) {
      out.push_back({path, -1});
    } else if (!fs::exists(path)) {
      throw InputError(input, "no such file or folder");
    } else {
      throw InputError(input, "neither an image, a video nor a folder");
    }
  }
  return out;
}

std::vector<TrainingImage> thinEvenly(const std::vector<TrainingImage>& images, int max_images) {
  if (max_images <= 0 || images.size() <= static_cast<size_t>(max_images)) return images;
  std::vector<TrainingImage> kept;
  for (int i = 0; i < max_images; ++i)
    kept.push_back(images[static_cast<size_t>(i) * images.size() / static_cast<size_t>(max_images)]);
  return kept;
}

size_t forEachTrainingImage(const std::vector<TrainingImage>& images,
                            const std::function<void(const cv::Mat&, const TrainingImage&)>& use) {
  size_t used = 0;
  cv::VideoCapture video;
  fs::path open_video, failed_video;
  int next_frame = 0;  // index of the frame the next grab() returns
  cv::Mat image, gray;
  for (const TrainingImage& item : images) {
    if (item.frame < 0) {
      image = cv::imread(item.path.string(), cv::IMREAD_GRAYSCALE);
    } else {
      // Frames of one video come in increasing order: decode forward, reopen only on rewind.
      if (open_video != item.path || item.frame < next_frame) {
        video.open(item.path.string());
        open_video = item.path;
        next_frame = 0;
      }
      image.release();
      while (video.isOpened() && next_frame < item.frame && video.grab()) ++next_frame;
      if (next_frame == item.frame && video.read(image)) ++next_frame;
      if (!image.empty() && image.channels() == 3) cv::cvtColor(image, image, cv::COLOR_BGR2GRAY);
    }
    if (image.empty()) {
      // A video whose header promised more frames than it holds: say so once, not per frame.
      if (item.frame < 0 || item.path != failed_video)
        spdlog::warn("{}: cannot read{}", item.label(), item.frame < 0 ? ", skipped" : "; later frames skipped too");
      if (item.frame >= 0) failed_video = item.path;
      continue;
    }
    if (image.depth() != CV_8U) image.convertTo(image, CV_8U);
    gray = fitCameraSize(image);
    use(gray, item);
    ++used;
  }
  return used;
}

}  // namespace dynanav
