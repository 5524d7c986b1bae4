#pragma once
// The dense static cloud (issue 15): every static pixel of every keyframe placed with its final
// pose, averaged per voxel, written as binary PLY (x y z float, red green blue uchar).
#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "mapping/map_keyframe.hpp"

namespace dynanav {

struct ColouredCloud {
  std::vector<Eigen::Vector3f> p_world;  ///< m
  std::vector<cv::Vec3b> bgr;
  [[nodiscard]] size_t size() const { return p_world.size(); }
};

/// Back-projects every `pixel_step`-th static pixel of each keyframe (rays from rayTable at the
/// keyframes' resolution) and keeps one point per `voxel_m` voxel: the mean position and colour
/// of the samples that fell in it.
ColouredCloud denseCloud(const std::vector<PosedKeyframe>& keyframes, const cv::Mat& rays,
                         int pixel_step, double voxel_m);

/// Drops the points for which `drop` is true (e.g. in space the octree later saw free).
ColouredCloud filterCloud(const ColouredCloud& cloud,
                          const std::function<bool(const Eigen::Vector3f&)>& drop);

/// Binary little-endian PLY. Throws InputError when the file cannot be written.
void writePly(const std::filesystem::path& path, const ColouredCloud& cloud);
/// Reads what writePly wrote (binary little-endian, float xyz + uchar rgb). Throws InputError.
ColouredCloud readPly(const std::filesystem::path& path);

}  // namespace dynanav
