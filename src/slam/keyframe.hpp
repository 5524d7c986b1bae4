#pragma once
// A keyframe (ORB-SLAM2 KeyFrame): the frame's features, its pose, the map points its keypoints
// observe, and its place in the covisibility graph and spanning tree. Graph links are raw
// pointers ordered by keyframe id; the Map owns keyframes (shared_ptr) and unlinks culled ones.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "core/se3.hpp"
#include "slam/features.hpp"
#include "slam/map_point.hpp"
#include "slam/rolling_shutter.hpp"
#include "slam/vocabulary/bow_vector.hpp"

namespace dynanav {

class KeyFrame : public std::enable_shared_from_this<KeyFrame> {
 public:
  KeyFrame(uint64_t id, uint64_t frame_id, double stamp_s, Features features,
           const SE3& T_camera_world, std::vector<MapPointPtr> map_points);
  ~KeyFrame();
  KeyFrame(const KeyFrame&) = delete;
  KeyFrame& operator=(const KeyFrame&) = delete;
  /// KeyFrame objects alive in this process, culled ones still held included: beside the map's
  /// count it shows whether culled keyframes (and the features, words and points they hold) are
  /// freed over a long run.
  [[nodiscard]] static int64_t instances();

  const uint64_t id;
  const uint64_t frame_id;
  const double stamp_s;
  const Features features;
  std::vector<MapPointPtr> map_points;  ///< per keypoint, nullptr where none

  [[nodiscard]] const SE3& T_camera_world() const { return T_camera_world_; }
  [[nodiscard]] const SE3& T_world_camera() const { return T_world_camera_; }
  [[nodiscard]] Vec3 center() const { return T_world_camera_.translation(); }
  void setPose(const SE3& T_camera_world) {
    T_camera_world_ = T_camera_world;
    T_world_camera_ = T_camera_world.inverse();
  }

  // Covisibility graph (ORB-SLAM2 UpdateConnections): weight = shared map points.
  std::map<KeyFrame*, int, KeyFrameIdLess> connections;
  std::vector<KeyFrame*> ordered_covisible;  ///< by weight desc, then id
  std::vector<int> ordered_weights;
  KeyFrame* parent = nullptr;  ///< spanning tree
  /// Set when culled: the parent and the pose relative to it (ORB-SLAM2 mTcp), owning, so frames
  /// anchored on a culled keyframe can still follow later corrections of the tree.
  std::shared_ptr<KeyFrame> parent_when_culled;
  SE3 T_camera_parent = SE3::Identity();
  std::set<KeyFrame*, KeyFrameIdLess> children;
  bool bad = false;

  /// Issue 18: the camera's motion over the frame interval when this keyframe was taken
  /// (interval 0: not known yet) and the readout its keypoints were re-timed with. A wrong readout
  /// shifts the map points it creates along that motion; the readout estimate models the shift.
  CameraVelocity motion;
  double readout_used_s = 0.0;
  /// How this keyframe's fitted pose moved per second of readout error, (rho, phi) on the left
  /// (ReadoutEvidence::pose_shift_per_s): its map points moved with it.
  Eigen::Matrix<double, 6, 1> pose_shift_per_readout = Eigen::Matrix<double, 6, 1>::Zero();
  /// Issue 18: its frame's static depth, sampled (camera frame; slam/depth_surface.hpp). Frames
  /// that take it as their reference are also posed by it, placed in the world by its pose.
  std::vector<Vec3> depth_samples_camera;

  // Place recognition (issue 4, loop/relocalisation): bag of words and direct index, computed
  // once when the keyframe enters the keyframe database; loop edges join the two keyframes of a
  // closed loop in the essential graph.
  BowVector bow;
  FeatureVector bow_features;
  std::set<KeyFrame*, KeyFrameIdLess> loop_edges;

  // Scratch for tracking and local mapping.
  uint64_t local_for_frame = UINT64_MAX;
  uint64_t ba_local_for_keyframe = UINT64_MAX;
  uint64_t ba_fixed_for_keyframe = UINT64_MAX;
  uint64_t fuse_target_keyframe = UINT64_MAX;

  /// Recomputes this keyframe's covisibility links from its map points and updates the other
  /// side; on the first call also picks the spanning-tree parent (strongest link).
  void updateConnections(int min_weight);
  void addConnection(KeyFrame* other, int weight);
  void eraseConnection(KeyFrame* other);
  [[nodiscard]] std::vector<KeyFrame*> bestCovisible(int n) const;
  [[nodiscard]] std::vector<KeyFrame*> covisibleAtLeast(int weight) const;
  /// Map points observed by at least `min_observations` keyframes.
  [[nodiscard]] int trackedMapPoints(int min_observations) const;
  void eraseMapPoint(int index) { map_points[index].reset(); }
  void eraseMapPoint(const MapPoint* point);
  /// Marks the keyframe bad: unlinks it from the graph and from its points' observations, and
  /// re-parents its children. Keyframe 0 is never culled.
  void setBad();

 private:
  void sortConnections();
  SE3 T_camera_world_;
  SE3 T_world_camera_;
  bool first_connection_ = true;
  static std::atomic<int64_t> instances_;
};

using KeyFramePtr = std::shared_ptr<KeyFrame>;

}  // namespace dynanav

namespace dynanav {

/// Current world-to-camera pose of a frame tracked at T_frame_reference relative to `reference`,
/// following culled keyframes up the spanning tree (how ORB-SLAM2 writes its final trajectory).
inline SE3 anchoredPose(const KeyFrame& reference, const SE3& T_frame_reference) {
  SE3 T = T_frame_reference;
  const KeyFrame* kf = &reference;
  while (kf->bad && kf->parent_when_culled) {
    T = T * kf->T_camera_parent;
    kf = kf->parent_when_culled.get();
  }
  return T * kf->T_camera_world();
}

}  // namespace dynanav
