#pragma once
// A picture of the dense cloud for people to look at (README, docs): coloured point splats with
// a depth buffer, either straight down onto the floor plane or from an oblique viewpoint above
// and behind the scene. Points above `max_height_m` (the ceiling) are left out so the view
// reaches the floor.
#include <opencv2/core.hpp>
#include <string>

#include "mapping/dense_cloud.hpp"
#include "mapping/floor_grid.hpp"

namespace dynanav {

struct CloudView {
  std::string kind = "oblique";  ///< "top" (orthographic, from above) or "oblique"
  cv::Size size{960, 720};
  double max_height_m = 2.0;  ///< above the floor; higher points are not drawn
  double elevation_deg = 50;  ///< oblique: how far the view looks down
  double azimuth_deg = 0;     ///< oblique: 0 = looking along the first camera's forward axis
  int splat_px = 2;
};

/// Throws InputError for an unknown view kind. `floor` from estimateFloor (not found: world -y
/// is taken as up and no height cut is made).
cv::Mat renderCloud(const ColouredCloud& cloud, const FloorPlane& floor, const CloudView& view);

}  // namespace dynanav
