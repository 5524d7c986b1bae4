#include "mapping/floor_grid.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <random>

namespace dynanav {
namespace {

constexpr double kInlierM = 0.03;

/// Least-squares plane through the points (normal oriented like `up_hint`).
FloorPlane fitPlane(const std::vector<Vec3>& points, const Vec3& up_hint) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU);
  Vec3 n = svd.matrixU().col(2);
  if (n.dot(up_hint) < 0) n = -n;
  FloorPlane plane;
  plane.found = true;
  plane.up = n;
  plane.offset_m = -n.dot(mean);
  plane.inliers = int(points.size());
  return plane;
}

}  // namespace

FloorPlane estimateFloor(const ColouredCloud& cloud, const std::vector<Vec3>& camera_centres,
                         double max_tilt_deg, double min_camera_height_m) {
  FloorPlane none;
  if (cloud.size() < 100) return none;
  // Counting inliers on ~20k points is enough to rank planes and keeps this well under 50 ms.
  const size_t stride = std::max<size_t>(1, cloud.size() / 20000);
  std::vector<Vec3> sample;
  for (size_t i = 0; i < cloud.size(); i += stride)
    sample.push_back(cloud.p_world[i].cast<double>());
  const Vec3 up_hint(0, -1, 0);
  const double min_cos = std::cos(max_tilt_deg * M_PI / 180.0);
  std::mt19937 rng(7);
  std::uniform_int_distribution<size_t> pick(0, sample.size() - 1);
  struct Candidate {
    Vec3 n;
    double d;
    int inliers;
    double lowest_camera_height;
  };
  std::vector<Candidate> candidates;
  int best = 0;
  for (int iter = 0; iter < 400; ++iter) {
    const Vec3 &a = sample[pick(rng)], &b = sample[pick(rng)], &c = sample[pick(rng)];
    Vec3 n = (b - a).cross(c - a);
    if (n.norm() < 1e-6) continue;
    n.normalize();
    if (n.dot(up_hint) < 0) n = -n;
    if (n.dot(up_hint) < min_cos) continue;
    const double d = -n.dot(a);
    double lowest = 1e9;
    for (const Vec3& centre : camera_centres) lowest = std::min(lowest, n.dot(centre) + d);
    if (camera_centres.empty() || lowest < min_camera_height_m) continue;
    int inliers = 0;
    for (const Vec3& p : sample) inliers += std::abs(n.dot(p) + d) < kInlierM;
    best = std::max(best, inliers);
    candidates.push_back({n, d, inliers, lowest});
  }
  if (best < 50) return none;
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates)
    if (c.inliers >= best / 2 &&
        (!chosen || c.lowest_camera_height > chosen->lowest_camera_height + kInlierM ||
         (std::abs(c.lowest_camera_height - chosen->lowest_camera_height) <= kInlierM &&
          c.inliers > chosen->inliers)))
      chosen = &c;
  std::vector<Vec3> inliers;
  for (const Vec3& p : sample)
    if (std::abs(chosen->n.dot(p) + chosen->d) < kInlierM) inliers.push_back(p);
  FloorPlane plane = fitPlane(inliers, up_hint);
  plane.inliers = int(inliers.size() * stride);
  return plane;
}

cv::Mat OccupancyGrid::image() const {
  cv::Mat out(cells.size(), CV_8U, cv::Scalar(160));
  out.setTo(255, cells == kFree);
  out.setTo(0, cells == kOccupied);
  return out;
}

OccupancyGrid occupancyGrid(const octomap::ColorOcTree& tree, const FloorPlane& floor,
                            double min_height_m, double max_height_m, double cell_m) {
  OccupancyGrid grid;
  grid.cell_m = cell_m;
  grid.floor = floor;
  const Vec3 up = floor.up;
  grid.right = projectOntoPlane(Vec3::UnitX(), up).normalized();
  grid.forward = up.cross(grid.right).normalized();
  if (grid.forward.dot(Vec3::UnitZ()) < 0) grid.forward = -grid.forward;
  struct Leaf {
    double right_m, forward_m, half_m;
    bool occupied;
  };
  std::vector<Leaf> leaves;
  double r0 = 1e9, r1 = -1e9, f0 = 1e9, f1 = -1e9;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const octomap::point3d c = it.getCoordinate();
    const Vec3 p(c.x(), c.y(), c.z());
    const double h = floor.height(p);
    if (h < min_height_m || h > max_height_m) continue;
    const Leaf leaf{grid.right.dot(p), grid.forward.dot(p), it.getSize() / 2.0,
                    tree.isNodeOccupied(*it)};
    r0 = std::min(r0, leaf.right_m - leaf.half_m);
    r1 = std::max(r1, leaf.right_m + leaf.half_m);
    f0 = std::min(f0, leaf.forward_m - leaf.half_m);
    f1 = std::max(f1, leaf.forward_m + leaf.half_m);
    leaves.push_back(leaf);
  }
  if (leaves.empty()) return grid;
  const double margin = 4 * cell_m;
  grid.right0_m = r0 - margin;
  grid.forward0_m = f1 + margin;
  const int cols = int(std::ceil((r1 - r0 + 2 * margin) / cell_m));
  const int rows = int(std::ceil((f1 - f0 + 2 * margin) / cell_m));
  grid.cells = cv::Mat::zeros(rows, cols, CV_8U);
  // Free first, then occupied on top: an obstacle anywhere in the height band blocks the cell.
  for (bool occupied_pass : {false, true})
    for (const Leaf& leaf : leaves) {
      if (leaf.occupied != occupied_pass) continue;
      const int c0 = int((leaf.right_m - leaf.half_m - grid.right0_m) / cell_m);
      const int c1 = int((leaf.right_m + leaf.half_m - grid.right0_m) / cell_m - 1e-6);
      const int q0 = int((grid.forward0_m - leaf.forward_m - leaf.half_m) / cell_m);
      const int q1 = int((grid.forward0_m - leaf.forward_m + leaf.half_m) / cell_m - 1e-6);
      const uint8_t value = occupied_pass ? OccupancyGrid::kOccupied : OccupancyGrid::kFree;
      for (int r = std::max(0, q0); r <= std::min(rows - 1, q1); ++r)
        for (int c = std::max(0, c0); c <= std::min(cols - 1, c1); ++c)
          grid.cells.at<uint8_t>(r, c) = value;
    }
  return grid;
}

}  // namespace dynanav
