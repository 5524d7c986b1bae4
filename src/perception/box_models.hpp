#pragma once
// The two per-box networks (MODELS.md): MediaPipe selfie segmentation → a person mask in the
// box, and MoveNet Lightning → 17 body keypoints. Both read a square crop around the box,
// zero-padded where it leaves the image, taken by one affine warp (crop + pad + resize at once).
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include "core/config/perception.hpp"
#include "perception/instances.hpp"

namespace dynanav {

/// Where one per-box call spent its time (ms).
struct BoxModelTiming {
  double crop_ms = 0.0;     ///< warp to the network size + blob
  double forward_ms = 0.0;  ///< the network
  double decode_ms = 0.0;   ///< mapping the output back to the image
};

/// The square (side = scale × the box's longer side) centred on the box, in image pixels;
/// it may extend beyond the image.
cv::Rect2f squareAround(const cv::Rect& box, double scale);

/// `square` of `bgr` resampled to side×side pixels (zero outside the image).
cv::Mat warpSquare(const cv::Mat& bgr, const cv::Rect2f& square, int side);

class SelfieSegmenter {
 public:
  SelfieSegmenter(const std::filesystem::path& models_dir, const PerceptionConfig& config);
  /// CV_8U mask of the box's size: 255 where the model's person probability > threshold.
  cv::Mat maskInBox(const cv::Mat& bgr, const cv::Rect& box);
  [[nodiscard]] const BoxModelTiming& lastTiming() const { return timing_; }

 private:
  cv::dnn::Net net_;
  PerceptionConfig config_;
  BoxModelTiming timing_;
};

class KeypointDetector {
 public:
  KeypointDetector(const std::filesystem::path& models_dir, const PerceptionConfig& config);
  /// MoveNet's 17 keypoints for the person in `box`, in image pixels.
  BodyKeypoints detect(const cv::Mat& bgr, const cv::Rect& box);
  [[nodiscard]] const BoxModelTiming& lastTiming() const { return timing_; }

 private:
  cv::dnn::Net net_;
  std::vector<std::string> outputs_;
  PerceptionConfig config_;
  BoxModelTiming timing_;
};

/// MoveNet's single-pose decoding (what the graph's post-processing did before we cut it):
/// heat 1x17xHxW, centre 1x1xHxW, regress and offset 1x34xHxW (channel 2k = y, 2k+1 = x).
/// Keypoints in the crop's normalised coordinates (0..1), scores from the heatmaps.
BodyKeypoints decodeMoveNet(const cv::Mat& heat, const cv::Mat& centre, const cv::Mat& regress,
                            const cv::Mat& offset);

}  // namespace dynanav
