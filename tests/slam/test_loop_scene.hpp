#pragma once
// A synthetic world for relocalisation and loop-closing tests: a cylindrical room whose wall holds
// points with random ORB descriptors, a camera that turns around inside it looking at the wall,
// exact keypoints and depth, and a small vocabulary trained on the points' descriptors. Keyframes
// can be given drifted poses, with their points placed from the drifted poses, like a real map.
#include <memory>
#include <random>
#include <vector>

#include "core/camera.hpp"
#include "core/config/orb.hpp"
#include "slam/features.hpp"
#include "slam/keyframe.hpp"
#include "slam/map.hpp"
#include "slam/vocabulary/vocabulary.hpp"

namespace dynanav::test {

struct LoopScene {
  std::shared_ptr<const PinholeCamera> camera;
  std::shared_ptr<const PyramidScales> scales;
  std::vector<Vec3> points;  ///< true world positions
  cv::Mat descriptors;       ///< one row per point
  std::shared_ptr<const Vocabulary> vocabulary;
};

/// `count` points on a wall of radius `radius_m` about the vertical axis through (0, 0, -orbit_m),
/// heights in [-1.2, 1.2] m.
LoopScene makeLoopScene(int count, double radius_m, double orbit_m, uint64_t seed);

/// Camera at angle `angle_rad` on a circle of radius `orbit_m` about the room's axis (y down),
/// looking out at the wall; angle 0 is the identity pose (the world frame).
SE3 orbitPose(double angle_rad, double orbit_m);

struct View {
  Features features;
  std::vector<int> point_of;  ///< true point index per keypoint
};

/// What a camera at T_camera_world sees: exact keypoints (level 0) with depth, descriptors with
/// up to `flip_bits` random bits changed.
View renderView(const LoopScene& scene, const SE3& T_camera_world, int flip_bits, uint64_t seed);

/// Keyframes seeing the scene from the true poses but placed at the estimated ones, in order. A
/// keyframe re-uses the map point of a true point that one of the previous 3 keyframes observed
/// (tracking continuity), else creates a new point from its estimated pose and its depth: so a
/// revisit after a long way round duplicates points, as a drifting SLAM map does.
std::vector<KeyFramePtr> buildMap(const LoopScene& scene, const std::vector<SE3>& T_cw_true,
                                  const std::vector<SE3>& T_cw_estimated, Map& map,
                                  int flip_bits = 6);

}  // namespace dynanav::test
