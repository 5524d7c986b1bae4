#pragma once
// Rigid motion of one object between two frames from its points (VDO-SLAM, Zhang et al. 2020,
// §III-B as the paper uses it): previous-frame 3D points in the world, their pixels in the
// current frame (carried by dense flow) and the current camera pose. The motion H_world maps the
// object's points of the previous frame onto those of this one (p_cur = H p_prev, world frame),
// so the current camera sees p_prev through T_camera_world * H: a PnP problem. EPnP in RANSAC
// (OpenCV) is tried against the previous motion used as a prior; the one with more inliers is
// kept and refined in Ceres on a robust (Huber) reprojection error. The velocity of the object's
// centroid c follows from H = (R, t): c' - c = t - (I - R) c.
#include <cstdint>
#include <vector>

#include "core/camera.hpp"
#include "core/se3.hpp"

namespace dynanav {

struct ObjectMotionOptions {
  int ransac_iterations = 100;
  double reprojection_px = 2.0;  ///< inlier threshold
  double huber_px = 1.0;         ///< robust-loss scale of the refinement
  int refine_iterations = 10;
  int min_points = 12;
  uint64_t seed = 1;  ///< RANSAC's sampler (cv::theRNG) is seeded with it
};

struct ObjectMotion {
  bool ok = false;
  SE3 H_world = SE3::Identity();  ///< previous-frame object points -> this frame's (world)
  std::vector<uint8_t> inlier;    ///< per correspondence
  int inliers = 0;
  bool from_prior = false;  ///< the prior beat EPnP-RANSAC
};

/// `p_prev_world[i]` is seen at `pixels[i]` (undistorted, this frame) by a camera at
/// T_camera_world; `prior` is the previous frame's motion (identity for a new track).
/// `depth_m[i]` (optional; 0 = none) is the depth measured there: the refinement then also
/// fits it (weighted by the structured-light noise 0.01 + 0.003 z^2 m per pixel of error), which
/// pins the motion along the line of sight that reprojection of a small, far object leaves loose.
ObjectMotion estimateObjectMotion(const std::vector<Vec3>& p_prev_world,
                                  const std::vector<Eigen::Vector2d>& pixels,
                                  const SE3& T_camera_world, const PinholeCamera& camera,
                                  const SE3& prior, const ObjectMotionOptions& options,
                                  const std::vector<double>& depth_m = {});

/// Displacement of the point c under H: t - (I - R) c (= H c - c).
Vec3 centroidDisplacement(const SE3& H_world, const Vec3& c_world);

/// The velocity (m/s, world) of the centroid of `motion`'s inliers among `p_prev_world` (the
/// points it was estimated from) over dt_s: the object's measured velocity. Needs motion.ok.
Vec3 inlierCentroidVelocity(const ObjectMotion& motion, const std::vector<Vec3>& p_prev_world,
                            double dt_s);

}  // namespace dynanav
