#pragma once
// The per-keypoint measurements of one RGB-D image, shared by Frame and KeyFrame (data only).
// Per-keypoint flags leave room for later stages: `usable` is cleared for keypoints on moving
// objects (issue 7) so tracking and mapping skip them, `instance_id` says which object they lie on.
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.hpp"
#include "slam/feature_grid.hpp"
#include "slam/pyramid.hpp"

namespace dynanav {

struct Features {
  std::vector<cv::KeyPoint> keypoints;  ///< as extracted (distorted pixels, octave, angle)
  std::vector<cv::Point2f> points;      ///< undistorted pixel positions
  std::vector<float> depth_m;           ///< depth per keypoint, -1 if invalid
  std::vector<float> u_right;           ///< virtual right-image u = u - bf/z, -1 if no depth
  cv::Mat descriptors;                  ///< N x 32 CV_8U
  std::vector<uint8_t> usable;          ///< 1 = may be used for tracking/mapping (static)
  std::vector<uint16_t> instance_id;    ///< 0 = background
  /// Spread of each keypoint's position along its motion-blur streak (px, a standard deviation as
  /// a vector along the streak); empty when not known (slam/rolling_shutter.hpp:
  /// measureMotionBlur, slam/observation_noise.hpp).
  std::vector<cv::Point2f> blur_sigma_px;
  FeatureGrid grid;
  cv::Rect2d bounds;  ///< undistorted image area (ORB-SLAM2 mnMinX..mnMaxY)
  std::shared_ptr<const PinholeCamera> camera;
  std::shared_ptr<const PyramidScales> scales;

  [[nodiscard]] int size() const { return static_cast<int>(keypoints.size()); }
  [[nodiscard]] bool hasDepth(int i) const { return depth_m[i] > 0.f; }
  [[nodiscard]] bool inBounds(double u, double v) const {
    return u >= bounds.x && u <= bounds.x + bounds.width && v >= bounds.y &&
           v <= bounds.y + bounds.height;
  }
  /// Point in the camera frame from keypoint i's undistorted pixel and depth (needs depth).
  [[nodiscard]] Vec3 backproject(int i) const {
    return camera->backproject(points[i].x, points[i].y, depth_m[i]);
  }
  [[nodiscard]] std::vector<int> featuresInArea(float x, float y, float radius, int min_level = -1,
                                                int max_level = -1) const {
    return grid.featuresInArea(x, y, radius, keypoints, points, min_level, max_level);
  }
};

/// Builds Features from extracted keypoints: undistorts them, looks up depth at the distorted
/// pixel (depth is registered to the colour image), computes u_right, builds the grid.
Features makeFeatures(std::vector<cv::KeyPoint> keypoints, cv::Mat descriptors,
                      const cv::Mat& depth_m, double depth_max_m,
                      std::shared_ptr<const PinholeCamera> camera,
                      std::shared_ptr<const PyramidScales> scales);

/// Hamming distance of two 32-byte ORB descriptors.
int hammingDistance(const uint8_t* a, const uint8_t* b);
inline int descriptorRowDistance(const cv::Mat& a, int row_a, const cv::Mat& b, int row_b) {
  return hammingDistance(a.ptr<uint8_t>(row_a), b.ptr<uint8_t>(row_b));
}

}  // namespace dynanav
