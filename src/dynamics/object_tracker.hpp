#pragma once
// Step 8 of the per-frame story (DESIGN.md §1): tracks every instance over the run with an id
// that stays (mask overlap with the track's last mask plus the votes of its flow-carried points;
// ids are never reused), estimates each object's rigid motion from its points
// (object_motion.hpp), filters centre and velocity with a constant-velocity Kalman filter
// (kalman_cv.hpp) and reports TrackedObjects with covariance and a predicted path. An object the
// segmenter misses is carried by its points for up to max_missed_frames. Objects not found
// moving (a seated person, a chair) get position, distance and bearing with zero velocity.
// Values in, values out: the pipeline gives this frame's instances, the dynamics verdicts, the
// shared flow, depth and camera pose.
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/camera.hpp"
#include "core/config/dynamics.hpp"
#include "core/config/objects.hpp"
#include "core/se3.hpp"
#include "core/tracked_object.hpp"
#include "dynamics/first_motion.hpp"
#include "dynamics/floor_plane.hpp"
#include "dynamics/frame_dynamics.hpp"
#include "dynamics/kalman_cv.hpp"
#include "dynamics/object_flow.hpp"
#include "dynamics/object_points.hpp"
#include "perception/instances.hpp"

namespace dynanav {

struct ObjectTrackerInput {
  int frame_index = 0;
  double stamp_s = 0.0;
  const Instances& instances;
  const FrameDynamics& dynamics;  ///< moving_ids / static_ids of this frame's instances
  const cv::Mat& flow_half;       ///< previous -> this frame, half-size pixels (may be empty)
  const cv::Mat& depth_m;         ///< CV_32F
  const SE3& T_world_camera;
  bool tracked = false;  ///< camera pose valid: without it no motion is estimated
  const PinholeCamera& camera;
  /// This frame's half-size grey image (FramePrep's grey_half): each object's own flow
  /// (object_flow.hpp) is computed on it and the last frame's. Empty: the shared flow alone.
  cv::Mat grey_half = {};
};

class ObjectTracker {
 public:
  /// `prior_dynamic_classes`: classes that move by themselves (people): a track of another class
  /// (a chair, a box) is static until the dynamics stage finds it moving.
  ObjectTracker(
      const ObjectTrackingConfig& config, int sample_step_px,
      std::vector<std::string> prior_dynamic_classes = DynamicsConfig{}.prior_dynamic_classes);
  std::vector<TrackedObject> track(const ObjectTrackerInput& input);
  [[nodiscard]] size_t liveTracks() const { return tracks_.size(); }

 private:
  struct Track {
    uint64_t id = 0;
    std::string class_name;
    bool prior_dynamic = true;        // a class that moves by itself (prior_dynamic_classes)
    std::vector<cv::Point2f> pixels;  // in the last frame
    std::vector<Vec3> p_world;        // lifted with the last frame's depth
    // Per point: a nearer surface within the flow's reach of it in the last frame, whose motion
    // the flow that carries it into this one carries too (left out of the motion fit, or, when
    // it is a mover, no fit at all: object_tracker.cpp).
    std::vector<NearerSurface> beside_nearer;
    // Sampled pixels without usable depth (a walker beyond the sensor's range): carried by the
    // flow only to vote in the association, so such a track survives a missed frame.
    std::vector<cv::Point2f> voters;
    uint16_t instance = 0;  // label in the last frame (0: carried)
    bool trunk = false;     // the points are a person's trunk
    // Side of the image (-1 left, +1 right, 0 none) that cut the object when the segmenter last
    // saw it: carried points are that frame's sample, so its centre stays as partial.
    int cut_side = 0;
    double depth_share = 1.0;  // share of the sampled mask pixels with usable depth
    KalmanCv filter;
    SE3 motion = SE3::Identity();  // last frame's rigid motion (the next frame's prior)
    int missed = 0;
    int still = 0;            // frames in a row not found moving
    bool stationary = false;  // reported with zero velocity
    int points_moving = 0;    // frames in a row whose points' rigid motion was not slow
    int points_slow = 0;      // frames in a row whose points' rigid motion was slow
    // How far the points' rigid motion has read the filtered speed (within a factor of 1.5) in
    // the frames before any slow ones, counted up and down: whether the points are to be
    // believed when they read a stop.
    int points_agree = 0;
    int inliers = 0;
    int whole_centre_frames = 0;  // frames in a row whose centre was measured whole
    // A new person track, not held still, whose filter has not yet been given a walker's speed
    // as the prior of its speed (applyWalkingSpeedPrior).
    bool walking_prior_pending = false;
    // > 0: every centre the filter has heard came from the height range (height_range.hpp), so
    // they share one error, the stature's (this relative sigma), which the filter was not told of
    // (it would have averaged it as if new in every frame); reported beside the filter's
    // covariance and handed to the filter when depth first places the person.
    double ranged_scale_sigma = 0.0;
    // Its height ranges read a range-rate no walker has (beyond a new track's velocity prior at
    // 99.9 %): the mask's height is not the person's (a far mask losing head and feet to
    // erosion), so no more ranges for it until depth places it.
    bool ranges_refuted = false;
    // Which part of the object the last centre measured (object_tracker.cpp, reanchoring); none:
    // no centre yet.
    struct CentreRule {
      int cut_side = 0;
      bool trunk = false;
      bool little_depth = false;  // most of its sample without usable depth
      bool ranged = false;        // placed by its height (height_range.hpp): the whole person
      bool operator==(const CentreRule&) const = default;
    };
    std::optional<CentreRule> centre_rule;
    bool reanchored = false;  // TrackedObject::reanchored, this frame
    bool restarted = false;   // the filter started afresh this frame at a centre it could not reach
    double last_stamp_s = 0.0;
  };
  struct Carried {  // one track's points carried into this frame
    std::vector<Vec3> p_prev_world;
    std::vector<NearerSurface> beside_nearer;  // Track::beside_nearer of each
    std::vector<Eigen::Vector2d> pixels;
    std::vector<Eigen::Vector2d> voters;  // Track::voters carried (no 3D)
  };

