#pragma once
// COCO object detector: Yolo-Fastest-1.1-xl (Darknet) through OpenCV DNN (MODELS.md, yolo-fastest).
// The npm-only alternative, MoveNet MultiPose (people only), is in npm_detector.hpp.
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/config/perception.hpp"
#include "perception/instances.hpp"

namespace dynanav {

struct Detection {
  int class_id = 0;  ///< COCO index (0 = person)
  std::string class_name;
  float score = 0.f;  ///< class score (already includes objectness in Yolo's output)
  cv::Rect box;       ///< pixels, clipped to the image
  std::optional<BodyKeypoints> keypoints;  ///< set by detectors that also find body keypoints
};

/// Where one detect() call spent its time (ms): for bench/bench_perception.cpp.
struct DetectorTiming {
  double preprocess_ms = 0.0;   ///< resize + blob (scale, RGB swap, NCHW)
  double forward_ms = 0.0;      ///< the network
  double postprocess_ms = 0.0;  ///< decoding rows + NMS
};

/// What the dnn segmenter needs of a detector.
class ObjectDetector {
 public:
  virtual ~ObjectDetector() = default;
  /// Detections sorted by decreasing score, after non-maximum suppression.
  virtual std::vector<Detection> detect(const cv::Mat& bgr) = 0;
  [[nodiscard]] virtual const DetectorTiming& lastTiming() const = 0;
};

class YoloDetector final : public ObjectDetector {
 public:
  /// Loads cfg/weights/names from `models_dir` (InputError naming a missing file).
  YoloDetector(const std::filesystem::path& models_dir, const PerceptionConfig& config);

  /// Detections sorted by decreasing score, after per-class non-maximum suppression.
  std::vector<Detection> detect(const cv::Mat& bgr) override;

  [[nodiscard]] const DetectorTiming& lastTiming() const override { return timing_; }
  [[nodiscard]] const std::vector<std::string>& classNames() const { return names_; }

 private:
  cv::dnn::Net net_;
  std::vector<std::string> names_;
  std::vector<std::string> output_names_;
  PerceptionConfig config_;
  DetectorTiming timing_;
  cv::Mat resized_, blob_;  // reused buffers
};

/// Yolo-Fastest when its files are in `models_dir`, else MoveNet MultiPose (npm_detector.hpp).
std::unique_ptr<ObjectDetector> makeObjectDetector(const std::filesystem::path& models_dir,
                                                   const PerceptionConfig& config);

}  // namespace dynanav
