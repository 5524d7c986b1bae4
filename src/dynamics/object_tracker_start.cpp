#include "dynamics/object_tracker.hpp"

// A new track (its first centre, filter and motion) and the settings every track's filter and
// rigid motion use (object_tracker.cpp updates the tracks).
#include <limits>

#include "dynamics/keypoint_dynamics.hpp"
#include "dynamics/object_points.hpp"

namespace dynanav {

ObjectMotionOptions ObjectTracker::motionOptions(int frame_index, uint64_t id) const {
  ObjectMotionOptions options;
  options.ransac_iterations = config_.ransac_iterations;
  options.reprojection_px = config_.ransac_reprojection_px;
  options.huber_px = config_.refine_huber_px;
  options.refine_iterations = config_.refine_iterations;
  options.min_points = config_.min_motion_points;
  options.seed = uint64_t(frame_index) * 7919u + id;  // same run, same answer
  return options;
}

KalmanCvNoise ObjectTracker::filterNoise(const std::string& class_name) const {
  // A walker's pace is steadier than its heading, so a person's filter has less acceleration noise
  // along its direction of travel than across it (docs/tracking.md "Session 38"). Not for what is
  // pushed or carried: a box stops when the push does.
  const double pace_accel_sigma_mps2 = class_name == "person" ? config_.pace_accel_sigma_mps2 : 0.0;
  return {config_.accel_sigma_mps2, config_.position_sigma_m, config_.velocity_sigma_mps,
          kInitialVelocitySigmaMps, pace_accel_sigma_mps2};
}

std::optional<Vec3> ObjectTracker::upWorld(const ObjectTrackerInput& input) const {
  if (!floor_) return std::nullopt;
  return (input.T_world_camera.linear() * floor_->normal_camera).normalized();
}

void ObjectTracker::applyWalkingSpeedPrior(Track& track,
                                           const std::optional<Vec3>& up_world) const {
  // A new track's velocity prior is 0 +- 1 m/s in every direction, and a standstill is no moving
  // person's speed: fused with it, a walker's first readings shrink by a quarter (simulated office
  // seed 3: a walker entering at 1.2 m/s read 0.78, 0.89, 0.96 m/s in its first frames). People
  // walk at about 1.2 m/s in a direction the prior cannot know; the points' first motion gives the
  // direction, and the speed along it is then told the walker's. Once: it is a prior, not a
  // measurement. Only once that direction is clear (its level speed above twice the velocity's
  // sigma): a first reading from a sliver at the image's side can point the wrong way (simulated
  // office-ramped seed 1: toward the camera for a walker going away), and a walker's speed told
  // along it made the filter confidently wrong (that seed 0.110 -> 0.153 m/s, docs/tracking.md
  // "Session 37"). Not for a person released from being held still: one setting off from a
  // standstill is not yet at a walker's speed.
  if (!track.walking_prior_pending) return;
  if (filterVelocityKnown(track) || config_.walking_speed_sigma_mps <= 0.0) {
    track.walking_prior_pending = false;
    return;
  }
  if (!up_world) return;
  const Vec3 v_level = projectOntoPlane(track.filter.velocity(), *up_world);
  const std::optional<Vec3> travel = track.filter.clearDirection(v_level);
  if (isSlow(v_level) || !travel) return;
  track.filter.updateVelocityAlong(*travel, config_.walking_speed_mps,
                                   config_.walking_speed_sigma_mps);
  track.walking_prior_pending = false;
}

bool ObjectTracker::beyondWalkersSpeed(const Vec3& v_world_mps) {
  return v_world_mps.squaredNorm() >
         kChiSquare3Dof999 * kInitialVelocitySigmaMps * kInitialVelocitySigmaMps;
}

ObjectTracker::Track::CentreRule ObjectTracker::centreRule(const Track& track, bool seen,
                                                           bool ranged) const {
  // Carried points are the last seen frame's sample: they keep its share of depth.
  const bool little_depth = seen ? track.depth_share < config_.min_depth_share
                                 : track.centre_rule && track.centre_rule->little_depth;
  return {track.cut_side, track.trunk, little_depth, ranged};
}

bool ObjectTracker::filterVelocityKnown(const Track& track) const {
  return track.filter.velocitySigma() <= config_.velocity_known_sigma_mps;
}

bool ObjectTracker::isSlow(const Vec3& v_mps) const {
  return v_mps.norm() < config_.static_speed_mps;
}

bool ObjectTracker::filterKnownSlow(const Track& track) const {
  return filterVelocityKnown(track) && isSlow(track.filter.velocity());
}

bool ObjectTracker::leftView(const Track& track, const ObjectTrackerInput& input) const {
  if (track.cut_side != 0) return true;
  const Vec3 p_camera = input.T_world_camera.inverse() * track.filter.position();
  if (!(p_camera.z() > 0.0)) return true;
  const Eigen::Vector2d px = input.camera.project(p_camera);
  return !input.camera.inImage(px.x(), px.y());
}

std::optional<uint64_t> ObjectTracker::recall(const std::string& class_name, const Vec3& p_world,
                                              double stamp_s) {
  // Where it could have got to since it was last placed: out of view the filter's constant
  // velocity says little (a walker turns: a simulated head-turns walker came back 1.5 m off it
  // after 0.8 s, docs/tracking.md "Session 32"), so a disc around the last position, as far as its
  // speed and a walker's change of pace carry it; of several, the nearest.
  std::optional<size_t> best;
  double best_m = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < out_of_view_.size(); ++k) {
    const OutOfView& r = out_of_view_[k];
    if (r.class_name != class_name) continue;
    const double away_s = std::max(0.0, stamp_s - r.left_s);
    const double reach_m = kRecallPositionMarginM + (r.speed_mps + kRecallSpeedMarginMps) * away_s;
    const double d_m = (p_world - r.p_world).norm();
    if (d_m <= reach_m && d_m < best_m) {
      best_m = d_m;
      best = k;
    }
  }
  if (!best) return std::nullopt;
  const uint64_t id = out_of_view_[*best].id;
  out_of_view_.erase(out_of_view_.begin() + std::ptrdiff_t(*best));
  return id;
}

