#include "slam/global_ba.hpp"

#include "slam/local_ba.hpp"
#include "slam/readout_shear.hpp"

namespace dynanav {

GlobalBaSnapshot buildGlobalBa(const Map& map) {
  GlobalBaSnapshot s;
  std::map<const KeyFrame*, int> slot;
  for (const auto& [id, kf] : map.keyframes()) {
    if (kf->bad) continue;
    if (s.keyframes.empty()) {
      const PinholeCamera& cam = *kf->features.camera;
      s.problem.camera = {cam.fx, cam.fy, cam.cx, cam.cy, cam.bf()};
    }
    slot[kf.get()] = static_cast<int>(s.keyframes.size());
    s.problem.keyframes.push_back({kf->id, kf->T_camera_world(), kf->id == 0});
    s.keyframes.push_back(kf);
  }
  for (const auto& [id, p] : map.points()) {
    if (p->bad) continue;
    const int j = static_cast<int>(s.points.size());
    bool any = false;
    for (const auto& [kf, i] : p->observations) {
      const auto it = slot.find(kf);
      if (it == slot.end()) continue;
      s.problem.observations.push_back(baObservation(kf->features, i, it->second, j));
      any = true;
    }
    if (!any) continue;
    s.problem.points.push_back({p->id, p->p_world});
    s.points.push_back(p);
  }
  // The readout is estimated here too, so that the whole map's points end where the local windows
  // put them (not adopted: tracking has ended, or goes on with the local windows' estimate).
  if (map.readout.estimate) {
    std::vector<const KeyFrame*> keyframes;
    for (const auto& kf : s.keyframes) keyframes.push_back(kf.get());
    addReadoutShear(s.problem, keyframes, map.readout.readout_s);
  }
  return s;
}

void applyGlobalBa(const GlobalBaSnapshot& s, const BaResult& result, Map& map) {
  for (size_t o = 0; o < s.problem.observations.size(); ++o) {
    if (result.outlier.empty() || !result.outlier[o]) continue;
    const auto& obs = s.problem.observations[o];
    KeyFrame* kf = s.keyframes[obs.keyframe].get();
    const MapPointPtr& p = s.points[obs.point];
    if (p->bad || kf->bad) continue;
    if (kf->map_points[obs.keypoint] == p) kf->eraseMapPoint(obs.keypoint);
    p->eraseObservation(kf);
  }
  // Old and new pose of every keyframe that moved: the snapshot's, then (in id order, so parents
  // come first) those created meanwhile, carried along with their parent.
  // Keyed by address, never dereferenced through the key: a point's reference may be culled.
  std::map<KeyFrame*, std::pair<SE3, SE3>> moved;  // T_camera_world before, after
  for (size_t k = 0; k < s.keyframes.size(); ++k) {
    KeyFrame* kf = s.keyframes[k].get();
    if (kf->bad) continue;
    moved[kf] = {kf->T_camera_world(), s.problem.keyframes[k].T_camera_world};
  }
  for (const auto& [id, kf] : map.keyframes()) {
    if (kf->bad || moved.count(kf.get())) continue;
    const auto parent = kf->parent ? moved.find(kf->parent) : moved.end();
    if (parent == moved.end()) continue;
    const SE3 T_child_parent = kf->T_camera_world() * parent->second.first.inverse();
    moved[kf.get()] = {kf->T_camera_world(), T_child_parent * parent->second.second};
  }
  std::map<const MapPoint*, size_t> in_snapshot;
  for (size_t j = 0; j < s.points.size(); ++j) in_snapshot[s.points[j].get()] = j;
  for (const auto& [id, p] : map.points()) {
    if (p->bad) continue;
    const auto it = in_snapshot.find(p.get());
    if (it != in_snapshot.end()) {
      p->p_world = s.problem.points[it->second].p_world;
    } else if (p->reference) {
      const auto ref = moved.find(p->reference);
      if (ref == moved.end()) continue;
      // Same place in the reference camera before and after.
      p->p_world = ref->second.second.inverse() * (ref->second.first * p->p_world);
    }
    if (!p->observations.empty())
      p->updateNormalAndDepth(*p->observations.begin()->first->features.scales);
  }
  for (const auto& [kf, poses] : moved) kf->setPose(poses.second);
}

GlobalBaRun runGlobalBa(Map& map, const BaOptions& options) {
  GlobalBaSnapshot snapshot;
  {
    std::unique_lock lock(map.mutex());
    snapshot = buildGlobalBa(map);
  }
  GlobalBaRun run;
  run.keyframes = snapshot.problem.keyframes.size();
  run.points = snapshot.problem.points.size();
  run.result = bundleAdjust(snapshot.problem, options);  // without the lock: tracking goes on
  std::unique_lock lock(map.mutex());
  applyGlobalBa(snapshot, run.result, map);
  map.removeBad();
  return run;
}

}  // namespace dynanav
