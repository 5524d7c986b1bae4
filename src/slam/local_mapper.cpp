#include "slam/local_mapper.hpp"

#include <algorithm>
#include <chrono>
#include <mutex>

#include <spdlog/spdlog.h>

#include "slam/global_ba.hpp"
#include "slam/local_ba.hpp"
#include "slam/matcher.hpp"
#include "slam/readout_shear.hpp"
#include "slam/triangulation.hpp"

namespace dynanav {

void LocalMapper::process(const KeyFramePtr& keyframe, bool more_waiting) {
  const auto start = std::chrono::steady_clock::now();
  double ba_ms = 0.0;
  {
    std::unique_lock lock(map_.mutex());
    registerKeyFrame(keyframe);
    cullRecentPoints(*keyframe);
    createNewPoints(*keyframe);
    if (!more_waiting) fuseWithNeighbours(*keyframe);
  }
  if (!more_waiting && !keyframe->bad) {
    const auto ba_start = std::chrono::steady_clock::now();
    localBundleAdjustment(*keyframe);
    ba_ms = msSince(ba_start);
    std::unique_lock lock(map_.mutex());
    cullRedundantKeyFrames(*keyframe);
  }
  {
    std::unique_lock lock(map_.mutex());
    map_.removeBad();
  }
  if (timers_) {
    // local_map: everything but the bundle adjustment, which is its own stage.
    timers_->add("local_map", msSince(start) - ba_ms);
    if (ba_ms > 0.0) timers_->add("local_ba", ba_ms);
  }
}

void LocalMapper::registerKeyFrame(const KeyFramePtr& keyframe) {
  KeyFrame& kf = *keyframe;
  const PyramidScales& scales = *kf.features.scales;
  for (int i = 0; i < static_cast<int>(kf.map_points.size()); ++i) {
    const MapPointPtr& point = kf.map_points[i];
    if (!point) continue;
    if (point->bad) {
      kf.map_points[i].reset();
      continue;
    }
    if (!point->observedBy(&kf)) {
      point->addObservation(&kf, i);
      point->updateNormalAndDepth(scales);
      point->updateDescriptor();
    } else {
      recent_points_.push_back(point);  // created from this keyframe's depth by tracking
    }
  }
  kf.updateConnections(config_.covisibility_min_weight);
}

void LocalMapper::cullRecentPoints(const KeyFrame& keyframe) {
  // ORB-SLAM2 MapPointCulling: a new point must be found in at least a quarter of the frames
  // that should see it, and be seen by enough keyframes two keyframes after its creation.
  std::vector<MapPointPtr> kept;
  for (const auto& point : recent_points_) {
    if (point->bad) continue;
    const uint64_t age = keyframe.id - point->first_keyframe_id;
    if (point->foundRatio() < config_.recent_point_min_found_ratio ||
        (age >= 2 && point->numObservations() <= config_.recent_point_min_observations)) {
      point->setBad();
      ++stats_.points_culled;
    } else if (age < 3) {
      kept.push_back(point);
    }
  }
  recent_points_ = std::move(kept);
}

void LocalMapper::createNewPoints(KeyFrame& keyframe) {
  const auto created = triangulateWithNeighbours(keyframe, map_, config_.triangulation_neighbours);
  stats_.new_points_triangulated += static_cast<int>(created.size());
  recent_points_.insert(recent_points_.end(), created.begin(), created.end());
}

void LocalMapper::fuseWithNeighbours(KeyFrame& keyframe) {
  // Neighbours and their neighbours (ORB-SLAM2 SearchInNeighbors), each once.
  std::vector<KeyFrame*> targets;
  keyframe.fuse_target_keyframe = keyframe.id;
  for (KeyFrame* n : keyframe.bestCovisible(config_.fuse_neighbours)) {
    if (n->bad || n->fuse_target_keyframe == keyframe.id) continue;
    n->fuse_target_keyframe = keyframe.id;
    targets.push_back(n);
  }
  const size_t first_ring = targets.size();
  for (size_t k = 0; k < first_ring; ++k) {
    for (KeyFrame* n2 : targets[k]->bestCovisible(5)) {
      if (n2->bad || n2->fuse_target_keyframe == keyframe.id) continue;
      n2->fuse_target_keyframe = keyframe.id;
      targets.push_back(n2);
    }
  }
  // This keyframe's points into the neighbours...
  for (KeyFrame* target : targets) {
    std::vector<MapPointPtr> points = keyframe.map_points;
    matcher::fuse(*target, points, 3.0f);
  }
  // ...and the neighbours' points into this keyframe.
  std::vector<MapPointPtr> candidates;
  for (KeyFrame* target : targets) {
    for (const auto& p : target->map_points) {
      if (!p || p->bad || p->fuse_target_keyframe == keyframe.id) continue;
      p->fuse_target_keyframe = keyframe.id;
      candidates.push_back(p);
    }
  }
  matcher::fuse(keyframe, candidates, 3.0f);
  const PyramidScales& scales = *keyframe.features.scales;
  for (const auto& p : keyframe.map_points) {
    if (!p || p->bad) continue;
    p->updateDescriptor();
    p->updateNormalAndDepth(scales);
  }
  keyframe.updateConnections(config_.covisibility_min_weight);
}

void LocalMapper::localBundleAdjustment(KeyFrame& keyframe) {
  BaProblem problem;
  LocalBaIndex index;
  {
    std::unique_lock lock(map_.mutex());
    if (map_.numKeyFrames() <= 2) return;
    problem = buildLocalBa(keyframe, index);
    if (map_.readout.estimate)
      addReadoutShear(problem, {index.keyframes.begin(), index.keyframes.end()},
                      map_.readout.readout_s);
  }
  BaOptions options;
  options.iterations_first = config_.ba_iterations_first;
  options.iterations_second = config_.ba_iterations_second;
  options.linear_solver = config_.ba_linear_solver;
  const BaResult result = bundleAdjust(problem, options);
  spdlog::debug("local BA kf {}: {} keyframes, {} points, {} observations, rms {:.3f} -> {:.3f} px",
                keyframe.id, problem.keyframes.size(), problem.points.size(),
                problem.observations.size(), result.initial_rms_px, result.final_rms_px);
  const double readout_sigma_s = readoutSigmaS(problem, result.outlier);  // without the lock
  std::unique_lock lock(map_.mutex());
  applyLocalBa(problem, result, index);
  adoptReadout(map_, problem, readout_sigma_s);
  ++stats_.bundle_adjustments;
}

void LocalMapper::finalBundleAdjustment() {
  if (config_.final_ba_iterations <= 0) return;
  {
    std::unique_lock lock(map_.mutex());
    if (map_.numKeyFrames() < 2) return;
  }
  const auto start = std::chrono::steady_clock::now();
  BaOptions options;
  options.iterations_first = config_.final_ba_iterations;
  options.iterations_second = config_.final_ba_iterations;
  options.linear_solver = config_.ba_linear_solver;
  const GlobalBaRun run = runGlobalBa(map_, options);
  spdlog::debug("final BA: {} keyframes, {} points, rms {:.3f} -> {:.3f} px", run.keyframes,
                run.points, run.result.initial_rms_px, run.result.final_rms_px);
  if (timers_) timers_->add("final_ba", msSince(start));
}

void LocalMapper::cullRedundantKeyFrames(KeyFrame& keyframe) {
  const int min_observers = config_.redundant_min_observers;
  for (KeyFrame* kf : keyframe.covisibleAtLeast(0)) {
    if (kf->id == 0 || kf->bad) continue;
    const Features& f = kf->features;
    const double close_depth = f.camera->closeDepthThreshold();
    int points = 0, redundant = 0;
    for (int i = 0; i < static_cast<int>(kf->map_points.size()); ++i) {
      const MapPointPtr& p = kf->map_points[i];
      if (!p || p->bad) continue;
      // RGB-D: only close points count, far ones say little about the keyframe's value.
      if (f.depth_m[i] > close_depth || f.depth_m[i] < 0.f) continue;
      ++points;
      if (p->numObservations() <= min_observers) continue;
      const int level = f.keypoints[i].octave;
      int observers = 0;
      for (const auto& [other, j] : p->observations) {
        if (other == kf) continue;
        if (other->features.keypoints[j].octave <= level + 1 && ++observers >= min_observers) break;
      }
      if (observers >= min_observers) ++redundant;
    }
    if (redundant > config_.redundant_keyframe_ratio * points) {
      if (map_.cullKeyFrame(*kf)) ++stats_.keyframes_culled;
    }
  }
}

}  // namespace dynanav