  std::vector<int> associate(const ObjectTrackerInput& input, const std::vector<Carried>& carried);
  /// The track's points carried into this frame by the shared flow, or where `own` covers them
  /// by its own (the voters always by the shared flow).
  static Carried carry(const Track& track, const ObjectTrackerInput& input,
                       const CroppedFlow* own = nullptr);
  /// The object's own flow from its last mask to `instance`'s (object_flow.hpp); empty when off
  /// or without the last frame's image.
  CroppedFlow ownFlow(const Track& track, const Instance& instance,
                      const ObjectTrackerInput& input);
  void update(Track& track, const Carried& carried, const Instance* instance,
              const ObjectTrackerInput& input);
  /// Moving or standing after this frame's update (track.still, track.stationary; a held track's
  /// filter held still, a released person's reopened): from the dynamics stage's verdict on
  /// `instance`, the points' motion along the floor `v_walk` (none: no rigid motion this frame)
  /// and the filter (object_tracker_still.cpp).
  void judgeStill(Track& track, const Instance* instance, const std::optional<Vec3>& v_walk,
                  bool verified_static, const ObjectTrackerInput& input);
  std::optional<Track> start(const Instance& instance, const ObjectTrackerInput& input);
  /// The track ends while out of the camera's view: its centre projects outside the image (or
  /// behind the camera), or the image's side cut it when it was last seen.
  [[nodiscard]] bool leftView(const Track& track, const ObjectTrackerInput& input) const;
  /// The id of a remembered track that left the view (recall_out_of_view_s) of `class_name` that
  /// could have got to `p_world` by `stamp_s` (taken out of the memory); none when none could.
  std::optional<uint64_t> recall(const std::string& class_name, const Vec3& p_world,
                                 double stamp_s);
  /// Which part of the object this frame's centre measures (`seen`: the segmenter saw it;
  /// `ranged`: placed by the height range).
  [[nodiscard]] Track::CentreRule centreRule(const Track& track, bool seen, bool ranged) const;
  /// The filter's velocity has been narrowed from its prior (0 +- 1 m/s) by measurements.
  [[nodiscard]] bool filterVelocityKnown(const Track& track) const;
  /// Slower than `static_speed_mps`: what a standing object's jitter reads (NaN is not slow).
  [[nodiscard]] bool isSlow(const Vec3& v_mps) const;
  /// The filter's velocity is known and slow: the track stands (or its heading says nothing).
  [[nodiscard]] bool filterKnownSlow(const Track& track) const;
  /// The floor's up in the world, when the floor is known (floor_).
  [[nodiscard]] std::optional<Vec3> upWorld(const ObjectTrackerInput& input) const;
  /// A new person track walks at a walker's speed: once its filter holds a velocity measured
  /// from its points, clearly one way in the floor's plane but not yet known, its speed along
  /// that direction is told walking_speed_mps +- walking_speed_sigma_mps, once (the prior a
  /// zero-mean velocity lacks). Waits while the floor is unknown or the direction is not clear.
  void applyWalkingSpeedPrior(Track& track, const std::optional<Vec3>& up_world) const;
  /// The EPnP-RANSAC and refinement settings of this frame's motion of track `id`.
  [[nodiscard]] ObjectMotionOptions motionOptions(int frame_index, uint64_t id) const;
  /// The configured noise of the filter of a track of `class_name` (a new track, or one restarted
  /// at a centre).
  [[nodiscard]] KalmanCvNoise filterNoise(const std::string& class_name) const;
  /// A velocity no walker has: outside a new track's prior (0 +- 1 m/s per axis) at 99.9 %.
  [[nodiscard]] static bool beyondWalkersSpeed(const Vec3& v_world_mps);
  struct Centre {
    Vec3 p_camera;
    std::optional<Mat3> cov_world;  ///< measurement noise (m^2); none: the configured one
    /// From the height range: relative sigma of the stature, an error common to all frames and
    /// not in cov_world (0: not from the height range).
    double scale_sigma = 0.0;
    bool depth_measured = false;  ///< its distance is measured (by depth or the height range)
  };
  /// The object's centre from its points (camera frame), with the components its visible part
  /// does not measure marked unknown.
  std::optional<Centre> measureCentre(const Track& track, const std::vector<Vec3>& p_camera,
                                      const Instance* instance,
                                      const ObjectTrackerInput& input) const;
  /// |cos| of the angle between a ranged person's level heading (its filter's velocity) and the
  /// level viewing direction to `p_camera`; none while it stands or its velocity is not known
  /// (height_range.hpp, footLeadM).
  [[nodiscard]] std::optional<double> headingAbsCos(const Track& track, const Vec3& p_camera,
                                                    const ObjectTrackerInput& input) const;
  /// The instance's sample pixels (dynamics/object_points.hpp; people: the trunk).
  ObjectSample samplePixels(const Instance& instance, const ObjectTrackerInput& input) const;
  /// Points of `pixels` lifted with this frame's depth into the world; false-depth ones dropped,
  /// those without depth kept as voters. `rays`: the pixels undistorted, when the caller has
  /// them (else undistorted here).
  void lift(Track& track, const std::vector<cv::Point2f>& pixels, const ObjectTrackerInput& input,
            const std::vector<cv::Point2f>* rays = nullptr) const;
  TrackedObject report(const Track& track, const ObjectTrackerInput& input) const;

