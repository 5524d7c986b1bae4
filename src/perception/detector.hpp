#pragma once
// COCO object detector: Yolo-Fastest-1.1-xl (Darknet) through OpenCV DNN (MODELS.md, yolo-fastest).
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <string>
#include <vector>

#include "core/config/perception.hpp"

namespace dynanav {

struct Detection {
  int class_id = 0;  ///< COCO index (0 = person)
  std::string class_name;
  float score = 0.f;  ///< class score (already includes objectness in Yolo's output)
  cv::Rect box;       ///< pixels, clipped to the image
};

/// Where one detect() call spent its time (ms): for bench/bench_perception.cpp.
struct DetectorTiming {
  double preprocess_ms = 0.0;   ///< resize + blob (scale, RGB swap, NCHW)
  double forward_ms = 0.0;      ///< the network
  double postprocess_ms = 0.0;  ///< decoding rows + NMS
};

class YoloDetector {
 public:
  /// Loads cfg/weights/names from `models_dir` (InputError naming a missing file).
  YoloDetector(const std::filesystem::path& models_dir, const PerceptionConfig& config);

  /// Detections sorted by decreasing score, after per-class non-maximum suppression.
  std::vector<Detection> detect(const cv::Mat& bgr);

  [[nodiscard]] const DetectorTiming& lastTiming() const { return timing_; }
  [[nodiscard]] const std::vector<std::string>& classNames() const { return names_; }

 private:
  cv::dnn::Net net_;
  std::vector<std::string> names_;
  std::vector<std::string> output_names_;
  PerceptionConfig config_;
  DetectorTiming timing_;
  cv::Mat resized_, blob_;  // reused buffers
};

}  // namespace dynanav
