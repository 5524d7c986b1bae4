#include "slam/feature_grid.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {

FeatureGrid::FeatureGrid(const std::vector<cv::Point2f>& points, const cv::Rect2d& bounds)
    : bounds_(bounds),
      inv_cell_w_(static_cast<float>(kCols / bounds.width)),
      inv_cell_h_(static_cast<float>(kRows / bounds.height)),
      cell_start_(kRows * kCols + 1, 0) {
  // Counting sort by cell: count, prefix-sum into starts, place (indices stay increasing).
  const int n = static_cast<int>(points.size());
  std::vector<int> cell_of(n, -1);
  for (int i = 0; i < n; ++i) {
    const int cx = static_cast<int>(std::round((points[i].x - bounds_.x) * inv_cell_w_));
    const int cy = static_cast<int>(std::round((points[i].y - bounds_.y) * inv_cell_h_));
    if (cx < 0 || cx >= kCols || cy < 0 || cy >= kRows) continue;  // outside the undistorted area
    cell_of[i] = cy * kCols + cx;
    ++cell_start_[cell_of[i] + 1];
  }
  for (int c = 0; c < kRows * kCols; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_points_.resize(cell_start_.back());
  std::vector<uint32_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i) {
    if (cell_of[i] >= 0) cell_points_[next[cell_of[i]]++] = i;
  }
}

std::vector<int> FeatureGrid::featuresInArea(float x, float y, float radius,
                                             const std::vector<cv::KeyPoint>& keypoints,
                                             const std::vector<cv::Point2f>& points, int min_level,
                                             int max_level) const {
  std::vector<int> out;
  if (cell_start_.empty()) return out;
  const int min_cx =
      std::max(0, static_cast<int>(std::floor((x - bounds_.x - radius) * inv_cell_w_)));
  const int max_cx =
      std::min(kCols - 1, static_cast<int>(std::ceil((x - bounds_.x + radius) * inv_cell_w_)));
  const int min_cy =
      std::max(0, static_cast<int>(std::floor((y - bounds_.y - radius) * inv_cell_h_)));
  const int max_cy =
      std::min(kRows - 1, static_cast<int>(std::ceil((y - bounds_.y + radius) * inv_cell_h_)));
  if (min_cx >= kCols || max_cx < 0 || min_cy >= kRows || max_cy < 0) return out;
  for (int cy = min_cy; cy <= max_cy; ++cy) {
    for (int cx = min_cx; cx <= max_cx; ++cx) {
      const int cell = cy * kCols + cx;
      for (uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const int i = cell_points_[k];
        const int octave = keypoints[i].octave;
        if (min_level >= 0 && octave < min_level) continue;
        if (max_level >= 0 && octave > max_level) continue;
        if (std::abs(points[i].x - x) < radius && std::abs(points[i].y - y) < radius)
          out.push_back(i);
      }
    }
  }
  return out;
}

}  // namespace dynanav
