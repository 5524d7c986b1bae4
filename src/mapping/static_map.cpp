#include "mapping/static_map.hpp"

#include <chrono>
#include <future>
#include <opencv2/imgcodecs.hpp>
#include <tuple>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/json_io.hpp"

namespace dynanav {

StaticMap buildStaticMap(const std::vector<PosedKeyframe>& keyframes, const cv::Mat& rays,
                         const StaticMapOptions& options) {
  StaticMap map;
  // Cloud and octree are independent: build them side by side (the run is over, the cores free).
  auto cloud = std::async(std::launch::async, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    ColouredCloud c = denseCloud(keyframes, rays, options.cloud_pixel_step, options.voxel_m);
    return std::make_pair(std::move(c), msSince(t0));
  });
  auto t0 = std::chrono::steady_clock::now();
  map.tree = buildOctree(keyframes, rays, options.octree);
  map.octree_ms = msSince(t0);
  std::tie(map.cloud, map.cloud_ms) = cloud.get();
  map.points_before_free_space_filter = map.cloud.size();
  t0 = std::chrono::steady_clock::now();
  if (options.drop_points_in_free_space) {
    const octomap::ColorOcTree& tree = *map.tree;
    // The cloud is sorted by voxel, so runs of points share an octree leaf: search once per run.
    octomap::OcTreeKey last_key;
    bool have_last = false, last_free = false;
    map.cloud = filterCloud(map.cloud, [&](const Eigen::Vector3f& p) {
      octomap::OcTreeKey key;
      if (!tree.coordToKeyChecked(p.x(), p.y(), p.z(), key)) return false;
      if (!have_last || !(key == last_key)) {
        last_key = key;
        have_last = true;
        last_free = cellState(tree, tree.search(key)) == CellState::kFree;
      }
      return last_free;
    });
  }
  map.filter_ms = msSince(t0);
  t0 = std::chrono::steady_clock::now();
  std::vector<Vec3> centres;
  for (const PosedKeyframe& k : keyframes) centres.push_back(k.T_world_camera.translation());
  const FloorPlane floor = estimateFloor(map.cloud, centres);
  if (floor.found)
    map.grid = occupancyGrid(*map.tree, floor, options.walk_min_height_m, options.walk_max_height_m,
                             options.grid_cell_m);
  map.grid_ms = msSince(t0);
  return map;
}

void writeStaticMap(const std::filesystem::path& out_dir, const StaticMap& map) {
  writePly(out_dir / "map.ply", map.cloud);
  writeBinaryOctree(out_dir / "map.bt", *map.tree);
  const OccupancyGrid& g = map.grid;
  if (!g.cells.empty() && !cv::imwrite((out_dir / "occupancy.png").string(), g.image()))
    throw InputError((out_dir / "occupancy.png").string(), "cannot write");
  auto vec = [](const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json info = {
      {"frame", "world = first camera frame (x right, y down, z forward), metres"},
      {"cloud_points", map.cloud.size()},
      {"cloud_points_before_free_space_filter", map.points_before_free_space_filter},
      {"octree_resolution_m", map.tree->getResolution()},
      {"octree_leaves", map.tree->getNumLeafNodes()},
      {"build_ms",
       {{"cloud", map.cloud_ms},
        {"octree", map.octree_ms},
        {"free_space_filter", map.filter_ms},
        {"grid", map.grid_ms}}},
      {"floor",
       {{"found", g.floor.found},
        {"up", vec(g.floor.up)},
        {"offset_m", g.floor.offset_m},
        {"inliers", g.floor.inliers}}}};
  if (!g.cells.empty())
    info["occupancy"] = {{"file", "occupancy.png"},
                         {"cell_m", g.cell_m},
                         {"cols", g.cells.cols},
                         {"rows", g.cells.rows},
                         {"right_axis", vec(g.right)},
                         {"forward_axis", vec(g.forward)},
                         {"right0_m", g.right0_m},
                         {"forward0_m", g.forward0_m},
                         {"legend",
                          "white free, black occupied, grey unknown; column = "
                          "(right.p - right0)/cell, row = (forward0 - forward.p)/cell"}};
  writeJsonFile(out_dir / "map_info.json", info);
}

}  // namespace dynanav
