#pragma once
// The floor under the wearer, from one depth image: where a far walker's feet meet it gives the
// walker's range without assuming a stature (height_range.hpp, rangeFromFloorContact). Indoors
// the floor is in the depth sensor's range in the image's lower part whenever the camera looks
// ahead; the plane is fitted afresh every frame it is needed, so a head's bob and pitch are
// followed (the simulated walk: 1.58-1.62 m below the camera frame to frame).
#include <opencv2/core.hpp>
#include <optional>

#include "core/camera.hpp"
#include "core/se3.hpp"

namespace dynanav {

/// (Not mapping/floor_grid.hpp's FloorPlane, the floor of the whole map's cloud in the world
/// frame.) A plane n·p = offset_m in the camera frame, n the unit normal pointing up (away from the
/// floor, toward the camera): the camera lies -offset_m above it.
struct CameraFloor {
  Vec3 normal_camera = Vec3(0.0, -1.0, 0.0);
  double offset_m = 0.0;
};

struct CameraFloorOptions {
  double lower_share = 0.4;       ///< the image's lower part searched (share of its rows)
  int step_px = 8;                ///< one depth sample every step_px in each direction
  int iterations = 150;           ///< RANSAC draws of three points
  double inlier_band_m = 0.02;    ///< a point this near the plane supports it
  double max_tilt_deg = 30.0;     ///< the normal lies within this of the expected up
  double min_inlier_share = 0.3;  ///< of the valid samples, for a plane to be reported
  uint64_t seed = 1;              ///< same image, same plane
};

/// The world's up seen from a camera at T_world_camera: the world frame is the first camera's,
/// whose -y is taken as up (the floor fit's expected normal, the stature range's vertical).
inline Vec3 worldUpInCamera(const SE3& T_world_camera) {
  return T_world_camera.linear().transpose() * Vec3(0.0, -1.0, 0.0);
}

/// The dominant plane among the depth points of the image's lower part whose upward normal lies
/// within max_tilt_deg of `up_camera` (the world's up seen from this camera) and below the
/// camera; RANSAC, then a least-squares refit to its inliers. None when too few points support
/// one (the floor out of view or out of the sensor's range).
std::optional<CameraFloor> estimateFloorPlane(const cv::Mat& depth_m, const PinholeCamera& camera,
                                              const Vec3& up_camera,
                                              const CameraFloorOptions& options = {});

/// The floor in the world frame, averaged over the frames that fitted one: the floor does not
/// move while one frame's fit jitters (the simulated approach: 1-2 % of a walker's range at
/// 11 m frame to frame, the fit alone). A fit far from the average (after a few frames) is left
/// out: a table top or a ramp, not the floor.
class FloorAverage {
 public:
  /// Takes this frame's fit (camera frame; none: nothing to add) at this frame's tracked pose,
  /// and returns the averaged floor seen from this camera (none before any fit).
  std::optional<CameraFloor> update(const std::optional<CameraFloor>& fit_camera,
                                    const SE3& T_world_camera);

 private:
  static constexpr int kMemoryFrames = 30;     ///< the average's weight on a new fit: 1/30 at least
  static constexpr int kSettledFrames = 5;     ///< from then on, far fits are left out
  static constexpr double kMaxTiltRad = 0.05;  ///< 2.9 degrees
  static constexpr double kMaxOffsetM = 0.10;
  Vec3 normal_world_ = Vec3::Zero();
  double offset_world_m_ = 0.0;
  int frames_ = 0;
};

}  // namespace dynanav
