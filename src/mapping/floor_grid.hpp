#pragma once
// The floor and the walking-height occupancy grid (issue 15). The world frame is the first
// camera's (y down), not gravity-aligned, so the floor is found as a plane: the largest roughly
// horizontal plane well below the cameras, preferring the lowest of the large ones (a big table
// top is smaller than the floor, but may win against a half-seen floor).
#include <octomap/ColorOcTree.h>

#include <opencv2/core.hpp>
#include <vector>

#include "core/se3.hpp"
#include "mapping/dense_cloud.hpp"

namespace dynanav {

struct FloorPlane {
  bool found = false;
  Vec3 up = Vec3(0, -1, 0);  ///< unit normal, pointing from the floor to the cameras
  double offset_m = 0.0;     ///< height(p) = up . p + offset_m
  int inliers = 0;
  [[nodiscard]] double height(const Vec3& p_world) const { return up.dot(p_world) + offset_m; }
};

/// RANSAC on the cloud: planes within `max_tilt_deg` of the first camera's -y axis and at least
/// `min_camera_height_m` below every camera centre. Deterministic (fixed seed).
FloorPlane estimateFloor(const ColouredCloud& cloud, const std::vector<Vec3>& camera_centres,
                         double max_tilt_deg = 40.0, double min_camera_height_m = 0.5);

/// A 2D grid on the floor plane. Image axes: columns along the floor's projection of the first
/// camera's x (right), rows against its z (forward is up in the image).
struct OccupancyGrid {
  enum : uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };
  cv::Mat cells;  ///< CV_8U, one of the three values
  double cell_m = 0.05;
  FloorPlane floor;
  Vec3 right = Vec3::UnitX(), forward = Vec3::UnitZ();  ///< in-plane axes (world)
  double right0_m = 0.0, forward0_m = 0.0;  ///< plane coordinates of the top-left corner
  /// Pixel (column, row) of a world point projected onto the floor.
  [[nodiscard]] cv::Point2f pixel(const Vec3& p_world) const {
    return {float((right.dot(p_world) - right0_m) / cell_m),
            float((forward0_m - forward.dot(p_world)) / cell_m)};
  }
  /// Grey = unknown, white = free, black = occupied (what occupancy.png holds).
  [[nodiscard]] cv::Mat image() const;
};

/// Cells whose octree leaves lie between min and max height above the floor: occupied if any
/// occupied leaf projects into them, else free if any free leaf does, else unknown.
OccupancyGrid occupancyGrid(const octomap::ColorOcTree& tree, const FloorPlane& floor,
                            double min_height_m, double max_height_m, double cell_m);

}  // namespace dynanav
