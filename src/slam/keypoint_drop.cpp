#include "slam/keypoint_drop.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dynanav {

std::vector<float> predictedMapPointDepths(const Frame& frame) {
  std::vector<float> depth_m(frame.size(), 0.f);
  for (int i = 0; i < frame.size(); ++i) {
    const MapPointPtr& point = frame.map_points[i];
    if (!point || frame.outlier[i] || point->bad) continue;
    depth_m[i] = static_cast<float>((frame.T_camera_world * point->p_world).z());
  }
  return depth_m;
}

std::vector<float> mapPointMovingEvidence(const Frame& frame) {
  std::vector<float> evidence(frame.size(), std::nanf(""));
  for (int i = 0; i < frame.size(); ++i) {
    const MapPointPtr& point = frame.map_points[i];
    if (!point || frame.outlier[i] || point->bad) continue;
    evidence[i] = point->moving_evidence;
  }
  return evidence;
}

void addDrops(KeypointDrop& drop, const std::vector<int>& keypoints, bool cull) {
  std::vector<std::pair<int, bool>> merged;
  merged.reserve(drop.drop.size() + keypoints.size());
  for (size_t k = 0; k < drop.drop.size(); ++k)
    merged.emplace_back(drop.drop[k], drop.cull_on_drop[k]);
  for (const int i : keypoints) merged.emplace_back(i, cull);
  std::sort(merged.begin(), merged.end());
  drop.drop.clear();
  drop.cull_on_drop.clear();
  for (const auto& [i, c] : merged) {
    if (!drop.drop.empty() && drop.drop.back() == i) {
      drop.cull_on_drop.back() = drop.cull_on_drop.back() || c;
      continue;
    }
    drop.drop.push_back(i);
    drop.cull_on_drop.push_back(c);
  }
}

int applyKeypointDrop(Frame& frame, const KeypointDrop& drop) {
  for (size_t i = 0; i < drop.moving_evidence.size() && int(i) < frame.size(); ++i)
    if (!std::isnan(drop.moving_evidence[i]) && frame.map_points[i])
      frame.map_points[i]->moving_evidence = drop.moving_evidence[i];
  int culled = 0;
  auto cull = [&culled](const MapPointPtr& point) {
    if (!point || point->bad || point->numObservations() < 1) return;
    point->setBad();
    ++culled;
  };
  for (int i : drop.cull_vanished) cull(frame.map_points[i]);
  for (size_t k = 0; k < drop.drop.size(); ++k) {
    const int i = drop.drop[k];
    if (drop.cull_on_drop[k]) cull(frame.map_points[i]);
    frame.features.usable[i] = 0;
    frame.map_points[i].reset();
    frame.outlier[i] = 0;
  }
  return culled;
}

}  // namespace dynanav
