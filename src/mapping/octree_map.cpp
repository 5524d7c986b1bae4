#include "mapping/octree_map.hpp"

#include <fstream>

#include "core/error.hpp"

namespace dynanav {

std::unique_ptr<octomap::ColorOcTree> buildOctree(const std::vector<PosedKeyframe>& keyframes,
                                                  const cv::Mat& rays,
                                                  const OctreeOptions& options) {
  auto tree = std::make_unique<octomap::ColorOcTree>(options.resolution_m);
  const int step = std::max(1, options.pixel_step);
  for (size_t k = 0; k < keyframes.size(); ++k) {
    const PosedKeyframe& posed = keyframes[k];
    const MapKeyframe& kf = *posed.keyframe;
    const Eigen::Matrix3d R = posed.T_world_camera.linear();
    const Vec3 t = posed.T_world_camera.translation();
    octomap::Pointcloud scan;
    std::vector<std::pair<octomap::point3d, cv::Vec3b>> colours;
    const int rows = std::min(kf.depth_m.rows, rays.rows),
              cols = std::min(kf.depth_m.cols, rays.cols);
    // Offset the sampling grid per keyframe so successive keyframes' rays interleave.
    const int offset = int(k % size_t(step));
    for (int y = offset; y < rows; y += step) {
      const float* depth = kf.depth_m.ptr<float>(y);
      const cv::Vec2f* ray = rays.ptr<cv::Vec2f>(y);
      for (int x = offset; x < cols; x += step) {
        const double z = depth[x];
        if (!(z > 0.0)) continue;
        const Vec3 p = R * Vec3(ray[x][0] * z, ray[x][1] * z, z) + t;
        const octomap::point3d q(float(p.x()), float(p.y()), float(p.z()));
        scan.push_back(q);
        colours.emplace_back(q, kf.bgr.at<cv::Vec3b>(y, x));
      }
    }
    const octomap::point3d origin(float(t.x()), float(t.y()), float(t.z()));
    // discretize: one ray per end cell (many pixels hit the same 5 cm cell at close range).
    tree->insertPointCloud(scan, origin, options.max_range_m, /*lazy_eval=*/true,
                           /*discretize=*/true);
    for (const auto& [q, c] : colours)
      tree->integrateNodeColor(q.x(), q.y(), q.z(), c[2], c[1], c[0]);
  }
  tree->updateInnerOccupancy();
  return tree;
}

void writeBinaryOctree(const std::filesystem::path& path, const octomap::ColorOcTree& tree) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path.string(), "cannot write");
  // The header AbstractOccupancyOcTree::writeBinary writes, with the plain OcTree id: the binary
  // payload (two occupancy bits per child) is the same for every occupancy tree.
  out << "# Octomap OcTree binary file\n# dynanav static map (world = first camera, y down)\n"
      << "id OcTree\nsize " << tree.size() << "\nres " << tree.getResolution() << "\ndata\n";
  tree.writeBinaryData(out);
  if (!out) throw InputError(path.string(), "write failed");
}

CellState cellState(const octomap::AbstractOccupancyOcTree& tree, const octomap::OcTreeNode* node) {
  if (node == nullptr) return CellState::kUnknown;
  return tree.isNodeOccupied(node) ? CellState::kOccupied : CellState::kFree;
}

}  // namespace dynanav
