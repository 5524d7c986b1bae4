#include "perception/npm_detector.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "perception/model_files.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

using Clock = std::chrono::steady_clock;

/// Plane (y, x) of channel c of a 1xCxHxW blob.
cv::Mat plane(const cv::Mat& blob, int c) {
  return cv::Mat(blob.size[2], blob.size[3], CV_32F, const_cast<float*>(blob.ptr<float>(0, c)));
}

/// The cell of `heat` in rows [y0, y1) and columns [x0, x1) maximising heat / (distance to
/// (ry, rx) + 1.8), as MoveNet weighs keypoint candidates by their distance to the regression.
cv::Point bestKeypointCell(const cv::Mat& heat, cv::Range rows, cv::Range cols, float ry,
                           float rx) {
  float best = -1.f;
  cv::Point at(std::clamp(int(std::lround(rx)), 0, heat.cols - 1),
               std::clamp(int(std::lround(ry)), 0, heat.rows - 1));
  for (int y = rows.start; y < rows.end; ++y) {
    const float* v = heat.ptr<float>(y);
    for (int x = cols.start; x < cols.end; ++x) {
      const float s = v[x] / (std::hypot(float(y) - ry, float(x) - rx) + 1.8f);
      if (s > best) best = s, at = {x, y};
    }
  }
  return at;
}

}  // namespace

