#include "slam/local_map.hpp"

#include <algorithm>
#include <map>

namespace dynanav {

void updateLocalMap(const Frame& frame, const std::map<uint64_t, KeyFramePtr>& lookup,
                    int max_keyframes, LocalMap& local) {
  // Votes: how many of the frame's points each keyframe observes.
  std::map<KeyFrame*, int, KeyFrameIdLess> votes;
  for (const auto& point : frame.map_points) {
    if (!point || point->bad) continue;
    for (const auto& [kf, index] : point->observations) ++votes[kf];
  }
  local.keyframes.clear();
  local.points.clear();
  if (votes.empty()) return;
  auto take = [&](KeyFrame* kf) {
    if (kf->bad || kf->local_for_frame == frame.id) return false;
    const auto it = lookup.find(kf->id);
    if (it == lookup.end()) return false;
    kf->local_for_frame = frame.id;
    local.keyframes.push_back(it->second);
    return true;
  };
  KeyFrame* best = nullptr;
  int best_votes = 0;
  for (const auto& [kf, n] : votes) {
    if (kf->bad) continue;
    if (n > best_votes) {
      best_votes = n;
      best = kf;
    }
    take(kf);
  }
  // Neighbours of the direct observers: up to 10 covisible, children, parent (ORB-SLAM2).
  const size_t direct = local.keyframes.size();
  for (size_t k = 0; k < direct; ++k) {
    if (static_cast<int>(local.keyframes.size()) > max_keyframes) break;
    KeyFrame* kf = local.keyframes[k].get();
    for (KeyFrame* neighbour : kf->bestCovisible(10)) {
      if (take(neighbour)) break;
    }
    for (KeyFrame* child : kf->children) {
      if (take(child)) break;
    }
    if (kf->parent) take(kf->parent);
  }
  for (const auto& kf : local.keyframes) {
    for (const auto& point : kf->map_points) {
      if (!point || point->bad || point->local_for_frame == frame.id) continue;
      point->local_for_frame = frame.id;
      local.points.push_back(point);
    }
  }
  if (best) local.reference = lookup.at(best->id);
}

bool prepareProjection(const Frame& frame, const Vec3& frame_center, MapPoint& point,
                       float min_view_cos) {
  point.track_in_view = false;
  const Features& f = frame.features;
  const PinholeCamera& cam = *f.camera;
  const Vec3 p_c = frame.T_camera_world * point.p_world;
  if (p_c.z() <= 0.0) return false;
  const Eigen::Vector2d uv = cam.project(p_c);
  if (!f.inBounds(uv.x(), uv.y())) return false;
  const Vec3 po = point.p_world - frame_center;
  const double dist = po.norm();
  if (dist < 0.8 * point.min_distance_m || dist > 1.2 * point.max_distance_m) return false;
  const double view_cos = po.dot(point.normal) / dist;
  if (view_cos < min_view_cos) return false;
  point.track_in_view = true;
  point.track_u = static_cast<float>(uv.x());
  point.track_v = static_cast<float>(uv.y());
  point.track_u_right = static_cast<float>(uv.x() - cam.bf() / p_c.z());
  point.track_level = point.predictLevel(dist, *f.scales);
  point.track_view_cos = static_cast<float>(view_cos);
  return true;
}

}  // namespace dynanav
