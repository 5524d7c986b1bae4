#include "slam/map_point.hpp"

#include <algorithm>
#include <vector>

#include "slam/features.hpp"
#include "slam/keyframe.hpp"

namespace dynanav {

bool KeyFrameIdLess::operator()(const KeyFrame* a, const KeyFrame* b) const {
  return a->id < b->id;
}

MapPoint::MapPoint(uint64_t id_, const Vec3& p, KeyFrame* ref)
    : id(id_),
      p_world(p),
      reference(ref),
      first_keyframe_id(ref ? ref->id : 0),
      first_mapped_s(ref ? ref->stamp_s : 0.0) {}

void MapPoint::addObservation(KeyFrame* kf, int index) {
  if (observations.emplace(kf, index).second)
    weighted_observations_ += kf->features.hasDepth(index) ? 2 : 1;
}

void MapPoint::eraseObservation(KeyFrame* kf) {
  auto it = observations.find(kf);
  if (it == observations.end()) return;
  weighted_observations_ -= kf->features.hasDepth(it->second) ? 2 : 1;
  observations.erase(it);
  if (reference == kf) reference = observations.empty() ? nullptr : observations.begin()->first;
  if (weighted_observations_ <= 2) setBad();
}

void MapPoint::setBad() {
  if (bad) return;
  bad = true;
  const auto observers = std::move(observations);
  observations.clear();
  weighted_observations_ = 0;
  for (const auto& [kf, index] : observers) {
    if (kf->map_points[index].get() == this) kf->map_points[index].reset();
  }
}

void MapPoint::replaceWith(const std::shared_ptr<MapPoint>& other) {
  if (other.get() == this) return;
  const auto observers = std::move(observations);
  observations.clear();
  weighted_observations_ = 0;
  for (const auto& [kf, index] : observers) {
    if (!other->observedBy(kf)) {
      kf->map_points[index] = other;
      other->addObservation(kf, index);
    } else {
      kf->eraseMapPoint(index);
    }
  }
  other->found += found;
  other->visible += visible;
  other->updateDescriptor();
  bad = true;
  replaced_by = other;
}

void MapPoint::updateDescriptor() {
  std::vector<const uint8_t*> descs;
  descs.reserve(observations.size());
  for (const auto& [kf, index] : observations) {
    if (!kf->bad) descs.push_back(kf->features.descriptors.ptr<uint8_t>(index));
  }
  if (descs.empty()) return;
  const size_t n = descs.size();
  std::vector<int> dist(n * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      dist[i * n + j] = dist[j * n + i] = hammingDistance(descs[i], descs[j]);
  int best_median = INT32_MAX;
  size_t best = 0;
  std::vector<int> row(n);
  for (size_t i = 0; i < n; ++i) {
    std::copy(dist.begin() + i * n, dist.begin() + (i + 1) * n, row.begin());
    std::nth_element(row.begin(), row.begin() + (n - 1) / 2, row.end());
    const int median = row[(n - 1) / 2];
    if (median < best_median) {
      best_median = median;
      best = i;
    }
  }
  descriptor = cv::Mat(1, 32, CV_8U);
  std::copy(descs[best], descs[best] + 32, descriptor.ptr<uint8_t>());
}

void MapPoint::updateNormalAndDepth(const PyramidScales& scales) {
  if (observations.empty() || reference == nullptr) return;
  Vec3 sum = Vec3::Zero();
  for (const auto& [kf, index] : observations) sum += (p_world - kf->center()).normalized();
  normal = sum.normalized();
  // ORB-SLAM2: a point seen at level L from distance d is detectable from d*scale^L (finest
  // level) down to that divided by the coarsest scale.
  const double distance = (p_world - reference->center()).norm();
  const auto it = observations.find(reference);
  const int level = it != observations.end() ? reference->features.keypoints[it->second].octave : 0;
  max_distance_m = static_cast<float>(distance * scales.scale[level]);
  min_distance_m = max_distance_m / scales.scale[scales.levels - 1];
}

}  // namespace dynanav
