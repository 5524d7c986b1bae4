#include "mapping/map_keyframe.hpp"

#include <opencv2/imgproc.hpp>

namespace dynanav {

cv::Mat staticMask(const cv::Mat& labels_u16, const std::vector<uint16_t>& dynamic_ids,
                   int dilation_px) {
  cv::Mat dynamic = cv::Mat::zeros(labels_u16.size(), CV_8U);
  for (uint16_t id : dynamic_ids) dynamic.setTo(255, labels_u16 == id);
  if (dilation_px > 0 && !dynamic_ids.empty()) {
    const cv::Mat kernel = cv::getStructuringElement(
        cv::MORPH_ELLIPSE, cv::Size(2 * dilation_px + 1, 2 * dilation_px + 1));
    cv::dilate(dynamic, dynamic, kernel);
  }
  cv::Mat static_mask;
  cv::bitwise_not(dynamic, static_mask);
  return static_mask;
}

MapKeyframe keepKeyframe(double stamp_s, const cv::Mat& bgr, const cv::Mat& depth_m,
                         const cv::Mat& static_mask, int downscale, double max_depth_m) {
  MapKeyframe out;
  out.stamp_s = stamp_s;
  cv::Mat depth = depth_m.clone();
  // NaN, negative, too far or dynamic: all become 0 (invalid) before any resampling.
  cv::Mat bad = (depth != depth) | (depth <= 0.0f) | (depth > float(max_depth_m));
  if (!static_mask.empty()) bad |= static_mask == 0;
  depth.setTo(0.0f, bad);
  const int k = std::max(1, downscale);
  if (k == 1) {
    out.bgr = bgr.clone();
    out.depth_m = depth;
    return out;
  }
  const cv::Size small(bgr.cols / k, bgr.rows / k);
  cv::resize(bgr, out.bgr, small, 0, 0, cv::INTER_AREA);
  // Nearest sampling at each block's centre pixel (matches rayTable's pixel centres).
  out.depth_m.create(small, CV_32F);
  for (int y = 0; y < small.height; ++y) {
    const float* src = depth.ptr<float>(std::min(depth.rows - 1, y * k + k / 2));
    float* dst = out.depth_m.ptr<float>(y);
    for (int x = 0; x < small.width; ++x) dst[x] = src[std::min(depth.cols - 1, x * k + k / 2)];
  }
  return out;
}

cv::Mat rayTable(const PinholeCamera& camera, int downscale) {
  const int k = std::max(1, downscale);
  const int w = camera.width / k, h = camera.height / k;
  std::vector<cv::Point2f> pixels;
  pixels.reserve(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pixels.emplace_back(float(x * k + k / 2), float(y * k + k / 2));
  const std::vector<cv::Point2f> undistorted = camera.undistortPixels(pixels);
  cv::Mat rays(h, w, CV_32FC2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Point2f& u = undistorted[size_t(y) * size_t(w) + size_t(x)];
      rays.at<cv::Vec2f>(y, x) = {float((u.x - camera.cx) / camera.fx),
                                  float((u.y - camera.cy) / camera.fy)};
    }
  return rays;
}

}  // namespace dynanav
