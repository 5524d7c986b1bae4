#include "slam/feature_grid.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {

FeatureGrid::FeatureGrid(const std::vector<cv::Point2f>& points, const cv::Rect2d& bounds)
    : bounds_(bounds),
      inv_cell_w_(static_cast<float>(kCols / bounds.width)),
      inv_cell_h_(static_cast<float>(kRows / bounds.height)),
      cells_(kRows * kCols) {
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const int cx = static_cast<int>(std::round((points[i].x - bounds_.x) * inv_cell_w_));
    const int cy = static_cast<int>(std::round((points[i].y - bounds_.y) * inv_cell_h_));
    if (cx < 0 || cx >= kCols || cy < 0 || cy >= kRows) continue;  // outside the undistorted area
    cells_[cy * kCols + cx].push_back(i);
  }
}

std::vector<int> FeatureGrid::featuresInArea(float x, float y, float radius,
                                             const std::vector<cv::KeyPoint>& keypoints,
                                             const std::vector<cv::Point2f>& points,
                                             int min_level, int max_level) const {
  std::vector<int> out;
  if (cells_.empty()) return out;
  const int min_cx = std::max(0, static_cast<int>(std::floor((x - bounds_.x - radius) * inv_cell_w_)));
  const int max_cx = std::min(kCols - 1, static_cast<int>(std::ceil((x - bounds_.x + radius) * inv_cell_w_)));
  const int min_cy = std::max(0, static_cast<int>(std::floor((y - bounds_.y - radius) * inv_cell_h_)));
  const int max_cy = std::min(kRows - 1, static_cast<int>(std::ceil((y - bounds_.y + radius) * inv_cell_h_)));
  if (min_cx >= kCols || max_cx < 0 || min_cy >= kRows || max_cy < 0) return out;
  for (int cy = min_cy; cy <= max_cy; ++cy) {
    for (int cx = min_cx; cx <= max_cx; ++cx) {
      for (const int i : cells_[cy * kCols + cx]) {
        const int octave = keypoints[i].octave;
        if (min_level >= 0 && octave < min_level) continue;
        if (max_level >= 0 && octave > max_level) continue;
        if (std::abs(points[i].x - x) < radius && std::abs(points[i].y - y) < radius) out.push_back(i);
      }
    }
  }
  return out;
}

}  // namespace dynanav
