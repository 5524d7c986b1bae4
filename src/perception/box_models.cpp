#include "perception/box_models.hpp"

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

cv::dnn::Net loadTensorflow(const fs::path& file) {
  try {
    cv::dnn::Net net = cv::dnn::readNetFromTensorflow(file.string());
    net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
    net.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
    return net;
  } catch (const cv::Exception& e) {
    throw InputError(file.string(), std::string("cannot load the model: ") + e.what());
  }
}

/// Plane (y, x) of channel c of a 1xCxHxW blob.
cv::Mat plane(const cv::Mat& blob, int c) {
  return cv::Mat(blob.size[2], blob.size[3], CV_32F, const_cast<float*>(blob.ptr<float>(0, c)));
}

/// Argmax over the grid of value(y, x) / (distance to (ry, rx) + bias).
cv::Point argmaxWeighted(const cv::Mat& value, float ry, float rx, float bias) {
  float best = -1.f;
  cv::Point at(0, 0);
  for (int y = 0; y < value.rows; ++y) {
    const float* v = value.ptr<float>(y);
    for (int x = 0; x < value.cols; ++x) {
      const float d = std::hypot(float(y) - ry, float(x) - rx);
      const float s = v[x] / (d + bias);
      if (s > best) best = s, at = {x, y};
    }
  }
  return at;
}

}  // namespace

cv::Rect2f squareAround(const cv::Rect& box, double scale) {
  const float side = float(scale * std::max(box.width, box.height));
  const float cx = float(box.x) + 0.5f * float(box.width), cy = float(box.y) + 0.5f * float(box.height);
  return {cx - 0.5f * side, cy - 0.5f * side, side, side};
}

cv::Mat warpSquare(const cv::Mat& bgr, const cv::Rect2f& square, int side) {
  const double k = double(side) / square.width;
  // Pixel centres: crop pixel i covers image x = (i + 0.5) / k + square.x - 0.5.
  const cv::Matx23d A(k, 0, k * (0.5 - square.x) - 0.5, 0, k, k * (0.5 - square.y) - 0.5);
  cv::Mat out;
  cv::warpAffine(bgr, out, A, cv::Size(side, side), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar());
  return out;
}

SelfieSegmenter::SelfieSegmenter(const fs::path& models_dir, const PerceptionConfig& config)
    : net_(loadTensorflow(requireModelFile(models_dir, model_files::kSelfie))), config_(config) {}

cv::Mat SelfieSegmenter::maskInBox(const cv::Mat& bgr, const cv::Rect& box) {
  constexpr int kSide = 256;
  auto t0 = Clock::now();
  const cv::Rect2f square = squareAround(box, config_.selfie_crop_scale);
  const cv::Mat crop = warpSquare(bgr, square, kSide);
  net_.setInput(cv::dnn::blobFromImage(crop, 1.0 / 255.0, cv::Size(), cv::Scalar(), true, false));
  timing_.crop_ms = msSince(t0);

  t0 = Clock::now();
  const cv::Mat prob = net_.forward("activation_10");  // 1x1x256x256 sigmoid
  timing_.forward_ms = msSince(t0);

  t0 = Clock::now();
  const cv::Mat prob2d(kSide, kSide, CV_32F, const_cast<float*>(prob.ptr<float>()));
  // Box pixel u sits at k (u + 0.5 + box.x - square.x) - 0.5 in the crop (pixel centres).
  const double k = kSide / double(square.width);
  const cv::Matx23d to_crop(k, 0, k * (0.5 + box.x - square.x) - 0.5, 0, k,
                            k * (0.5 + box.y - square.y) - 0.5);
  cv::Mat prob_box, mask;
  cv::warpAffine(prob2d, prob_box, to_crop, box.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_CONSTANT, cv::Scalar());
  cv::compare(prob_box, config_.selfie_threshold, mask, cv::CMP_GT);
  timing_.decode_ms = msSince(t0);
  return mask;
}

KeypointDetector::KeypointDetector(const fs::path& models_dir, const PerceptionConfig& config)
    : net_(loadTensorflow(requireModelFile(models_dir, model_files::kMoveNet))), config_(config) {
  // OpenCV names a convolution+bias node "<node>/_base" (MODELS.md).
  const std::string p = "StatefulPartitionedCall/";
  outputs_ = {p + "Sigmoid", p + "Sigmoid_1", p + "kpt_regress_0/conv2d_6/BiasAdd/_base",
              p + "kpt_offset_0/conv2d_7/BiasAdd/_base"};
}

BodyKeypoints decodeMoveNet(const cv::Mat& heat, const cv::Mat& centre, const cv::Mat& regress,
                            const cv::Mat& offset) {
  const int h = heat.size[2], w = heat.size[3];
  const cv::Point c = argmaxWeighted(plane(centre, 0), 0.5f * float(h - 1), 0.5f * float(w - 1), 1.f);
  BodyKeypoints out;
  for (int k = 0; k < kBodyKeypointCount; ++k) {
    const float ry = float(c.y) + plane(regress, 2 * k).at<float>(c.y, c.x);
    const float rx = float(c.x) + plane(regress, 2 * k + 1).at<float>(c.y, c.x);
    const cv::Mat hk = plane(heat, k);
    const cv::Point p = argmaxWeighted(hk, ry, rx, 1.8f);
    const float oy = plane(offset, 2 * k).at<float>(p.y, p.x);
    const float ox = plane(offset, 2 * k + 1).at<float>(p.y, p.x);
    out.points[size_t(k)] = {{(float(p.x) + ox) / float(w), (float(p.y) + oy) / float(h)},
                             hk.at<float>(p.y, p.x)};
  }
  return out;
}

BodyKeypoints KeypointDetector::detect(const cv::Mat& bgr, const cv::Rect& box) {
  constexpr int kSide = 192;  // fixed: the graph adds 48x48 constants (another size fails to load)
  auto t0 = Clock::now();
  const cv::Rect2f square = squareAround(box, config_.keypoint_crop_scale);
  const cv::Mat crop = warpSquare(bgr, square, kSide);
  // MoveNet wants x/127.5 - 1 in RGB order.
  net_.setInput(cv::dnn::blobFromImage(crop, 1.0 / 127.5, cv::Size(), cv::Scalar(127.5, 127.5, 127.5),
                                       true, false));
  timing_.crop_ms = msSince(t0);

  t0 = Clock::now();
  std::vector<cv::Mat> outs;
  net_.forward(outs, outputs_);
  timing_.forward_ms = msSince(t0);

  t0 = Clock::now();
  BodyKeypoints keypoints = decodeMoveNet(outs[0], outs[1], outs[2], outs[3]);
  for (Keypoint& k : keypoints.points)
    k.pixel = {square.x + k.pixel.x * square.width, square.y + k.pixel.y * square.height};
  timing_.decode_ms = msSince(t0);
  return keypoints;
}

}  // namespace dynanav
