#pragma once
// The frame being tracked (ORB-SLAM2 Frame): features, current pose estimate and the map point
// matched to each keypoint, with an outlier flag per match from pose optimisation.
#include <cstdint>
#include <vector>

#include "core/se3.hpp"
#include "slam/depth_surface.hpp"
#include "slam/features.hpp"
#include "slam/map_point.hpp"

namespace dynanav {

struct Frame {
  uint64_t id = 0;
  double stamp_s = 0.0;
  Features features;
  SE3 T_camera_world = SE3::Identity();
  std::vector<MapPointPtr> map_points;  ///< per keypoint
  std::vector<uint8_t> outlier;         ///< per keypoint, set by pose optimisation
  /// This frame's static depth (empty: not kept), and its reference keyframe's static depth
  /// samples placed in the world by that keyframe's pose (empty: none to align with): pose
  /// evidence beside the keypoints (slam/depth_surface.hpp).
  DepthSurface depth_surface;
  std::vector<Vec3> depth_reference_world;

  Frame() = default;
  Frame(uint64_t id_, double stamp, Features f) : id(id_), stamp_s(stamp), features(std::move(f)) {
    map_points.assign(features.size(), nullptr);
    outlier.assign(features.size(), 0);
  }
  [[nodiscard]] int size() const { return features.size(); }
  [[nodiscard]] Vec3 center() const { return T_camera_world.inverse().translation(); }
  void clearMatches() {
    std::fill(map_points.begin(), map_points.end(), nullptr);
    std::fill(outlier.begin(), outlier.end(), 0);
  }
};

}  // namespace dynanav
