#pragma once
// topview.png (issue 15, like the paper's Fig. 2e): the walking-height occupancy grid with the
// wearer's path and each tracked object's path drawn over it, one colour per object id.
#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "core/se3.hpp"
#include "mapping/floor_grid.hpp"

namespace dynanav {

struct ObjectPath {
  std::string class_name;
  std::vector<Vec3> p_world;  ///< in time order
};

/// `scale_px` image pixels per grid cell. Paths outside the grid are clipped.
cv::Mat drawTopView(const OccupancyGrid& grid, const std::vector<Vec3>& wearer_path_world,
                    const std::map<uint64_t, ObjectPath>& objects, int scale_px = 4);

}  // namespace dynanav