  /// Noise (m) of a centre component the visible part does not measure (an object cut by the
  /// image's side: sideways; a person without the trunk in view: the height): a body's size.
  static constexpr double kUnmeasuredSigmaM = 1.0;
  /// A track recalled after leaving the view may be this far from where it was last placed (m,
  /// a centre's error and a step), plus its speed and this change of pace (m/s) for the time away.
  static constexpr double kRecallPositionMarginM = 0.5;
  static constexpr double kRecallSpeedMarginMps = 0.5;
  /// A new track's velocity prior (m/s): a walker's speed is 0-2 m/s.
  static constexpr double kInitialVelocitySigmaMps = 1.0;
  /// 99.9 % quantile of the chi-square distribution with 3 degrees of freedom: a position
  /// innovation beyond it is not what the filter's covariance allows.
  static constexpr double kChiSquare3Dof999 = 16.27;
  /// The same with 6 degrees of freedom (position and velocity).
  static constexpr double kChiSquare6Dof999 = 22.46;

  ObjectTrackingConfig config_;
  int sample_step_px_ = 5;
  std::vector<std::string> prior_dynamic_classes_;
  uint64_t next_id_ = 1;
  std::vector<Track> tracks_;  // ordered by id
  /// A track that ended out of view, as recall() needs it (where and how fast it last was).
  struct OutOfView {
    uint64_t id = 0;
    std::string class_name;
    Vec3 p_world = Vec3::Zero();  ///< its filter's last position
    double speed_mps = 0.0;       ///< its filter's last speed (0 when held still)
    double left_s = 0.0;          ///< time of its last frame
  };
  /// Tracks that ended out of view, remembered for recall_out_of_view_s (oldest first); not
  /// reported while out of view. (A person placed by its height alone is not remembered: its
  /// distance rests on a stature.)
  std::vector<OutOfView> out_of_view_;
  cv::Mat previous_labels_;
  cv::Mat previous_grey_half_;           // the last frame's (ObjectTrackerInput::grey_half)
  cv::Mat previous_depth_m_;             // the last frame's depth (own flows; previous_ shares it)
  cv::Ptr<cv::DISOpticalFlow> own_dis_;  // each object's own flow (object_flow.hpp)
  PreviousDepthFrame previous_;  // a new track's first motion (first_motion.hpp); none: untracked
  /// This frame's floor seen from the camera (floor_plane.hpp: this frame's fit averaged over
  /// the frames before), fitted once per frame with anything to track; none: no floor found.
  std::optional<CameraFloor> floor_;
  FloorAverage floor_average_;
  /// The last frame's instances tracked moving (their labels): a nearer surface beside a
  /// track's points that moves by itself (object_tracker.cpp, the motion fit).
  std::vector<uint16_t> previous_moving_labels_;
};

}  // namespace dynanav
