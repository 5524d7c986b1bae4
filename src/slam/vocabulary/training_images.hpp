#pragma once
// The images a vocabulary is trained on: image files, folders of them, and frames sampled from
// video files. Listing is separate from reading so that `--max-images` can thin the list evenly
// before anything is decoded.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace dynanav {

struct TrainingImage {
  std::filesystem::path path;
  int frame = -1;  // frame index for a video; -1 for an image file
  [[nodiscard]] std::string label() const;
};

/// Expands `inputs` (image files, video files, folders searched recursively), in sorted path
/// order; a video contributes every `video_frame_step`-th frame. Throws InputError for an input
/// that does not exist or is neither an image, a video nor a folder.
std::vector<TrainingImage> listTrainingImages(const std::vector<std::string>& inputs,
                                              int video_frame_step);

/// At most `max_images`, evenly spaced over the list (all of them when max_images <= 0).
std::vector<TrainingImage> thinEvenly(const std::vector<TrainingImage>& images, int max_images);

/// Reads each image as 8-bit grey, scaled down to fit 640 x 480 (the camera resolution the
/// vocabulary serves, so feature scales match), and hands it to `use`. Unreadable entries are
/// skipped with a warning; returns how many were used.
size_t forEachTrainingImage(const std::vector<TrainingImage>& images,
                            const std::function<void(const cv::Mat& gray, const TrainingImage&)>& use);

}  // namespace dynanav
