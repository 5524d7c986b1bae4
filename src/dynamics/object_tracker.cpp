#include "dynamics/object_tracker.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "dynamics/height_range.hpp"
#include "dynamics/object_motion.hpp"
#include "dynamics/object_points.hpp"

namespace dynanav {
namespace {

uint16_t labelAt(const cv::Mat& labels, const Eigen::Vector2d& pixel) {
  const int x = int(std::lround(pixel.x())), y = int(std::lround(pixel.y()));
  if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) return 0;
  return labels.at<uint16_t>(y, x);
}

}  // namespace

ObjectTracker::ObjectTracker(const ObjectTrackingConfig& config, int sample_step_px,
                             std::vector<std::string> prior_dynamic_classes)
    : config_(config),
      sample_step_px_(sample_step_px),
      prior_dynamic_classes_(std::move(prior_dynamic_classes)) {}

std::vector<TrackedObject> ObjectTracker::track(const ObjectTrackerInput& input) {
  // The floor, every tracked frame: far walkers stand on it (the soles' range), and what is
  // tracked moves along it (the vertical velocity). Followed from the run's start, not only
  // while something is tracked, so it is known when a walker enters a view where little of it
  // shows (simulated office: the floor filled half the image's lower rows at the start, 10-29 %
  // behind a pin board where the first walker entered, and was unknown for his first 10 frames;
  // his centre's rise as his body came into view read 0.6 m/s upward, docs/tracking.md
  // "Session 37").
  const bool floor_needed = config_.floor_contact_range || config_.vertical_speed_sigma_mps > 0.0;
  floor_.reset();
  if (floor_needed && input.tracked)
    floor_ = floor_average_.update(
        estimateFloorPlane(input.depth_m, input.camera, worldUpInCamera(input.T_world_camera)),
        input.T_world_camera);
  // Which of the last frame's instances were tracked moving (before this frame's updates).
  previous_moving_labels_.clear();
  for (const Track& t : tracks_)
    if (t.instance != 0 && !t.stationary && !isSlow(t.filter.velocity()))
      previous_moving_labels_.push_back(t.instance);
  // 1. Every track's points into this frame along the shared flow.
  std::vector<Carried> carried(tracks_.size());
  for (size_t k = 0; k < tracks_.size(); ++k) carried[k] = carry(tracks_[k], input);
  // 2. Which instance each track is now; 3. motion, centre and filter per track, its points
  // carried again by its own flow where the segmenter saw it in both frames.
  const std::vector<int> match = associate(input, carried);
  const auto& items = input.instances.items;
  std::vector<uint8_t> claimed(items.size(), 0);
  for (size_t k = 0; k < tracks_.size(); ++k) {
    const Instance* instance = match[k] >= 0 ? &items[size_t(match[k])] : nullptr;
    if (instance) {
      claimed[size_t(match[k])] = 1;
      const CroppedFlow own = ownFlow(tracks_[k], *instance, input);
      if (!own.flow_half.empty()) carried[k] = carry(tracks_[k], input, &own);
    }
    update(tracks_[k], carried[k], instance, input);
  }
  // 4. Tracks unseen for too long, or whose points all left, end; those out of view are
  // remembered for a while (the head turns back, the walker comes back in).
  std::erase_if(out_of_view_, [&](const OutOfView& r) {
    return input.stamp_s - r.left_s > config_.recall_out_of_view_s;
  });
  std::erase_if(tracks_, [&](const Track& t) {
    const bool ends = t.missed > config_.max_missed_frames ||
                      (t.missed > 0 && t.pixels.size() + t.voters.size() < 4);
    if (ends && config_.recall_out_of_view_s > 0.0 && input.tracked &&
        t.ranged_scale_sigma <= 0.0 && leftView(t, input))
      out_of_view_.push_back({t.id, t.class_name, t.filter.position(),
                              t.stationary ? 0.0 : t.filter.velocity().norm(), t.last_stamp_s});
    return ends;
  });
  // 5. Instances no track claimed start new tracks (fresh ids, never reused).
  for (size_t m = 0; m < items.size(); ++m)
    if (!claimed[m])
      if (auto t = start(items[m], input)) tracks_.push_back(std::move(*t));
  previous_labels_ = input.instances.labels.clone();
  previous_grey_half_ = input.grey_half;
  const bool first_motion = input.tracked && config_.first_frame_motion;
  previous_depth_m_ =
      config_.own_flow || first_motion ? input.depth_m.clone() : cv::Mat();  // one copy for both
  previous_ = first_motion
                  ? PreviousDepthFrame{previous_depth_m_, input.T_world_camera, input.stamp_s}
                  : PreviousDepthFrame{};
  std::vector<TrackedObject> out;
  out.reserve(tracks_.size());
  for (const Track& t : tracks_) out.push_back(report(t, input));
  return out;
}

