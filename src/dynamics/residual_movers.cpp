#include "dynamics/residual_movers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "core/median.hpp"
#include "dynamics/keypoint_dynamics.hpp"

namespace dynanav {

namespace {
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

/// Per-axis median of the normalised residuals r / sigma of `keypoints` (not empty).
Eigen::Vector2d medianNormalised(const std::vector<int>& keypoints,
                                 const std::vector<MapResidual>& residuals) {
  std::vector<double> u, v;
  for (const int i : keypoints) {
    const Eigen::Vector2d n = residuals[i].normalised();
    u.push_back(n.x());
    v.push_back(n.y());
  }
  return {medianInPlace(u), medianInPlace(v)};
}

/// The median normalised residual of the young keypoints outside `region` (zero if fewer than
/// `min_points`). Young points share their keyframe's pose error, which the established points
/// do not: all of them then show a common offset, which is not motion.
Eigen::Vector2d othersOffset(const std::vector<int>& young, const std::vector<int>& region,
                             const std::vector<MapResidual>& residuals, int min_points) {
  std::vector<int> others;
  for (const int i : young)
    if (!std::binary_search(region.begin(), region.end(), i)) others.push_back(i);
  if (static_cast<int>(others.size()) < min_points) return Eigen::Vector2d::Zero();
  return medianNormalised(others, residuals);
}
}  // namespace

ResidualMovers findResidualMovers(const Frame& frame, const std::vector<MapResidual>& residuals,
                                  const DynamicsConfig& config) {
  ResidualMovers out;
  const Features& f = frame.features;
  std::vector<int> young;  // keypoint indices
  for (int i = 0; i < frame.size() && i < static_cast<int>(residuals.size()); ++i)
    if (residuals[i].valid && residuals[i].young && f.depth_m[i] > 0.f) young.push_back(i);
  const int n = static_cast<int>(young.size());
  if (n < config.residual_region_min_points) return out;
  const double radius2 = config.residual_region_radius_px * config.residual_region_radius_px;
  DisjointSets sets(n);
  // Pairs within the radius, found along the points sorted by column (a sweep, not all pairs).
  std::vector<int> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(),
            [&](int a, int b) { return f.points[young[a]].x < f.points[young[b]].x; });
  for (int ia = 0; ia < n; ++ia) {
    const int a = by_x[ia];
    const cv::Point2f& pa = f.points[young[a]];
    for (int ib = ia + 1; ib < n; ++ib) {
      const int b = by_x[ib];
      const cv::Point2f d = f.points[young[b]] - pa;
      if (double(d.x) > config.residual_region_radius_px) break;
      if (double(d.x) * d.x + double(d.y) * d.y > radius2) continue;
      if (std::abs(f.depth_m[young[a]] - f.depth_m[young[b]]) > config.residual_region_depth_band_m)
        continue;
      sets.join(a, b);
    }
  }
  std::vector<std::vector<int>> regions(n);
  for (int a = 0; a < n; ++a) regions[sets.find(a)].push_back(young[a]);
  for (const std::vector<int>& region : regions) {
    const int count = static_cast<int>(region.size());
    if (count < config.residual_region_min_points) continue;
    const Eigen::Vector2d offset =
        othersOffset(young, region, residuals, config.residual_region_min_points);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();  // in units of each keypoint's sigma
    for (const int i : region) mean += residuals[i].normalised();
    mean = mean / count - offset;
    if (count * mean.squaredNorm() <= config.residual_region_chi2) continue;
    if (mean.norm() < config.residual_region_min_px) continue;
    ++out.regions;
    out.keypoints.insert(out.keypoints.end(), region.begin(), region.end());
  }
  std::sort(out.keypoints.begin(), out.keypoints.end());
  return out;
}

ResidualInstances findResidualInstances(const Frame& frame,
                                        const std::vector<MapResidual>& background_residuals,
                                        const Instances& instances, const DynamicsConfig& config) {
  ResidualInstances out;
  const Features& f = frame.features;
  if (instances.empty() || f.instance_id.size() != f.keypoints.size()) return out;
  std::map<uint16_t, std::vector<int>> measured;  // instance -> keypoints with a residual
  const int n = std::min(frame.size(), static_cast<int>(background_residuals.size()));
  for (int i = 0; i < n; ++i)
    if (background_residuals[i].valid && f.instance_id[i] != 0)
      measured[f.instance_id[i]].push_back(i);
  for (const auto& [id, keypoints] : measured) {
    const Instance* instance = instances.find(id);
    const int count = static_cast<int>(keypoints.size());
    if (!instance || isPriorDynamic(*instance, config) || count < config.residual_region_min_points)
      continue;
    const Eigen::Vector2d median = medianNormalised(keypoints, background_residuals);
    if (count * (2.0 / M_PI) * median.squaredNorm() > config.residual_region_chi2 &&
        median.norm() >= config.residual_region_min_px)
      out.ids.push_back(id);
  }
  // The instance decides for all its keypoints, those without a match too (as the depth vote).
  for (int i = 0; i < frame.size(); ++i)
    if (f.instance_id[i] && std::binary_search(out.ids.begin(), out.ids.end(), f.instance_id[i]))
      out.keypoints.push_back(i);
  return out;
}

}  // namespace dynanav
