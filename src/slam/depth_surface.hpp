#pragma once
// The static depth of a frame as pose evidence (issue 18: crowded frames). Where walkers fill most
// of the view, a frame's pose rests on a few dozen keypoints on one wall, and is weakly held along
// the direction they leave open: sliding sideways while turning the other way moves a far wall's
// corners alike (Bonn crowd, frames 246-247 and 391-393: the persistent fit's translation sigma
// 2.3-3.2 cm against a median 0.46 cm, docs/slam.md "Session 27"). The depth image tells the two
// apart: a turn tilts the wall's depth across the image, a slide does not, and the floor and other
// walls outside every mask hold thousands of samples where corners are few. So each frame keeps its
// static depth as a surface (undistorted, at half resolution, masked where the segmenter and the
// dynamics stage masked keypoints), the last frame's static samples are placed in the world with
// its pose, and pose optimisation weighs their point-to-plane distance to this frame's surface
// beside the keypoints (slam/pose_optimizer.hpp).
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.hpp"
#include "core/se3.hpp"

namespace dynanav {

/// A pinhole depth image (no distortion) at some resolution: where a point lands and what surface
/// lies there.
struct DepthSurface {
  cv::Mat depth_m;  ///< CV_32F; 0 = no depth, beyond the range, or masked
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;

  [[nodiscard]] bool empty() const { return depth_m.empty(); }
};

/// The surface's point and unit normal (toward the camera) under a pixel.
struct SurfacePoint {
  Vec3 p_camera;
  Vec3 normal_camera;
};

/// Builds surfaces from one camera's depth images (registered to its distorted colour image):
/// every pixel of the half-resolution undistorted image takes the depth at its distorted
/// full-size pixel (nearest: no interpolation across depth edges). The pixel map is the camera's,
/// computed once.
class DepthSurfaceMaker {
 public:
  DepthSurfaceMaker(const PinholeCamera& camera, double depth_max_m);
  /// 0 where `allowed` (CV_8U, full size; empty = everything) is 0, where the depth is invalid
  /// or beyond the range.
  [[nodiscard]] DepthSurface make(const cv::Mat& depth_m, const cv::Mat& allowed) const;

 private:
  cv::Size full_size_, half_size_;
  std::vector<int> source_;  ///< full-size pixel index per surface pixel; -1 outside the image
  DepthSurface intrinsics_;
  double depth_max_m_;
};

/// The surface under a point of the camera frame: its projection's depth and a normal from the
/// neighbours two pixels away; none off the image, in a hole, across a depth edge (the neighbours
/// further apart than a plane that steep allows), or where the point lies more than
/// `max_distance_m` from it.
std::optional<SurfacePoint> surfaceAt(const DepthSurface& surface, const Vec3& p_camera,
                                      double max_distance_m);

/// Camera-frame points of the surface on a grid every `step_px` of its pixels.
std::vector<Vec3> surfaceSamples(const DepthSurface& surface, int step_px);

/// The depth noise (m) of a structured-light sensor at `depth_m` (Nguyen et al., 3DIMPVT 2012:
/// 1.2 mm at 0.4 m, growing with the square of the distance beyond).
inline double depthSigmaM(double depth_m) {
  const double d = depth_m - 0.4;
  return 0.0012 + 0.0019 * d * d;
}

}  // namespace dynanav
