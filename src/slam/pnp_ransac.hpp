#pragma once
// Camera pose from 3D-2D matches (relocalisation, ORB-SLAM2 §V-B): EPnP (Lepetit et al., IJCV
// 2009) inside RANSAC, through OpenCV's solvePnPRansac. Inputs are plain vectors so the solver is
// tested on synthetic scenes with a known pose.
#include <cstdint>
#include <vector>

#include "core/camera.hpp"
#include "core/se3.hpp"

namespace dynanav {

struct PnpRansacOptions {
  int iterations = 300;
  double reprojection_px = 5.991;  ///< inlier threshold (ORB-SLAM2 uses chi2(2) at level 0)
  int min_inliers = 10;
  uint64_t seed = 1;  ///< OpenCV's RNG is seeded with it: same input, same answer
};

struct PnpRansacResult {
  bool ok = false;
  SE3 T_camera_world = SE3::Identity();
  std::vector<uint8_t> inlier;  ///< per match
  int inliers = 0;
};

/// `pixels` are undistorted; the camera's distortion is ignored.
PnpRansacResult solvePnpRansac(const std::vector<Vec3>& p_world,
                               const std::vector<Eigen::Vector2d>& pixels,
                               const PinholeCamera& camera, const PnpRansacOptions& options = {});

}  // namespace dynanav
