#include "slam/local_ba.hpp"

#include "slam/observation_noise.hpp"

namespace dynanav {

namespace {

/// Observations of the indexed points in the indexed keyframes.
void addObservations(BaProblem& problem, const LocalBaIndex& index) {
  std::map<const KeyFrame*, int> slot;
  for (size_t k = 0; k < index.keyframes.size(); ++k)
    slot[index.keyframes[k]] = static_cast<int>(k);
  problem.points.reserve(index.points.size());
  for (size_t j = 0; j < index.points.size(); ++j) {
    const MapPointPtr& p = index.points[j];
    problem.points.push_back({p->id, p->p_world});
    for (const auto& [kf, i] : p->observations) {
      const auto it = slot.find(kf);
      if (it == slot.end()) continue;
      problem.observations.push_back(
          baObservation(kf->features, i, it->second, static_cast<int>(j)));
    }
  }
}

}  // namespace

BaObservation baObservation(const Features& f, int keypoint, int keyframe_slot, int point_slot) {
  BaObservation obs;
  obs.keyframe = keyframe_slot;
  obs.point = point_slot;
  obs.keypoint = keypoint;
  obs.u = f.points[keypoint].x;
  obs.v = f.points[keypoint].y;
  obs.u_right = f.u_right[keypoint];
  obs.inv_sigma2 = f.scales->inv_sigma2[f.keypoints[keypoint].octave];
  obs.blur_sigma_px = blurSigmaPx(f, keypoint);
  return obs;
}

BaProblem buildLocalBa(KeyFrame& keyframe, LocalBaIndex& index) {
  BaProblem problem;
  const PinholeCamera& cam = *keyframe.features.camera;
  problem.camera = {cam.fx, cam.fy, cam.cx, cam.cy, cam.bf()};
  const uint64_t tag = keyframe.id;
  std::vector<KeyFrame*> local{&keyframe};
  for (KeyFrame* kf : keyframe.covisibleAtLeast(0)) {
    if (!kf->bad) local.push_back(kf);
  }
  auto add_keyframe = [&](KeyFrame* kf, bool fixed) {
    problem.keyframes.push_back({kf->id, kf->T_camera_world(), fixed || kf->id == 0});
    index.keyframes.push_back(kf);
  };
  for (KeyFrame* kf : local) {
    kf->ba_local_for_keyframe = tag;
    add_keyframe(kf, false);
  }
  for (KeyFrame* kf : local) {
    for (const auto& p : kf->map_points) {
      if (!p || p->bad || p->ba_local_for_keyframe == tag) continue;
      p->ba_local_for_keyframe = tag;
      index.points.push_back(p);
    }
  }
  // Keyframes outside the window that see window points: fixed anchors.
  for (const auto& p : index.points) {
    for (const auto& [kf, i] : p->observations) {
      if (kf->bad || kf->ba_local_for_keyframe == tag || kf->ba_fixed_for_keyframe == tag) continue;
      kf->ba_fixed_for_keyframe = tag;
      add_keyframe(kf, true);
    }
  }
  addObservations(problem, index);
  return problem;
}

void applyLocalBa(const BaProblem& problem, const BaResult& result, const LocalBaIndex& index) {
  for (size_t o = 0; o < problem.observations.size(); ++o) {
    if (!result.outlier[o]) continue;
    const auto& obs = problem.observations[o];
    KeyFrame* kf = index.keyframes[obs.keyframe];
    const MapPointPtr& p = index.points[obs.point];
    if (p->bad || kf->bad) continue;
    if (kf->map_points[obs.keypoint] == p) kf->eraseMapPoint(obs.keypoint);
    p->eraseObservation(kf);
  }
  for (size_t k = 0; k < problem.keyframes.size(); ++k) {
    if (!problem.keyframes[k].fixed && !index.keyframes[k]->bad)
      index.keyframes[k]->setPose(problem.keyframes[k].T_camera_world);
  }
  for (size_t j = 0; j < problem.points.size(); ++j) {
    const MapPointPtr& p = index.points[j];
    if (p->bad) continue;
    p->p_world = problem.points[j].p_world;
    if (!p->observations.empty())
      p->updateNormalAndDepth(*p->observations.begin()->first->features.scales);
  }
}

}  // namespace dynanav
