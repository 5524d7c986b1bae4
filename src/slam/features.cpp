#include "slam/features.hpp"

#include <bit>
#include <cstring>

#include "core/frame.hpp"

namespace dynanav {

Features makeFeatures(std::vector<cv::KeyPoint> keypoints, cv::Mat descriptors,
                      const cv::Mat& depth_m, double depth_max_m,
                      std::shared_ptr<const PinholeCamera> camera,
                      std::shared_ptr<const PyramidScales> scales) {
  Features f;
  f.keypoints = std::move(keypoints);
  f.descriptors = std::move(descriptors);
  const int n = f.size();
  std::vector<cv::Point2f> distorted(n);
  for (int i = 0; i < n; ++i) distorted[i] = f.keypoints[i].pt;
  f.points = camera->undistortPixels(distorted);
  f.depth_m.assign(n, -1.f);
  f.u_right.assign(n, -1.f);
  const double bf = camera->bf();
  for (int i = 0; i < n; ++i) {
    // Depth is registered to the (distorted) colour image, so it is read at the raw pixel
    // (ORB-SLAM2 Frame::ComputeStereoFromRGBD).
    const int u = static_cast<int>(std::lround(f.keypoints[i].pt.x));
    const int v = static_cast<int>(std::lround(f.keypoints[i].pt.y));
    if (depth_m.empty() || u < 0 || v < 0 || u >= depth_m.cols || v >= depth_m.rows) continue;
    const float z = depth_m.at<float>(v, u);
    if (!validDepth(z) || z > depth_max_m) continue;
    f.depth_m[i] = z;
    f.u_right[i] = static_cast<float>(f.points[i].x - bf / z);
  }
  f.usable.assign(n, 1);
  f.instance_id.assign(n, 0);
  f.bounds = camera->undistortedBounds();
  f.grid = FeatureGrid(f.points, f.bounds);
  f.camera = std::move(camera);
  f.scales = std::move(scales);
  return f;
}

int hammingDistance(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int k = 0; k < 32; k += 8) {
    uint64_t x, y;
    std::memcpy(&x, a + k, 8);
    std::memcpy(&y, b + k, 8);
    d += std::popcount(x ^ y);
  }
  return d;
}

}  // namespace dynanav
