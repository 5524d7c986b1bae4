#pragma once
// A 3D landmark (ORB-SLAM2 MapPoint): position, representative descriptor, mean viewing
// direction, scale-invariance distance range, and the keyframes observing it (ordered by
// keyframe id for determinism). Keyframes own their points by shared_ptr; points refer back to
// keyframes by raw pointer, which the Map keeps valid by erasing observations of culled keyframes.
#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>

#include "core/se3.hpp"
#include "slam/pyramid.hpp"

namespace dynanav {

class KeyFrame;

struct KeyFrameIdLess {
  bool operator()(const KeyFrame* a, const KeyFrame* b) const;
};

class MapPoint {
 public:
  MapPoint(uint64_t id, const Vec3& p_world, KeyFrame* reference);

  const uint64_t id;
  Vec3 p_world;
  Vec3 normal = Vec3::Zero();  ///< mean unit viewing direction (point minus camera centre)
  cv::Mat descriptor;          ///< 1 x 32, the observation closest to all others
  float min_distance_m = 0.f;  ///< scale-invariance range (ORB-SLAM2 mfMinDistance)
  float max_distance_m = 0.f;
  KeyFrame* reference = nullptr;
  uint64_t first_keyframe_id = 0;
  double first_mapped_s = 0.0;  ///< stamp of the keyframe that mapped it (slam/persistent_pose)
  std::map<KeyFrame*, int, KeyFrameIdLess> observations;  ///< keyframe -> keypoint index
  int visible = 1;                                        ///< frames in whose frustum it was
  int found = 1;                                          ///< frames in which it was matched
  bool bad = false;
  std::shared_ptr<MapPoint> replaced_by;  ///< set when fused into another point
  /// Log-odds evidence (without the prior) that the point lies on something that moves, from the
  /// depth tests of the frames that matched it (dynamics/moving_evidence.hpp). Tracking only.
  float moving_evidence = 0.f;

  // Scratch written by tracking for the current frame (ORB-SLAM2 mbTrackInView & co.).
  bool track_in_view = false;
  float track_u = 0.f, track_v = 0.f, track_u_right = 0.f;
  int track_level = 0;
  float track_view_cos = 0.f;
  uint64_t last_seen_frame = UINT64_MAX;  ///< frame id that matched it
  uint64_t local_for_frame = UINT64_MAX;  ///< frame id whose local map holds it
  uint64_t ba_local_for_keyframe = UINT64_MAX;
  uint64_t fuse_target_keyframe = UINT64_MAX;

  /// ORB-SLAM2's observation count: an observation with depth counts twice (it constrains the
  /// point like a stereo pair). All thresholds on observations use this count.
  [[nodiscard]] int numObservations() const { return weighted_observations_; }
  [[nodiscard]] bool observedBy(const KeyFrame* kf) const {
    return observations.count(const_cast<KeyFrame*>(kf)) > 0;
  }
  [[nodiscard]] float foundRatio() const { return static_cast<float>(found) / visible; }
  [[nodiscard]] int predictLevel(double distance_m, const PyramidScales& scales) const {
    return scales.predictLevel(max_distance_m, distance_m);
  }

  void addObservation(KeyFrame* kf, int index);
  /// Removes kf's observation; the point is set bad when what is left is weaker than two
  /// monocular views (an observation with depth counts twice, as in ORB-SLAM2).
  void eraseObservation(KeyFrame* kf);
  /// Marks the point bad and removes it from every observing keyframe.
  void setBad();
  /// Moves this point's observations to `other` and marks this one replaced (ORB-SLAM2 Replace).
  void replaceWith(const std::shared_ptr<MapPoint>& other);
  /// Picks the observation descriptor with the least median distance to the others.
  void updateDescriptor();
  /// Recomputes the mean viewing direction and scale-invariance distances.
  void updateNormalAndDepth(const PyramidScales& scales);

 private:
  int weighted_observations_ = 0;
};

using MapPointPtr = std::shared_ptr<MapPoint>;

/// Follows replaced_by links to the point that now stands for `p` (nullptr stays nullptr).
inline MapPointPtr resolveReplaced(MapPointPtr p) {
  while (p && p->replaced_by) p = p->replaced_by;
  return p;
}

}  // namespace dynanav
