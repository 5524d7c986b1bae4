#pragma once
// Spatial index of a frame's undistorted keypoints (ORB-SLAM2's 64x48 cell grid) so projection
// searches look only at keypoints near the predicted pixel. Every keyframe keeps its grid for
// the life of the map, so the cells are one array of keypoint indices sorted by cell plus each
// cell's start in it (compressed rows), not a vector per cell: 3,072 vector headers and one
// small allocation per occupied cell came to about 100 KiB per keyframe, about as much as all
// of its other per-keypoint data.
#include <cstdint>
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
  /// Keypoint indices grouped by cell (row-major kRows x kCols), increasing within a cell.
  std::vector<int> cell_points_;
  /// Cell c holds cell_points_[cell_start_[c] .. cell_start_[c + 1]); empty when no grid.
  std::vector<uint32_t> cell_start_;
};

}  // namespace dynanav
