#pragma once
// Builds and writes the static map of a run (issue 15) from the kept keyframes and their final
// poses: map.ply (dense cloud), map.bt (OctoMap), occupancy.png (walking-height grid) and
// map_info.json (floor plane, grid geometry, sizes, build time).
#include <filesystem>
#include <memory>

#include "mapping/dense_cloud.hpp"
#include "mapping/floor_grid.hpp"
#include "mapping/octree_map.hpp"

namespace dynanav {

struct StaticMapOptions {
  double voxel_m = 0.01;
  int cloud_pixel_step = 1;
  OctreeOptions octree;
  /// Drop cloud points in cells the octree ends up seeing as free: what was there has gone
  /// (a moved box); people are already masked out.
  bool drop_points_in_free_space = true;
  double walk_min_height_m = 0.3, walk_max_height_m = 1.8;
  double grid_cell_m = 0.05;
};

struct StaticMap {
  ColouredCloud cloud;
  std::unique_ptr<octomap::ColorOcTree> tree;
  OccupancyGrid grid;  ///< empty cells when no floor was found
  size_t points_before_free_space_filter = 0;
  double cloud_ms = 0, octree_ms = 0, filter_ms = 0, grid_ms = 0;
};

/// `rays` from rayTable() at the keyframes' resolution. Keyframes in time order.
StaticMap buildStaticMap(const std::vector<PosedKeyframe>& keyframes, const cv::Mat& rays,
                         const StaticMapOptions& options);

/// Writes map.ply, map.bt, occupancy.png and map_info.json into out_dir.
void writeStaticMap(const std::filesystem::path& out_dir, const StaticMap& map);

}  // namespace dynanav
