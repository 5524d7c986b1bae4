#pragma once
// The SLAM facade (DESIGN.md §1 steps 3-6 and 10): it owns the map and its lock, the ORB
// extractor, the tracker, the local-mapping stage, place recognition, the loop closer and the
// per-frame anchors, and knows their shutdown order. The pipeline calls its phases in order and
// puts mover rejection (dynamics) between the initial pose and the local map; every lock is
// taken in here, never by the caller.
#include <memory>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/timer.hpp"
#include "io/trajectory.hpp"
#include "slam/depth_surface.hpp"
#include "slam/frame.hpp"
#include "slam/keypoint_drop.hpp"
#include "slam/local_mapper.hpp"
#include "slam/tracker.hpp"
#include "slam/trajectory_anchors.hpp"

namespace dynanav {

class OrbExtractor;
class Map;
class MappingStage;
class Vocabulary;
class PlaceIndex;
class Relocaliser;
class LoopCloser;
struct LoopEvent;
struct PyramidScales;

class SlamSystem {
 public:
  /// `timers` (may be null) receives local mapping's stage times.
  SlamSystem(const Config& config, const PinholeCamera& camera, StageTimers* timers);
  ~SlamSystem();
  SlamSystem(const SlamSystem&) = delete;
  SlamSystem& operator=(const SlamSystem&) = delete;

  /// 3. ORB features of a grey image where `allowed` (CV_8U, empty = everywhere) permits.
  Frame extract(const cv::Mat& grey, const cv::Mat& depth_m, double stamp_s,
                const cv::Mat& allowed);
  /// 4. Initial pose (motion model, reference keyframe or relocalisation), or map initialisation.
  InitialPose initialPose(Frame& frame);
  /// For 5, under one map lock: the depth of each keypoint's matched map point in the frame's
  /// camera (0 = no usable match); with `evidence`, each point's moving evidence (NaN = none);
  /// with `residual_min_established` > 0, each match's residual against a pose refitted to the
  /// established points (slam/established_residuals.hpp), and with `background` too against a
  /// pose refitted to the established points outside every instance.
  [[nodiscard]] MapPointChecks moverChecks(const Frame& frame, bool evidence,
                                           int residual_min_established,
                                           bool background = false) const;
  /// 5. Applies mover rejection's decision; returns the map points culled.
  int applyDrop(Frame& frame, const KeypointDrop& drop);
  /// 6. Local-map tracking on the static points left, and the keyframe decision.
  TrackOutcome trackLocalMap(Frame& frame, InitialPose initial);
  /// 10. Local mapping of the new keyframes (inline in deterministic mode), then remembers the
  /// frame's anchor on its reference keyframe for the refined trajectory, and moves anchors off
  /// keyframes culled meanwhile so those can be freed.
  void finishFrame(const Frame& frame, const TrackOutcome& outcome);
  /// Drains local mapping, joins a running global BA, then runs the final whole-map BA
  /// (idempotent).
  void finish();

  /// Keyframe poses (T_world_camera) ordered by time, as optimised so far.
  [[nodiscard]] std::vector<StampedPose> keyframePoses() const;
  /// Every tracked frame's pose re-anchored on its reference keyframe as that is now (after
  /// later bundle adjustments), as ORB-SLAM2 saves its trajectory.
  [[nodiscard]] std::vector<StampedPose> refinedTrajectory() const;
  [[nodiscard]] LocalMapperStats mappingStats() const;
  [[nodiscard]] size_t numMapPoints() const;
  [[nodiscard]] size_t numKeyFrames() const;
  /// Issue 18: the rolling-shutter readout estimated from the tracking residuals (since the last
  /// adopted readout when online), the readouts bundle adjustment adopted online, and the readout
  /// configured (tracking key, else the camera's).
  [[nodiscard]] const ReadoutEstimator& readoutEstimator() const {
    return tracker_->readoutEstimator();
  }
  [[nodiscard]] const std::vector<ReadoutStage>& onlineReadoutStages() const {
    return tracker_->onlineReadoutStages();
  }
  [[nodiscard]] double onlineReadoutS() const { return tracker_->onlineReadoutS(); }
  [[nodiscard]] bool readoutOnline() const { return config_.tracking.rolling_shutter_online; }
  [[nodiscard]] double configuredReadoutS() const {
    return config_.tracking.rolling_shutter_readout_ms >= 0.0
               ? config_.tracking.rolling_shutter_readout_ms * 1e-3
               : camera_->readout_s;
  }
  /// Loops closed so far (issue 4); empty when loop closing is off or has no vocabulary.
  [[nodiscard]] std::vector<LoopEvent> loops() const;
  /// Why relocalisation and loop closing are off ("" when the vocabulary loaded): the run's
  /// stats say so, since a run without them loses the camera for good in places it could
  /// have recovered.
  [[nodiscard]] const std::string& placeRecognitionOffReason() const {
    return place_recognition_off_;
  }

 private:
  /// Issue 4: vocabulary, keyframe database, relocaliser and loop closer, if the vocabulary loads.
  void setUpPlaceRecognition();

  Config config_;
  std::shared_ptr<const PinholeCamera> camera_;
  std::shared_ptr<const PyramidScales> scales_;
  std::unique_ptr<OrbExtractor> extractor_;
  std::unique_ptr<DepthSurfaceMaker> surfaces_;  ///< when depth poses frames too
  std::unique_ptr<Map> map_;
  std::unique_ptr<MappingStage> mapping_;
  std::unique_ptr<Tracker> tracker_;
  // Place recognition (issue 4); declared after the map and stages so they go first.
  std::shared_ptr<const Vocabulary> vocabulary_;
  std::unique_ptr<PlaceIndex> places_;
  std::unique_ptr<Relocaliser> relocaliser_;
  std::unique_ptr<LoopCloser> loop_closer_;
  std::string place_recognition_off_;
  uint64_t next_frame_id_ = 0;
  bool finished_ = false;
  TrajectoryAnchors anchors_;  ///< one per tracked frame
};

}  // namespace dynanav
