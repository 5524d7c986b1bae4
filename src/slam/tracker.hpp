#pragma once
// Tracking as a state machine (ORB-SLAM2 Tracking::Track for RGB-D, split into small units):
// initialise the map from the first frame with enough depth; then pose each frame by the motion
// model (or the reference keyframe), refine it against the local map, and hand new keyframes to
// local mapping. Loss is a state: lost frames are reported, and each later frame tries to
// recover against the last reference keyframe (full relocalisation is a later issue).
#include <cstdint>

#include "core/config/tracking.hpp"
#include "core/tracking_state.hpp"
#include "slam/frame.hpp"
#include "slam/local_map.hpp"
#include "slam/map.hpp"
#include "slam/mapping_stage.hpp"
#include "slam/readout_estimate.hpp"
#include "slam/readout_shear.hpp"
#include "slam/relocaliser.hpp"
#include "slam/rolling_shutter.hpp"

namespace dynanav {

struct TrackOutcome {
  TrackingState state = TrackingState::kNotInitialised;
  KeyFramePtr new_keyframe;  ///< set when this frame became a keyframe
  int inliers = 0;           ///< local-map inliers (or map points created at initialisation)
  bool recovered = false;    ///< this frame ended a loss
  KeyFramePtr reference;     ///< reference keyframe of a tracked frame (for final pose refinement)
  /// The frame's pose relative to `reference` as tracked: taken before local mapping or a loop
  /// correction moves the reference, so the refined trajectory moves the frame with it.
  SE3 T_frame_reference = SE3::Identity();
};

/// What the first tracking phase (initial pose) hands to the second (local map) for one frame.
struct InitialPose {
  bool ok = false;  ///< the frame has an initial pose: movers may be found, then the local map
  bool finished = false;  ///< nothing left to do: the map was initialised here, or could not be
  bool was_lost = false;
  bool retime = false;  ///< keypoints were re-timed for the rolling shutter with the prediction
  double readout_s = 0.0;
  bool blur = false;  ///< keypoints' motion blur was measured with the prediction
  double exposure_s = 0.0;
  /// The keypoints before re-timing (to re-time with own motion, and for the readout estimate).
  KeypointMeasurements as_read;
  /// The camera's motion from the last frame to this initial pose (interval 0: not known, e.g.
  /// after a loss); dynamics widens its depth test with it.
  CameraVelocity motion_since_last;
  TrackOutcome outcome;  ///< the result when `finished`
};

class Tracker {
 public:
  Tracker(Map& map, MappingStage& mapping, const TrackingConfig& config)
      : map_(map), mapping_(mapping), config_(config) {}

  /// Tracks one frame (its features set, id increasing): initialPose() then trackLocalMap().
  TrackOutcome track(Frame& frame);
  /// Phase 1: initialises the map from the first usable frame, or finds an initial pose by the
  /// motion model, the reference keyframe or relocalisation. Takes the map lock.
  InitialPose initialPose(Frame& frame);
  /// Phase 2 (after movers have been dropped from the frame): local-map tracking, rolling-shutter
  /// re-timing with the frame's own motion, the keyframe decision. Takes the map lock.
  TrackOutcome trackLocalMap(Frame& frame, InitialPose initial);

  [[nodiscard]] TrackingState state() const { return state_; }
  /// Issue 4: when lost, relocalise against the whole map by place recognition (nullptr: only
  /// retry the last reference keyframe).
  void setRelocaliser(const Relocaliser* relocaliser) { relocaliser_ = relocaliser; }
  [[nodiscard]] const LocalMap& localMap() const { return local_; }
  /// Issue 18: the rolling-shutter readout estimated from the tracking residuals so far.
  [[nodiscard]] const ReadoutEstimator& readoutEstimator() const { return readout_estimator_; }
  /// The online readout's updates (tracking.rolling_shutter_online): each estimate local bundle
  /// adjustment adopted (slam/readout_shear.hpp), used from `frame` on.
  [[nodiscard]] const std::vector<ReadoutStage>& onlineReadoutStages() const {
    return online_stages_;
  }
  /// The readout re-timing uses after the last update (clamped to [0, frame interval]).
  [[nodiscard]] double onlineReadoutS() const { return online_readout_s_; }

 private:
  bool initialise(Frame& frame, TrackOutcome& outcome);
  /// Re-anchors the last frame on its (possibly optimised) reference keyframe and gives it
  /// temporary points from depth so the motion model has close points to match.
  void updateLastFrame();
  /// The reference keyframe's static depth samples, placed in the world by its pose, for
  /// `frame`'s pose fits (slam/depth_surface.hpp).
  void placeReferenceDepth(Frame& frame) const;
  void rememberAsLast(const Frame& frame);
  /// Re-times the frame's keypoints (from `as_read`) and measures their motion blur with its own
  /// motion since the last frame (as `initial` asks), and re-optimises its pose; returns the
  /// local-map inliers left.
  int refineWithOwnMotion(Frame& frame, const InitialPose& initial) const;
  /// The readout to re-time this frame with: the configured or camera's value, or the latest
  /// estimate bundle adjustment adopted (tracking.rolling_shutter_online). Call with the map
  /// locked.
  double readoutFor(const Frame& frame);

  Map& map_;
  MappingStage& mapping_;
  TrackingConfig config_;
  TrackingState state_ = TrackingState::kNotInitialised;
  Frame last_;
  KeyFramePtr last_reference_;
  SE3 T_last_reference_ = SE3::Identity();  ///< last frame pose relative to its reference
  bool last_is_keyframe_ = false;
  SE3 velocity_ = SE3::Identity();    ///< T_current_last of the last tracked pair
  double velocity_interval_s_ = 0.0;  ///< time between that pair's frames
  bool has_velocity_ = false;
  KeyFramePtr reference_;
  LocalMap local_;
  uint64_t last_keyframe_frame_id_ = 0;
  const Relocaliser* relocaliser_ = nullptr;
  ReadoutEstimator readout_estimator_;
  KeyFramePtr awaiting_motion_;  ///< the map's first keyframe until the next frame gives a motion
  std::vector<ReadoutStage> online_stages_;
  double online_readout_s_ = 0.0;
  int adopted_seen_ = 0;  ///< MapReadout::adopted when online_stages_ was last extended
};

}  // namespace dynanav
