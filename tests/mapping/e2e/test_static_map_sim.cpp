// The static map on simulated scenes with exact ground truth (issue 15): no people ghosts in
// map.ply (office), and the OctoMap forgets where a pushed box stood (pushed-box).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <map>
#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "io/trajectory.hpp"
#include "mapping/dense_cloud.hpp"
#include "mapping/octree_map.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using dynanav::test::runCli;
using dynanav::test::scratchDir;

namespace dynanav {
namespace {

struct GtObject {
  std::string class_name;
  std::vector<Vec3> p_world;  ///< per frame, ground-truth world (= first camera frame)
};

std::map<int, GtObject> readObjects(const fs::path& path) {
  std::map<int, GtObject> out;
  for (const nlohmann::json& line : readJsonLines(path))
    for (const nlohmann::json& o : line["objects"]) {
      GtObject& g = out[o["id"].get<int>()];
      g.class_name = o["class"];
      const auto p = o["position_world"];
      g.p_world.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    }
  return out;
}

/// Ground-truth "up": people walk on the floor, so their centroids span a plane parallel to it.
Vec3 upFromWalkers(const std::map<int, GtObject>& objects) {
  std::vector<Vec3> points;
  for (const auto& [id, o] : objects)
    if (o.class_name == "person") points.insert(points.end(), o.p_world.begin(), o.p_world.end());
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vec3 up = eig.eigenvectors().col(0);
  return up.y() < 0 ? up : -up;  // y is down
}

/// Ground-truth world <- SLAM world, from the first keyframe (the SLAM world is its camera).
SE3 gtFromSlam(const fs::path& seq, const fs::path& out) {
  const auto gt = readTrajectory(seq / "groundtruth.txt");
  const auto kf = readTrajectory(out / "keyframes.txt");
  EXPECT_FALSE(kf.empty());
  for (const StampedPose& g : gt)
    if (std::abs(g.stamp_s - kf.front().stamp_s) < 1e-4)
      return g.T_world_camera * kf.front().T_world_camera.inverse();
  ADD_FAILURE() << "first keyframe stamp not in groundtruth.txt";
  return SE3::Identity();
}

fs::path simulateAndMap(const std::string& scenario, const std::string& tag) {
  const fs::path dir = scratchDir(tag);
  std::string log;
  EXPECT_EQ(runCli("simulate --scenario " + scenario + " --out " + (dir / "seq").string(), &log), 0)
      << log;
  EXPECT_EQ(runCli("run " + (dir / "seq").string() + " --out " + (dir / "out").string() +
                       " --segmenter masks --map --quiet",
                   &log),
            0)
      << log;
  return dir;
}

TEST(StaticMapSim, OfficeMapHasNoPeopleGhosts) {
  const fs::path dir = simulateAndMap("office", "map_office");
  const auto objects = readObjects(dir / "seq" / "objects_gt.jsonl");
  const Vec3 up = upFromWalkers(objects);
  const SE3 T_gt_slam = gtFromSlam(dir / "seq", dir / "out");
  // Every position a person held, thinned to 2 cm steps.
  std::vector<Vec3> person_positions;
  for (const auto& [id, o] : objects) {
    if (o.class_name != "person") continue;
    for (const Vec3& p : o.p_world)
      if (person_positions.empty() || (person_positions.back() - p).norm() > 0.02)
        person_positions.push_back(p);
  }
  ASSERT_FALSE(person_positions.empty());
  const ColouredCloud cloud = readPly(dir / "out" / "map.ply");
  ASSERT_GT(cloud.size(), 10000u);
  // The floor the map found is the one the walkers walk on (within 5 degrees).
  const nlohmann::json info = readJsonFile(dir / "out" / "map_info.json");
  ASSERT_TRUE(info["floor"]["found"].get<bool>());
  const auto u = info["floor"]["up"];
  const Vec3 floor_up_slam(u[0].get<double>(), u[1].get<double>(), u[2].get<double>());
  EXPECT_GT((T_gt_slam.linear() * floor_up_slam).dot(up), std::cos(5.0 * M_PI / 180.0));
  const double floor_offset_m = info["floor"]["offset_m"].get<double>();
  // A ghost is a point where a body was: within 0.35 m horizontally of a person's position AND
  // between 0.10 m and 2.0 m above the floor. The floor under a walker's path and the ceiling
  // over it are within 0.35 m horizontally too, but they are not people; both counts printed.
  size_t in_cylinder = 0, in_body = 0;
  for (const Eigen::Vector3f& p_slam : cloud.p_world) {
    const Vec3 p = T_gt_slam * p_slam.cast<double>();
    for (const Vec3& q : person_positions) {
      const Vec3 d = p - q;
      if ((d - d.dot(up) * up).squaredNorm() < 0.35 * 0.35) {
        ++in_cylinder;
        const double h = floor_up_slam.dot(p_slam.cast<double>()) + floor_offset_m;
        in_body += h > 0.10 && h < 2.0;
        break;
      }
    }
  }
  const double share = double(in_body) / double(cloud.size());
  std::printf(
      "office: %zu of %zu map.ply points (%.3f %%) within 0.35 m horizontally of a person's "
      "position and 0.1-2.0 m above the floor; %zu (%.3f %%) at any height (floor and ceiling "
      "included)\n",
      in_body, cloud.size(), 100.0 * share, in_cylinder,
      100.0 * double(in_cylinder) / double(cloud.size()));
  EXPECT_LE(share, 0.01);
}

/// Occupancy samples in a vertical cylinder (radius, heights above the floor) around `centre`.
struct CylinderCount {
  int occupied = 0, free = 0, unknown = 0;
};
CylinderCount countCylinder(const octomap::OcTree& tree, const Vec3& centre_slam, const Vec3& up,
                            double radius_m, double below_m, double above_m) {
  CylinderCount c;
  const Vec3 a = up.unitOrthogonal(), b = up.cross(a);
  for (double h = -below_m; h <= above_m + 1e-9; h += 0.05)
    for (double x = -radius_m; x <= radius_m + 1e-9; x += 0.05)
      for (double y = -radius_m; y <= radius_m + 1e-9; y += 0.05) {
        if (x * x + y * y > radius_m * radius_m) continue;
        const Vec3 p = centre_slam + h * up + x * a + y * b;
        switch (cellState(tree, tree.search(p.x(), p.y(), p.z()))) {
          case CellState::kOccupied:
            ++c.occupied;
            break;
          case CellState::kFree:
            ++c.free;
            break;
          default:
            ++c.unknown;
        }
      }
  return c;
}

TEST(StaticMapSim, PushedBoxStartIsFreeAndEndIsOccupied) {
  const fs::path dir = simulateAndMap("pushed-box", "map_pushed_box");
  const auto objects = readObjects(dir / "seq" / "objects_gt.jsonl");
  const GtObject* box = nullptr;
  for (const auto& [id, o] : objects)
    if (o.class_name == "box") box = &o;
  ASSERT_NE(box, nullptr);
  const Vec3 up_gt = upFromWalkers(objects);
  const SE3 T_slam_gt = gtFromSlam(dir / "seq", dir / "out").inverse();
  const Vec3 up = T_slam_gt.linear() * up_gt;
  octomap::OcTree tree(0.05);
  ASSERT_TRUE(tree.readBinary((dir / "out" / "map.bt").string()));
  // The 0.7 x 1.0 x 0.7 m box's centre is 0.5 m above the floor; inside the cylinder of radius
  // 0.25 m from 0.15 m to 0.85 m above the floor, only the box itself can be.
  const CylinderCount start =
      countCylinder(tree, T_slam_gt * box->p_world.front(), up, 0.25, 0.35, 0.35);
  const CylinderCount end =
      countCylinder(tree, T_slam_gt * box->p_world.back(), up, 0.40, 0.45, 0.45);
  std::printf("pushed-box start: %d occupied, %d free, %d unknown; end (r 0.40 m): %d occupied\n",
              start.occupied, start.free, start.unknown, end.occupied);
  EXPECT_EQ(start.occupied, 0);
  EXPECT_GT(start.free, start.unknown);  // seen through, not just unseen
  EXPECT_GE(end.occupied, 20);
}

}  // namespace
}  // namespace dynanav
