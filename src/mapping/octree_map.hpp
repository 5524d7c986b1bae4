#pragma once
// The OctoMap of the static scene (issue 15): each keyframe's static depth is ray cast from the
// camera centre, so a cell occupied early on (a chair before it was moved) is cleared when later
// rays pass through it. Ghost-free by construction, given free space is observed.
#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/se3.hpp"
#include "mapping/map_keyframe.hpp"

namespace dynanav {

struct OctreeOptions {
  double resolution_m = 0.05;
  double max_range_m = 4.0;  ///< rays longer than this only clear up to it
  int pixel_step = 6;        ///< one ray per k-th pixel of the kept keyframe images
};

/// Inserts the keyframes in time order (rays from rayTable at their resolution).
std::unique_ptr<octomap::ColorOcTree> buildOctree(const std::vector<PosedKeyframe>& keyframes,
                                                  const cv::Mat& rays,
                                                  const OctreeOptions& options);

/// Standard OctoMap binary (.bt, occupancy only) with the plain "OcTree" id, so any OctoMap tool
/// (octovis, OcTree::readBinary) reads it. Throws InputError.
void writeBinaryOctree(const std::filesystem::path& path, const octomap::ColorOcTree& tree);

enum class CellState { kUnknown, kFree, kOccupied };
/// What the tree says about the leaf holding `p_world`.
CellState cellState(const octomap::AbstractOccupancyOcTree& tree, const octomap::OcTreeNode* node);
template <class Tree>
CellState cellAt(const Tree& tree, const Vec3& p_world) {
  return cellState(tree, tree.search(p_world.x(), p_world.y(), p_world.z()));
}

}  // namespace dynanav