std::vector<Detection> decodeMultiPose(const MultiPoseHeads& heads, cv::Size image_size,
                                       float min_score, int max_people) {
  const cv::Mat centre = plane(heads.centre, 0);
  const int gh = centre.rows, gw = centre.cols;
  const float sx = float(image_size.width) / float(gw), sy = float(image_size.height) / float(gh);

  // Person centres: local maxima of the centre heatmap (the graph's 3x3 max-pool test).
  cv::Mat local_max;
  cv::dilate(centre, local_max, cv::Mat::ones(3, 3, CV_8U));
  std::vector<std::pair<float, cv::Point>> peaks;
  for (int y = 0; y < gh; ++y)
    for (int x = 0; x < gw; ++x) {
      const float v = centre.at<float>(y, x);
      if (v >= min_score && v >= local_max.at<float>(y, x)) peaks.push_back({v, {x, y}});
    }
  std::stable_sort(peaks.begin(), peaks.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (int(peaks.size()) > max_people) peaks.resize(size_t(max_people));

  const cv::Rect image(cv::Point(0, 0), image_size);
  std::vector<Detection> out;
  for (const auto& [score, c] : peaks) {
    // Box in grid cells (centre + sub-cell offset, size from the scale head).
    const float cy = float(c.y) + plane(heads.box_offset, 0).at<float>(c.y, c.x);
    const float cx = float(c.x) + plane(heads.box_offset, 1).at<float>(c.y, c.x);
    const float h = std::max(0.f, plane(heads.box_scale, 0).at<float>(c.y, c.x));
    const float w = std::max(0.f, plane(heads.box_scale, 1).at<float>(c.y, c.x));
    Detection d;
    d.class_id = 0;
    d.class_name = "person";
    d.score = score;
    d.box = cv::Rect(cvRound((cx - 0.5f * w) * sx), cvRound((cy - 0.5f * h) * sy), cvRound(w * sx),
                     cvRound(h * sy)) &
            image;
    if (d.box.area() == 0) continue;

    // Keypoints, searched inside the box (cells), as the graph's post-processing did.
    const cv::Range rows(std::clamp(int(std::floor(cy - 0.5f * h)), 0, gh - 1),
                         std::clamp(int(std::ceil(cy + 0.5f * h)), 1, gh));
    const cv::Range cols(std::clamp(int(std::floor(cx - 0.5f * w)), 0, gw - 1),
                         std::clamp(int(std::ceil(cx + 0.5f * w)), 1, gw));
    BodyKeypoints keypoints;
    for (int k = 0; k < kBodyKeypointCount; ++k) {
      const float ry = float(c.y) + plane(heads.regress, 2 * k).at<float>(c.y, c.x);
      const float rx = float(c.x) + plane(heads.regress, 2 * k + 1).at<float>(c.y, c.x);
      const cv::Mat hk = plane(heads.heat, k);
      const cv::Point p = bestKeypointCell(hk, rows, cols, ry, rx);
      const float oy = plane(heads.offset, 2 * k).at<float>(p.y, p.x);
      const float ox = plane(heads.offset, 2 * k + 1).at<float>(p.y, p.x);
      keypoints.points[size_t(k)] = {{(float(p.x) + ox) * sx, (float(p.y) + oy) * sy},
                                     hk.at<float>(p.y, p.x)};
    }
    d.keypoints = keypoints;
    out.push_back(std::move(d));
  }
  return out;
}

MultiPoseDetector::MultiPoseDetector(const fs::path& models_dir, const PerceptionConfig& config)
    : config_(config) {
  const fs::path file = requireModelFile(models_dir, model_files::kMultiPose);
  try {
    net_ = cv::dnn::readNetFromTensorflow(file.string());
  } catch (const cv::Exception& e) {
    throw InputError(file.string(), std::string("cannot load the detector: ") + e.what());
  }
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  // OpenCV names a convolution+bias node "<node>/_base" (tools/tfjs_to_pb).
  const std::string p = "StatefulPartitionedCall/";
  outputs_ = {p + "Sigmoid",
              p + "box_scale_0/conv2d_5/BiasAdd/_base",
              p + "box_offset_0/conv2d_6/BiasAdd/_base",
              p + "Sigmoid_1",
              p + "kpt_regress_0/conv2d_8/BiasAdd/_base",
              p + "kpt_offset_0/conv2d_9/BiasAdd/_base"};
}

cv::Size MultiPoseDetector::inputSize(cv::Size image) {
  const bool wide = image.width >= image.height;
  const double ratio = wide ? double(image.height) / std::max(1, image.width)
                            : double(image.width) / std::max(1, image.height);
  const int shorter = std::max(32, int(std::lround(ratio * kLongSide / 32.0)) * 32);
  return wide ? cv::Size(kLongSide, shorter) : cv::Size(shorter, kLongSide);
}

std::vector<Detection> MultiPoseDetector::detect(const cv::Mat& bgr) {
  auto t0 = Clock::now();
  cv::resize(bgr, resized_, inputSize(bgr.size()), 0, 0, cv::INTER_AREA);
  // MoveNet wants x/127.5 - 1 in RGB order.
  cv::dnn::blobFromImage(resized_, blob_, 1.0 / 127.5, cv::Size(), cv::Scalar(127.5, 127.5, 127.5),
                         true, false);
  net_.setInput(blob_);
  timing_.preprocess_ms = msSince(t0);

  t0 = Clock::now();
  std::vector<cv::Mat> outs;
  net_.forward(outs, outputs_);
  timing_.forward_ms = msSince(t0);

  t0 = Clock::now();
  const MultiPoseHeads heads{outs[0], outs[1], outs[2], outs[3], outs[4], outs[5]};
  std::vector<Detection> found =
      decodeMultiPose(heads, bgr.size(), float(config_.detector_min_score));
  // Two centre peaks on one person are rare; keep the better box as Yolo's NMS would.
  std::vector<cv::Rect> boxes;
  std::vector<float> scores;
  for (const Detection& d : found) boxes.push_back(d.box), scores.push_back(d.score);
  std::vector<int> keep;
  cv::dnn::NMSBoxes(boxes, scores, 0.f, float(config_.detector_nms_iou), keep);
  std::sort(keep.begin(), keep.end());  // found is already by decreasing score
  std::vector<Detection> out;
  for (int i : keep) out.push_back(std::move(found[size_t(i)]));
  timing_.postprocess_ms = msSince(t0);
  return out;
}

std::unique_ptr<ObjectDetector> makeObjectDetector(const fs::path& models_dir,
                                                   const PerceptionConfig& config) {
  std::error_code ec;
  if (fs::is_regular_file(models_dir / model_files::kDetectorCfg, ec) ||
      !fs::is_regular_file(models_dir / model_files::kMultiPose, ec))
    return std::make_unique<YoloDetector>(models_dir, config);  // names a missing Yolo file
  return std::make_unique<MultiPoseDetector>(models_dir, config);
}

}  // namespace dynanav
