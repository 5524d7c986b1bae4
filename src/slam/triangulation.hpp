#pragma once
// New map points from keypoint matches between a new keyframe and its covisible neighbours
// (ORB-SLAM2 LocalMapping::CreateNewMapPoints for RGB-D): linear triangulation where the rays
// have more parallax than the depth sensor's virtual stereo, else back-projection of the
// measured depth; then depth-positivity, reprojection (chi2) and scale-consistency checks.
#include <vector>

#include "slam/keyframe.hpp"
#include "slam/map.hpp"

namespace dynanav {

std::vector<MapPointPtr> triangulateWithNeighbours(KeyFrame& keyframe, Map& map, int neighbours);

/// Linear (DLT) triangulation of one match from two poses and undistorted pixels, in normalised
/// coordinates (ORB-SLAM2 Triangulate). Returns false at infinity.
bool triangulateLinear(const Eigen::Vector2d& xn1, const Eigen::Vector2d& xn2, const SE3& T_c1w,
                       const SE3& T_c2w, Vec3& p_world);

}  // namespace dynanav
