#include "slam/loop_verification.hpp"

#include <spdlog/spdlog.h>

#include <set>

#include "slam/matcher.hpp"
#include "slam/pose_optimizer.hpp"
#include "slam/rigid_ransac.hpp"
#include "slam/vocabulary/bow_matching.hpp"

namespace dynanav {
namespace {

bool good(const MapPointPtr& p) {
  return p && !p->bad;
}

std::vector<MapPointPtr> pointsAround(const KeyFrame& loop) {
  std::vector<MapPointPtr> out;
  std::set<uint64_t> seen;
  std::vector<const KeyFrame*> group{&loop};
  for (const KeyFrame* n : loop.ordered_covisible) group.push_back(n);
  for (const KeyFrame* kf : group) {
    if (kf->bad) continue;
    for (const auto& p : kf->map_points)
      if (good(p) && seen.insert(p->id).second) out.push_back(p);
  }
  return out;
}

/// Pose optimisation of the current keyframe against the loop points it matched; drops outliers
/// from `matches`. Returns the inlier count.
int refinePose(const KeyFrame& current, SE3& T_camera_world, std::vector<LoopMatch>& matches) {
  const Features& f = current.features;
  const PinholeCamera& cam = *f.camera;
  std::vector<PoseObservation> observations;
  for (const auto& m : matches) {
    PoseObservation obs;
    obs.p_world = m.point->p_world;
    obs.u = f.points[m.keypoint].x;
    obs.v = f.points[m.keypoint].y;
    obs.u_right = f.u_right[m.keypoint];
    obs.inv_sigma2 = f.scales->inv_sigma2[f.keypoints[m.keypoint].octave];
    observations.push_back(obs);
  }
  std::vector<uint8_t> outlier;
  const int inliers = optimizePose(observations, {cam.fx, cam.fy, cam.cx, cam.cy, cam.bf()}, {},
                                   T_camera_world, outlier);
  std::vector<LoopMatch> kept;
  for (size_t k = 0; k < matches.size(); ++k)
    if (!outlier[k]) kept.push_back(matches[k]);
  matches = std::move(kept);
  return inliers;
}

}  // namespace

int matchByProjection(const KeyFrame& keyframe, const SE3& T_camera_world,
                      const std::vector<MapPointPtr>& points, float radius_px,
                      std::vector<uint8_t>& taken, std::vector<LoopMatch>& matches) {
  const Features& f = keyframe.features;
  const PinholeCamera& cam = *f.camera;
  const PyramidScales& scales = *f.scales;
  const Vec3 center = T_camera_world.inverse().translation();
  int added = 0;
  for (const auto& point : points) {
    if (!good(point)) continue;
    const Vec3 p_c = T_camera_world * point->p_world;
    if (p_c.z() <= 0.0) continue;
    const Eigen::Vector2d uv = cam.project(p_c);
    if (!f.inBounds(uv.x(), uv.y())) continue;
    const Vec3 po = point->p_world - center;
    const double dist = po.norm();
    if (dist < 0.8 * point->min_distance_m || dist > 1.2 * point->max_distance_m) continue;
    if (po.dot(point->normal) < 0.5 * dist) continue;  // seen at over 60 degrees
    const int level = point->predictLevel(dist, scales);
    const float radius = radius_px * scales.scale[level];
    int best = 256, best_index = -1;
    for (const int j :
         f.featuresInArea(uv.x(), uv.y(), radius, std::max(0, level - 1), level + 1)) {
      if (taken[j] || !f.usable[j]) continue;
      const int d = descriptorRowDistance(point->descriptor, 0, f.descriptors, j);
      if (d < best) {
        best = d;
        best_index = j;
      }
    }
    if (best > matcher::kDistanceLow) continue;
    taken[best_index] = 1;
    matches.push_back({best_index, point});
    ++added;
  }
  return added;
}

std::optional<VerifiedLoop> verifyLoop(const KeyFrame& current,
                                       const std::vector<KeyFrame*>& candidates,
                                       const LoopConfig& config) {
  const Features& f = current.features;
  for (KeyFrame* candidate : candidates) {
    if (candidate->bad || candidate->bow_features.empty()) continue;
    const Features& g = candidate->features;
    auto bow_matches = matchByDirectIndex(
        current.bow_features, f.descriptors, f.keypoints, candidate->bow_features, g.descriptors,
        g.keypoints, {}, [&](int i) { return good(current.map_points[i]) && f.usable[i]; });
    std::erase_if(bow_matches,
                  [&](const cv::DMatch& m) { return !good(candidate->map_points[m.trainIdx]); });
    if (static_cast<int>(bow_matches.size()) < config.loop_min_bow_matches) {
      spdlog::debug("loop kf {} vs {}: {} bow matches, too few", current.id, candidate->id,
                    bow_matches.size());
      continue;
    }
    // 3D-3D pairs, each in its own camera: RANSAC finds T_candidate_current.
    std::vector<Vec3> a, b;
    std::vector<double> b_depth;
    for (const auto& m : bow_matches) {
      a.push_back(current.T_camera_world() * current.map_points[m.queryIdx]->p_world);
      b.push_back(candidate->T_camera_world() * candidate->map_points[m.trainIdx]->p_world);
      b_depth.push_back(b.back().z());
    }
    RigidRansacOptions ransac;
    ransac.min_inliers = config.loop_min_ransac_inliers;
    ransac.seed = current.id + 1;
    const RigidRansacResult rigid = estimateRigidRansac(a, b, ransac, b_depth);
    spdlog::debug("loop kf {} vs {}: {} bow matches, ransac {} ({} inliers)", current.id,
                  candidate->id, bow_matches.size(), rigid.ok ? "ok" : "failed", rigid.inliers);
    if (!rigid.ok) continue;
    VerifiedLoop loop;
    loop.loop = candidate;
    loop.ransac_inliers = rigid.inliers;
    loop.T_camera_world_corrected = rigid.T_b_a.inverse() * candidate->T_camera_world();
    std::vector<uint8_t> taken(f.size(), 0);
    for (size_t k = 0; k < bow_matches.size(); ++k) {
      if (!rigid.inlier[k]) continue;
      taken[bow_matches[k].queryIdx] = 1;
      loop.matches.push_back(
          {bow_matches[k].queryIdx, candidate->map_points[bow_matches[k].trainIdx]});
    }
    // More matches around the projections of everything the loop side sees, then a pose
    // optimisation over all of them: the loop is accepted only with wide geometric support.
    loop.loop_points = pointsAround(*candidate);
    matchByProjection(current, loop.T_camera_world_corrected, loop.loop_points, 10.0f, taken,
                      loop.matches);
    const int inliers = refinePose(current, loop.T_camera_world_corrected, loop.matches);
    spdlog::debug("loop kf {} vs {}: {} matches after projection, {} inliers", current.id,
                  candidate->id, loop.matches.size(), inliers);
    if (inliers < config.loop_min_matches) continue;
    return loop;
  }
  return std::nullopt;
}

}  // namespace dynanav