std::optional<ObjectTracker::Track> ObjectTracker::start(const Instance& instance,
                                                         const ObjectTrackerInput& input) {
  if (!input.tracked) return std::nullopt;
  Track t;
  t.class_name = instance.class_name;
  t.instance = instance.id;
  t.last_stamp_s = input.stamp_s;
  const ObjectSample sample = samplePixels(instance, input);
  lift(t, sample.pixels, input);
  t.trunk = sample.trunk;
  t.cut_side = instanceCutSide(instance, input.instances.labels.cols);
  const SE3 T_camera_world = input.T_world_camera.inverse();
  std::vector<Vec3> p_camera;
  for (const Vec3& p : t.p_world) p_camera.push_back(T_camera_world * p);
  const auto centre = measureCentre(t, p_camera, &instance, input);
  if (!centre) return std::nullopt;
  t.prior_dynamic = isPriorDynamicClass(instance.class_name, prior_dynamic_classes_);
  const Vec3 p_world = input.T_world_camera * centre->p_camera;
  t.filter = KalmanCv(p_world, filterNoise(t.class_name), centre->cov_world);
  t.centre_rule = centreRule(t, true, centre->scale_sigma > 0.0);
  t.ranged_scale_sigma = centre->scale_sigma;
  const bool moving = input.dynamics.foundMoving(instance.id);
  // Placed by its height: no verdict to go by (update's static rule for such tracks).
  t.still = moving || t.ranged_scale_sigma > 0.0 ? 0 : 1;
  // A person is taken as moving until found still; a chair as static until found moving.
  if (input.dynamics.foundStatic(instance.id) || (!t.prior_dynamic && !moving))
    t.still = config_.static_after_frames;
  t.stationary = t.still >= config_.static_after_frames;
  // The id of a track that left the view and could have got here (its filter is not taken
  // back: out of view its prediction drifted); not for a person placed by its height alone,
  // whose distance rests on a stature.
  const std::optional<uint64_t> recalled =
      centre->scale_sigma <= 0.0 ? recall(t.class_name, p_world, input.stamp_s) : std::nullopt;
  t.id = recalled ? *recalled : next_id_++;
  // Moving from its first frame (not placed by its height): its motion since the previous
  // frame, from that frame's points the flow carries onto its mask (first_motion.hpp). One
  // entering at the image's side measures only its velocity across the line of sight: the
  // sliver in view reads motion along it badly (the simulated crossing's walker read 2.5 m/s
  // toward the camera, walking across it at 1.4). Later frames' motion enters whole: by then
  // the filter knows the velocity along the ray from the centres, and leaving that component
  // out of a cut walker's every frame was worse (docs/tracking.md "Session 17").
  const bool cut = t.cut_side != 0;
  if (!t.stationary && t.ranged_scale_sigma <= 0.0 && (!cut || config_.first_motion_cut_across_ray))
    if (const auto first = firstFrameMotion(
            {instance, input.instances.labels, input.flow_half, input.depth_m, input.T_world_camera,
             input.stamp_s, input.camera, previous_, sample_step_px_, config_.depth_band_m},
            motionOptions(input.frame_index, t.id))) {
      if (cut)
        t.filter.updateVelocityAcross(first->v_world_mps,
                                      t.filter.position() - input.T_world_camera.translation());
      else
        t.filter.updateVelocity(first->v_world_mps);
      t.motion = first->H_world;
      t.inliers = first->inliers;
    }
  t.walking_prior_pending = t.class_name == "person" && !t.stationary;
  if (t.inliers > 0) applyWalkingSpeedPrior(t, upWorld(input));
  return t;
}

}  // namespace dynanav
