#include "perception/detector.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "perception/model_files.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

std::vector<std::string> readNames(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) names.push_back(line);
  }
  if (names.empty()) throw InputError(file.string(), "no class names in file");
  return names;
}

}  // namespace

YoloDetector::YoloDetector(const fs::path& models_dir, const PerceptionConfig& config)
    : config_(config) {
  if (config.detector_input_px < 64 || config.detector_input_px % 32 != 0)
    throw InputError("perception.detector_input_px",
                     "must be a multiple of 32 and at least 64, got " +
                         std::to_string(config.detector_input_px));
  const fs::path cfg = requireModelFile(models_dir, model_files::kDetectorCfg);
  const fs::path weights = requireModelFile(models_dir, model_files::kDetectorWeights);
  names_ = readNames(requireModelFile(models_dir, model_files::kCocoNames));
  try {
    net_ = cv::dnn::readNetFromDarknet(cfg.string(), weights.string());
  } catch (const cv::Exception& e) {
    throw InputError(weights.string(), std::string("cannot load the detector: ") + e.what());
  }
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  output_names_ = net_.getUnconnectedOutLayersNames();
}

std::vector<Detection> YoloDetector::detect(const cv::Mat& bgr) {
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  const int side = config_.detector_input_px;
  // Same as blobFromImage's own 8-bit INTER_LINEAR resize; done here to reuse the buffer.
  cv::resize(bgr, resized_, cv::Size(side, side), 0, 0, cv::INTER_LINEAR);
  cv::dnn::blobFromImage(resized_, blob_, 1.0 / 255.0, cv::Size(), cv::Scalar(), true, false);
  net_.setInput(blob_);
  timing_.preprocess_ms = msSince(t0);

  t0 = Clock::now();
  std::vector<cv::Mat> outs;
  net_.forward(outs, output_names_);
  timing_.forward_ms = msSince(t0);

  t0 = Clock::now();
  // Rows: [cx, cy, w, h, objectness, 80 class scores], relative to the image (MODELS.md).
  std::vector<cv::Rect> boxes;
  std::vector<float> scores;
  std::vector<int> classes;
  const float min_score = float(config_.detector_min_score);
  for (const cv::Mat& out : outs) {
    for (int r = 0; r < out.rows; ++r) {
      const float* row = out.ptr<float>(r);
      if (row[4] < min_score) continue;  // class scores are <= objectness
      const float* cls = row + 5;
      const int n = std::min(out.cols - 5, int(names_.size()));
      const int best = int(std::max_element(cls, cls + n) - cls);
      if (cls[best] < min_score) continue;
      const float w = row[2] * float(bgr.cols), h = row[3] * float(bgr.rows);
      const float x = row[0] * float(bgr.cols) - 0.5f * w, y = row[1] * float(bgr.rows) - 0.5f * h;
      boxes.emplace_back(cvRound(x), cvRound(y), cvRound(w), cvRound(h));
      scores.push_back(cls[best]);
      classes.push_back(best);
    }
  }
  // Per-class NMS in one call: shifting each class to its own far-away region (OpenCV 4.6 has
  // no NMSBoxesBatched) keeps boxes of different classes from suppressing each other.
  std::vector<cv::Rect> shifted = boxes;
  const int offset = 4 * std::max(bgr.cols, bgr.rows);
  for (size_t i = 0; i < shifted.size(); ++i) shifted[i].x += classes[i] * offset;
  std::vector<int> keep;
  cv::dnn::NMSBoxes(shifted, scores, min_score, float(config_.detector_nms_iou), keep);

  std::vector<Detection> detections;
  const cv::Rect image(0, 0, bgr.cols, bgr.rows);
  for (int i : keep) {
    const cv::Rect box = boxes[size_t(i)] & image;
    if (box.area() <= 0 || box.height < config_.min_box_height_px) continue;
    detections.push_back({classes[size_t(i)], names_[size_t(classes[size_t(i)])], scores[size_t(i)],
                          box, std::nullopt});
  }
  std::sort(detections.begin(), detections.end(),
            [](const Detection& a, const Detection& b) { return a.score > b.score; });
  timing_.postprocess_ms = msSince(t0);
  return detections;
}

}  // namespace dynanav