std::vector<int> ObjectTracker::associate(const ObjectTrackerInput& input,
                                          const std::vector<Carried>& carried) {
  const auto& items = input.instances.items;
  const cv::Mat& labels = input.instances.labels;
  std::vector<int> match(tracks_.size(), -1);
  if (items.empty() || tracks_.empty()) return match;
  // Label -> index maps for this frame's instances and the tracks' last instances.
  uint16_t max_label = 0;
  for (const Instance& it : items) max_label = std::max(max_label, it.id);
  for (const Track& t : tracks_) max_label = std::max(max_label, t.instance);
  std::vector<int> item_of(size_t(max_label) + 1, -1), track_of(size_t(max_label) + 1, -1);
  for (size_t m = 0; m < items.size(); ++m) item_of[items[m].id] = int(m);
  for (size_t k = 0; k < tracks_.size(); ++k)
    if (tracks_[k].instance) track_of[tracks_[k].instance] = int(k);
  const size_t n_items = items.size();
  std::vector<double> overlap(tracks_.size() * n_items, 0.0);
  std::vector<double> area_prev(tracks_.size(), 0.0), area_cur(n_items, 0.0);
  const bool have_prev = previous_labels_.size() == labels.size();
  // Mask overlap with the track's last mask (every second pixel and row: shares, not counts).
  for (int y = 0; y < labels.rows; y += 2) {
    const uint16_t* cur = labels.ptr<uint16_t>(y);
    const uint16_t* prev = have_prev ? previous_labels_.ptr<uint16_t>(y) : nullptr;
    for (int x = 0; x < labels.cols; x += 2) {
      const int m = cur[x] <= max_label ? item_of[cur[x]] : -1;
      const int k = prev && prev[x] <= max_label ? track_of[prev[x]] : -1;
      if (m >= 0) area_cur[size_t(m)] += 1.0;
      if (k >= 0) area_prev[size_t(k)] += 1.0;
      if (m >= 0 && k >= 0) overlap[size_t(k) * n_items + size_t(m)] += 1.0;
    }
  }
  std::vector<std::tuple<double, size_t, size_t>> candidates;
  for (size_t k = 0; k < tracks_.size(); ++k) {
    std::vector<double> votes(n_items, 0.0);
    for (const auto* pixels : {&carried[k].pixels, &carried[k].voters})
      for (const auto& px : *pixels) {
        const uint16_t label = labelAt(labels, px);
        if (label && label <= max_label && item_of[label] >= 0)
          votes[size_t(item_of[label])] += 1.0;
      }
    const double n = std::max<size_t>(1, carried[k].pixels.size() + carried[k].voters.size());
    for (size_t m = 0; m < n_items; ++m) {
      if (items[m].class_name != tracks_[k].class_name) continue;
      const double smaller = std::min(area_prev[k], area_cur[m]);
      const double score =
          votes[m] / n + (smaller > 0.0 ? overlap[k * n_items + m] / smaller : 0.0);
      if (score >= config_.match_min_score) candidates.emplace_back(score, k, m);
    }
  }
  // Greedy, best score first (ties by track, then instance: deterministic).
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) > std::get<0>(b);
    return std::tie(std::get<1>(a), std::get<2>(a)) < std::tie(std::get<1>(b), std::get<2>(b));
  });
  std::vector<uint8_t> item_taken(n_items, 0);
  for (const auto& [score, k, m] : candidates) {
    if (match[k] >= 0 || item_taken[m]) continue;
    match[k] = int(m);
    item_taken[m] = 1;
  }
  return match;
}

