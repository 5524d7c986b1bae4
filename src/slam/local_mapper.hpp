#pragma once
// Local mapping (ORB-SLAM2 LocalMapping): for each new keyframe, register its observations,
// cull weak recent points, triangulate new points with covisible keyframes, fuse duplicates with
// neighbours, run local bundle adjustment and cull redundant keyframes. process() runs one
// keyframe to the end; the deterministic mode calls it inline, the threaded mode from its own
// thread (MappingThread). It takes the map lock itself, step by step, and solves the bundle
// adjustment on a copy without the lock so tracking can go on meanwhile.
#include <vector>

#include "core/config/mapping.hpp"
#include "core/timer.hpp"
#include "slam/keyframe.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct LocalMapperStats {
  int new_points_triangulated = 0;
  int points_culled = 0;
  int keyframes_culled = 0;
  int bundle_adjustments = 0;
};

class LocalMapper {
 public:
  LocalMapper(Map& map, const MappingConfig& config, StageTimers* timers = nullptr)
      : map_(map), config_(config), timers_(timers) {}

  /// Runs the whole local-mapping step for one keyframe. With `more_waiting` (keyframes queued
  /// behind it) fusion, BA and keyframe culling are skipped, as ORB-SLAM2 does to catch up.
  void process(const KeyFramePtr& keyframe, bool more_waiting = false);

  /// Bundle adjustment over the whole map (keyframe 0 fixed) at the end of a run, so that
  /// keyframes.txt and the re-anchored trajectory hold the final optimisation. No-op when
  /// mapping.final_ba_iterations is 0.
  void finalBundleAdjustment();

  [[nodiscard]] const LocalMapperStats& stats() const { return stats_; }

 private:
  void registerKeyFrame(const KeyFramePtr& keyframe);
  void cullRecentPoints(const KeyFrame& keyframe);
  void createNewPoints(KeyFrame& keyframe);
  void fuseWithNeighbours(KeyFrame& keyframe);
  void localBundleAdjustment(KeyFrame& keyframe);
  void cullRedundantKeyFrames(KeyFrame& keyframe);

  Map& map_;
  MappingConfig config_;
  StageTimers* timers_;
  std::vector<MapPointPtr> recent_points_;
  LocalMapperStats stats_;
};

}  // namespace dynanav
