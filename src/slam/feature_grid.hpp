#pragma once
// Spatial index of a frame's undistorted keypoints (ORB-SLAM2's 64x48 cell grid) so projection
// searches look only at keypoints near the predicted pixel.
#include <opencv2/core.hpp>
#include <vector>

namespace dynanav {

class FeatureGrid {
 public:
  static constexpr int kCols = 64;
  static constexpr int kRows = 48;

  FeatureGrid() = default;
  /// `bounds`: the undistorted image area (PinholeCamera::undistortedBounds()).
  FeatureGrid(const std::vector<cv::Point2f>& points, const cv::Rect2d& bounds);

  /// Indices of points within the square of half-size `radius` around (x, y) whose octave lies
  /// in [min_level, max_level] (a negative bound means "no limit").
  [[nodiscard]] std::vector<int> featuresInArea(float x, float y, float radius,
                                                const std::vector<cv::KeyPoint>& keypoints,
                                                const std::vector<cv::Point2f>& points,
                                                int min_level = -1, int max_level = -1) const;

 private:
  cv::Rect2d bounds_;
  float inv_cell_w_ = 0.f, inv_cell_h_ = 0.f;
  std::vector<std::vector<int>> cells_;  ///< row-major kRows x kCols
};

}  // namespace dynanav