void ObjectTracker::update(Track& track, const Carried& carried, const Instance* instance,
                           const ObjectTrackerInput& input) {
  const double dt = input.stamp_s - track.last_stamp_s;
  track.last_stamp_s = input.stamp_s;
  track.missed = instance ? 0 : track.missed + 1;
  track.instance = instance ? instance->id : 0;
  track.inliers = 0;
  track.restarted = false;
  track.reanchored = false;
  if (dt > 0.0) track.filter.predict(dt);
  // The floor's normal in the world, when the floor is in view: people move in its plane.
  const std::optional<Vec3> up_world = upWorld(input);
  if (!input.tracked) {  // no camera pose: no world points; the filter coasts
    track.pixels.clear();
    for (const auto& px : carried.pixels) track.pixels.emplace_back(float(px.x()), float(px.y()));
    track.p_world = carried.p_prev_world;
    track.beside_nearer = carried.beside_nearer;
    track.voters.clear();
    for (const auto& px : carried.voters) track.voters.emplace_back(float(px.x()), float(px.y()));
    return;
  }
  // Keep the carried points that are still on the object: on its mask when the segmenter saw
  // it, and at the depth the last motion predicts (background behind a mask edge is not).
  const SE3 T_camera_world = input.T_world_camera.inverse();
  Carried kept;
  std::vector<cv::Point2f> kept_pixels;
  std::vector<double> kept_depth_m;
  for (size_t i = 0; i < carried.pixels.size(); ++i) {
    const Eigen::Vector2d& px = carried.pixels[i];
    if (instance && labelAt(input.instances.labels, px) != instance->id) continue;
    const float z = depthAt(input.depth_m, cv::Point2f(float(px.x()), float(px.y())));
    const double z_predicted = (T_camera_world * (track.motion * carried.p_prev_world[i])).z();
    if (z <= 0.f || std::abs(z - z_predicted) > config_.depth_band_m) continue;
    kept.p_prev_world.push_back(carried.p_prev_world[i]);
    kept.beside_nearer.push_back(carried.beside_nearer[i]);
    kept_pixels.emplace_back(float(px.x()), float(px.y()));
    kept_depth_m.push_back(z);
  }
  // The motion is fitted to the points' rays (undistorted pixels), as their 3D was lifted; a
  // carried track's points are lifted along the same rays below.
  const std::vector<cv::Point2f> kept_rays = input.camera.undistortPixels(kept_pixels);
  std::optional<Vec3> v_measured;
  if (dt > 0.0) {
    // Points that lay beside a nearer surface moved with it in the flow (a walker coming out
    // from behind another took the other's motion): the motion is fitted without them while
    // enough others remain. With fewer, all are fitted when what they lie beside stands (its
    // flow under-reads the object's own motion but keeps its direction: no motion at all cost
    // more, a walker coming out from behind a cabinet then read its sliding centre alone,
    // docs/tracking.md "Session 30"), and none when most lie beside an instance tracked moving
    // (the flow there is that mover's: a walker emerging from behind another read 1.4-2.3 m/s
    // of the other's motion sideways, "Session 32").
    size_t clear_points = 0, beside_points = 0, beside_movers = 0;
    for (const NearerSurface& beside : kept.beside_nearer) {
      if (!beside.found) {
        ++clear_points;
        continue;
      }
      ++beside_points;
      if (beside.label != 0 &&
          std::ranges::find(previous_moving_labels_, beside.label) != previous_moving_labels_.end())
        ++beside_movers;
    }
    const bool skip_beside =
        config_.motion_skips_nearer_edge && clear_points >= size_t(config_.min_motion_points);
    const bool beside_mover = config_.motion_skips_nearer_edge &&
                              config_.motion_not_beside_movers && !skip_beside &&
                              2 * beside_movers > beside_points;
    std::vector<Vec3> fit_p_prev;
    std::vector<Eigen::Vector2d> fit_rays;
    std::vector<double> fit_depth_m;
    for (size_t i = 0; i < kept_rays.size() && !beside_mover; ++i) {
      if (skip_beside && kept.beside_nearer[i].found) continue;
      fit_p_prev.push_back(kept.p_prev_world[i]);
      fit_rays.emplace_back(kept_rays[i].x, kept_rays[i].y);
      fit_depth_m.push_back(kept_depth_m[i]);
    }
    const ObjectMotion motion =
        estimateObjectMotion(fit_p_prev, fit_rays, T_camera_world, input.camera, track.motion,
                             motionOptions(input.frame_index, track.id), fit_depth_m);
    if (motion.ok) {
      v_measured = inlierCentroidVelocity(motion, fit_p_prev, dt);
      track.motion = motion.H_world;
      track.inliers = motion.inliers;
    } else {
      track.motion = SE3::Identity();
    }
  }
  // The points for the next frame and the centre: sampled afresh from this frame's mask when
  // the segmenter saw the object (carried points drift over the body, and a track started on a
  // leg entering the view would keep measuring the leg); the carried ones when it did not.
  if (instance) {
    const ObjectSample sample = samplePixels(*instance, input);
    lift(track, sample.pixels, input);
    track.trunk = sample.trunk;
    track.cut_side = instanceCutSide(*instance, input.instances.labels.cols);
  } else {
    lift(track, kept_pixels, input, &kept_rays);
    // The voters stay voters while the object is unseen: without a mask nothing says a pixel
    // that now has depth is still on it.
    track.voters.clear();
    for (const auto& px : carried.voters) track.voters.emplace_back(float(px.x()), float(px.y()));
  }
  std::vector<Vec3> p_camera;
  p_camera.reserve(track.p_world.size());
  for (const Vec3& p : track.p_world) p_camera.push_back(T_camera_world * p);
  bool ranged_centre = false;  // placed by its height this frame (no depth)
  if (const auto centre = measureCentre(track, p_camera, instance, input)) {
    ranged_centre = centre->scale_sigma > 0.0;
    // The centre measured whole (the segmenter saw all of it, the trunk of a person) carries
    // the velocity over the frames; the one-frame rigid motion is needed only until it has done
    // so for a while, or while part of the centre is unknown. Its error is mostly a bias (the
    // dense flow under-reads a walker's smooth clothes by about a fifth: -0.3 m/s along a
    // crossing walk), which no number of frames averages out; the centres' error is not.
    const bool whole = instance && !centre->cov_world;
    track.whole_centre_frames = whole ? track.whole_centre_frames + 1 : 0;
    // A rigid object (a class that does not move by itself: a pushed box, a chair) has no such
    // bias: its flow follows its texture, while its centre, pushed behind the visible surface
    // along a viewing ray that turns as it moves, reads fast. Its rigid motion always enters.
    const bool use_motion = config_.motion_velocity_frames < 0 || !whole ||
                            track.whole_centre_frames <= config_.motion_velocity_frames ||
                            !track.prior_dynamic;
    const Vec3 p_world = input.T_world_camera * centre->p_camera;
    const Vec3 camera_world = input.T_world_camera.translation();
    std::optional<Mat3> cov_world = centre->cov_world;
    // An object that does not move by itself (a chair, a box) whose centre lies where it could
    // not have got to since the last frame (outside the filter's 99.9 % gate while the segmenter
    // sees it) shows another extent of itself, not motion: a segment merged with or split from a
    // neighbour's (static fr1_xyz: a chair's centre jumped 0.85 m in one frame, was read as
    // up to 2.2 m/s toward the wearer and raised an urgent warning in a room where nothing moves).
    // The filter starts afresh there, its velocity unknown again. Judged before a held object found
    // moving is reopened (below). Not for people: a walker's centre leaves the gate as limbs and
    // trunk come and go from view, and restarting them lost more than it saved (simulated
    // office speed 0.140 / 0.144 / 0.172 -> 0.168 / 0.207 / 0.214 m/s, docs/tracking.md
    // "Session 20").
    if (instance && !track.prior_dynamic && config_.restart_beyond_gate &&
        track.filter.normalisedInnovation(p_world, std::nullopt, cov_world) > kChiSquare3Dof999) {
      track.filter = KalmanCv(p_world, filterNoise(track.class_name), cov_world);
      track.restarted = true;
    } else if (!track.prior_dynamic && track.stationary && instance &&
               input.dynamics.foundMoving(instance->id)) {
      // An object held still (its velocity clamped at zero, an assumption rather than a
      // measurement) that the dynamics stage now finds moving has an unknown velocity again: the
      // filter is told so, and the rigid motion measures it in a frame or two instead of a ramp
      // from the clamped zero. Its centre, predicted at a standstill, is an assumption too: kept
      // tight, the distance the object moved meanwhile was read as speed (the pushed box 30 %
      // fast for 8 frames), so it is reopened by a body's size, as for a released person below.
      // (People set off on their points instead: session 10's rule.)
      track.filter.reopen(kUnmeasuredSigmaM, kInitialVelocitySigmaMps);
    }
    if (centre->scale_sigma > 0.0 && track.ranged_scale_sigma <= 0.0) {
      // Depth placed this person before (the filter is metric) and now it is beyond the range:
      // the stature's error is new to the filter. It enters every frame as if independent
      // (an approximation: the filter then trusts the range a little more than it should).
      const Vec3 d = p_world - camera_world;
      *cov_world += centre->scale_sigma * centre->scale_sigma * d * d.transpose();
    } else if (centre->scale_sigma <= 0.0 && centre->depth_measured &&
               track.ranged_scale_sigma > 0.0) {
      // Depth places a person the height range placed so far: the stature's common error enters
      // the filter now, with the position-velocity correlation of a scale, so this update
      // corrects the position (and the velocity, in the prior's units) the ranges measured.
      // The ranges' velocity also rests on the mask's ends being unbiased from frame to frame,
      // which a segmenter does not promise for a far person (a mask short by 5 px at each end
      // reads 12 % far at 11 m, 6 % at 5 m: it approaches too fast): it stays only as a guess as
      // wide as a new track's prior (docs/tracking.md step 6).
      KalmanCv::Mat6 Q = statureCovariance(track.filter.position(), track.filter.velocity(),
                                           camera_world, track.ranged_scale_sigma);
      Q.bottomRightCorner<3, 3>() +=
          Mat3::Identity() * kInitialVelocitySigmaMps * kInitialVelocitySigmaMps;
      track.filter.addCovariance(Q);
      track.ranged_scale_sigma = 0.0;
      // Unless the depth says the ranges were wrong in more than scale (a mask that lost head and
      // feet: eroded 5 px, one read 35 m at 11 m): then the filter starts afresh at the depth.
      // (Ranges whose rate no walker has were withdrawn while they came: below.)
      const Mat3 S = track.filter.covariance().topLeftCorner<3, 3>() +
                     cov_world.value_or(Mat3::Identity() * config_.position_sigma_m *
                                        config_.position_sigma_m);
      const Vec3 innovation = p_world - track.filter.position();
      track.ranges_refuted = false;  // placed by depth: its next ranges are judged afresh
      if (innovation.dot(S.ldlt().solve(innovation)) > kChiSquare3Dof999) {
        track.filter = KalmanCv(p_world, filterNoise(track.class_name), cov_world);
        track.restarted = true;
      }
    }
    const std::optional<Vec3> v_used = use_motion ? v_measured : std::nullopt;
    // Missed by the segmenter, nothing says the carried points are still on the object: the
    // flow may have dragged them onto a walker passing in front or onto the background. Their
    // centre and motion enter only when the filter's covariance allows them (99.9 %); otherwise
    // the track coasts on its prediction (Bonn crowd: a walker the detector lost read 2.6 m/s).
    const bool gated_out = !instance && config_.gate_missed &&
                           track.filter.normalisedInnovation(p_world, v_used, cov_world) >
                               (v_used ? kChiSquare6Dof999 : kChiSquare3Dof999);
    // A centre measured on another part of the object than the last one (the image's side now
    // cuts it or no longer does; a person's trunk found or lost; most of it beyond the depth's
    // range or no longer) differs from it by the two parts' offset, which is not motion: static
    // fr1_xyz in real time, a false "person" on an oblique desk moved 0.16-0.21 m toward the camera
    // as its sample switched from the trunk band to the whole mask, and an urgent "approaching"
    // warning followed (docs/tracking.md "Session 22"). Such a centre places the object (a
    // position-only update); the velocity keeps what the points' rigid motion measures. Not for
    // centres placed by the height range (they measure the whole person whatever was sampled;
    // their hand-over to depth is judged above).
    const Track::CentreRule rule = centreRule(track, instance != nullptr, ranged_centre);
    const bool reanchor = config_.reanchor_on_rule_change && track.centre_rule &&
                          !(*track.centre_rule == rule) && !rule.ranged &&
                          !track.centre_rule->ranged;
    track.centre_rule = rule;
    if (!track.restarted && !gated_out) {
      if (reanchor) {
        track.filter.reanchor(p_world, kUnmeasuredSigmaM, cov_world);
        if (v_used) track.filter.updateVelocity(*v_used);
        track.reanchored = true;
      } else {
        track.filter.update(p_world, v_used, cov_world);
      }
      if (v_used) applyWalkingSpeedPrior(track, up_world);
      // Once the rigid motion no longer enters (the centres carry the velocity), its heading
      // still does: the centre of a turning walker cuts the corner (simulated office, a 60-90
      // degree turn at 1.2 m/s: the measured centre fell up to 0.1 m inside the truth's path and
      // the filter read 0.91-1.05 m/s), while the points turn with the walker. Across the
      // direction of travel their error is noise (0.12-0.17 m/s RMS on the simulated walkers, no
      // bias); along it they carry the flow's under-read, which stays out.
      if (!use_motion && v_measured && up_world && config_.heading_sigma_mps > 0.0)
        track.filter.updateHeading(*v_measured, *up_world, config_.heading_sigma_mps);
    }
  } else {
    track.whole_centre_frames = 0;
  }
  // People and what they push move along the floor: the centre's vertical jitter (a gait's bob,
  // the trunk's sampled part changing, a ranged centre's noise) is not their motion (the
  // simulated crossing and office: 0.12-0.21 m/s of vertical velocity error, docs/tracking.md
  // "Session 19"). Told every frame, so the filter keeps it near zero while a stair climber's
  // rise would still come through.
  if (up_world && config_.vertical_speed_sigma_mps > 0.0)
    track.filter.updateVelocityAlong(*up_world, 0.0, config_.vertical_speed_sigma_mps);
  const bool verified_static = instance && input.dynamics.foundStatic(instance->id);
  if (ranged_centre && beyondWalkersSpeed(track.filter.velocity())) {
    // The ranges rush (or recede) faster than a walker can: the mask's height changes for
    // another reason (a far eroded mask gaining head and feet as the person nears read 36 -> 24 m
    // in 2 s for a walker at 9 m, 1 m/s, and raised an urgent warning). What they said is
    // withdrawn: the velocity back to a new track's prior (the position keeps its covariance, and
    // the stature's common error stays beside it), and no more ranges until depth places the
    // person, where the hand-over above judges the position.
    track.ranges_refuted = true;
    const Mat3 position_cov = track.filter.covariance().topLeftCorner<3, 3>();
    track.filter = KalmanCv(track.filter.position(), filterNoise(track.class_name), position_cov);
  }
  if (ranged_centre) {
    // Placed by its height, without depth: the dynamics stage has nothing to find it moving by,
    // so its "not moving" says nothing (a walker 10 m down a hall was held still until depth
    // reached it); the filter's own velocity, once known, does. The filter is not held still:
    // its centres are all that shows the person setting off.
    const bool slow = filterKnownSlow(track);
    track.still = slow ? track.still + 1 : 0;
    track.stationary = verified_static || track.still >= config_.static_after_frames;
    return;
  }
  // The points' speed is judged along the floor when it is in view: a body also rises and sinks
  // (a gait's bob; a stride closing into a standing pose read 0.28-0.33 m/s upward in the two
  // frames after a stop in simulated office seed 2, 0.03-0.09 along the floor), which is not
  // walking, as the filter is told every frame (vertical_speed_sigma_mps).
  std::optional<Vec3> v_walk = v_measured;
  if (v_walk && up_world) *v_walk = projectOntoPlane(*v_walk, *up_world);
  judgeStill(track, instance, v_walk, verified_static, input);
}

}  // namespace dynanav
