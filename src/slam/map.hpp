#pragma once
// The map: every keyframe and map point, ordered by id (deterministic iteration), plus the id
// counters. One mutex guards it in threaded mode: tracking holds it while it tracks a frame,
// local mapping while it changes the map (its bundle adjustment solves on a copy, unlocked).
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>

#include "slam/keyframe.hpp"
#include "slam/map_point.hpp"

namespace dynanav {

/// Issue 18: the colour camera's rolling-shutter readout, estimated by bundle adjustment together
/// with the map (tracking.rolling_shutter_online; slam/readout_shear.hpp): local mapping writes
/// it, tracking re-times each frame's keypoints with it. Guarded by the map's mutex.
struct MapReadout {
  bool estimate = false;
  double readout_s = 0.0;  ///< the estimate in use (starts at the configured readout)
  double sigma_s = std::numeric_limits<double>::infinity();  ///< its standard error
  /// A bundle adjustment's estimate replaces the one in use when its standard error is below this
  /// (a still camera's window leaves the readout undetermined).
  double adopt_sigma_s = 0.001;
  int adopted = 0;           ///< estimates adopted so far
  int window_keyframes = 0;  ///< keyframes of the adjustment that gave the one in use
};

class Map {
 public:
  MapPointPtr createPoint(const Vec3& p_world, KeyFrame* reference) {
    auto p = std::make_shared<MapPoint>(next_point_id_++, p_world, reference);
    points_.emplace(p->id, p);
    return p;
  }
  /// A map point that is not stored in the map (tracking's temporary visual-odometry points).
  MapPointPtr createTemporaryPoint(const Vec3& p_world) {
    return std::make_shared<MapPoint>(UINT64_MAX, p_world, nullptr);
  }
  uint64_t nextKeyFrameId() const { return next_keyframe_id_; }
  KeyFramePtr addKeyFrame(KeyFramePtr kf) {
    next_keyframe_id_ = std::max(next_keyframe_id_, kf->id + 1);
    keyframes_.emplace(kf->id, kf);
    return kf;
  }
  /// Culls a keyframe (KeyFrame::setBad) and drops every covisibility link left to it: links are
  /// not symmetric (as in ORB-SLAM2, a keyframe keeps its link to one that dropped it in its own
  /// last update), so setBad() cannot reach them all from the culled side, and a raw pointer left
  /// behind would dangle once nothing holds the culled keyframe and it is freed. Returns false
  /// when the keyframe may not be culled (keyframe 0, a loop's end).
  bool cullKeyFrame(KeyFrame& keyframe) {
    keyframe.setBad();
    if (!keyframe.bad) return false;
    for (const auto& [id, kf] : keyframes_) kf->eraseConnection(&keyframe);
    return true;
  }
  /// Drops bad keyframes and points from the containers (they stay alive while referenced).
  void removeBad() {
    std::erase_if(points_, [](const auto& kv) { return kv.second->bad; });
    std::erase_if(keyframes_, [](const auto& kv) { return kv.second->bad; });
  }
  [[nodiscard]] const std::map<uint64_t, KeyFramePtr>& keyframes() const { return keyframes_; }
  [[nodiscard]] const std::map<uint64_t, MapPointPtr>& points() const { return points_; }
  [[nodiscard]] size_t numKeyFrames() const { return keyframes_.size(); }
  [[nodiscard]] size_t numPoints() const { return points_.size(); }
  std::mutex& mutex() { return mutex_; }
  MapReadout readout;

 private:
  std::map<uint64_t, KeyFramePtr> keyframes_;
  std::map<uint64_t, MapPointPtr> points_;
  uint64_t next_point_id_ = 0;
  uint64_t next_keyframe_id_ = 0;
  std::mutex mutex_;
};

}  // namespace dynanav
