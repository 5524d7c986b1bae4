#pragma once
// Config section `objects`: moving-object tracking (dynamics/object_tracker.hpp; see
// core/config.hpp for how sections are loaded and echoed). The sampling step is the dynamics
// section's sample_step_px (5 px), shared with scene flow.
#include "core/config/range.hpp"

namespace dynanav {

struct ObjectTrackingConfig {
  bool enabled = true;
  int max_points = 400;
  int trunk_min_points = 20;
  int max_missed_frames = 15;
  double recall_out_of_view_s = 2.0;
  bool gate_missed = true;
  bool restart_beyond_gate = true;
  bool reanchor_on_rule_change = true;
  bool first_frame_motion = true;
  bool first_motion_cut_across_ray = true;
  bool motion_skips_nearer_edge = true;
  bool motion_not_beside_movers = true;
  int centre_min_points = 8;
  int flow_finest_scale = 1;
  int flow_refinement_iterations = 0;
  bool own_flow = true;
  int own_flow_fill_offset = 64;
  bool floor_contact_range = true;
  double vertical_speed_sigma_mps = 0.3;
  double match_min_score = 0.3;
  double depth_band_m = 0.5;
  double centre_behind_surface_m = 0.15;
  double min_depth_share = 0.5;
  int min_motion_points = 12;
  int ransac_iterations = 100;
  double ransac_reprojection_px = 2.0;
  double refine_huber_px = 1.0;
  int refine_iterations = 10;
  double accel_sigma_mps2 = 0.5;
  double pace_accel_sigma_mps2 = 0.35;
  double position_sigma_m = 0.05;
  double velocity_sigma_mps = 0.6;
  int motion_velocity_frames = 10;
  double heading_sigma_mps = 0.3;
  double walking_speed_mps = 1.2;
  double walking_speed_sigma_mps = 0.4;
  double velocity_known_sigma_mps = 0.3;
  int static_after_frames = 3;
  int stop_after_slow_frames = 2;
  double static_speed_mps = 0.25;
  double path_horizon_s = 3.0;
  double path_step_s = 0.5;
  template <class V>
  void visit(V&& v) {
    v("enabled", enabled, "track instances (ids, position, velocity); only with dynamics on");
    v("max_points", max_points,
      "most points kept per object (the 5 px grid is thinned to this; bounds the per-frame cost)",
      Range{10, 100000});
    v("trunk_min_points", trunk_min_points,
      "people with shoulders and hips: sample the trunk between them if it gives this many points",
      Range{0, 100000});
    v("max_missed_frames", max_missed_frames,
      "a track the segmenter misses is carried by its flow points for at most this many frames",
      Range{0, 1000});
    v("recall_out_of_view_s", recall_out_of_view_s,
      "a track that ends because it left the field of view (the head turned away, or it walked "
      "out at the side) is remembered this long (s; 0: not at all): a new instance of its class "
      "found where it could have got to meanwhile (0.5 m + (its speed + 0.5 m/s) x the time "
      "away from where it was last placed) takes its id back instead of a new one",
      Range{0.0, 60.0});
    v("gate_missed", gate_missed,
      "a track the segmenter misses takes its flow points' centre and motion only when they lie "
      "within the filter's 99.9 % chi-square gate; otherwise it coasts on its prediction");
    v("restart_beyond_gate", restart_beyond_gate,
      "an object that does not move by itself (outside prior_dynamic_classes) whose seen centre "
      "lies outside the filter's 99.9 % chi-square gate shows another extent of itself (a "
      "segment merged with or split from a neighbour's), not motion: the filter starts afresh "
      "there, its velocity unknown, and earlier centres no longer give its motion");
    v("reanchor_on_rule_change", reanchor_on_rule_change,
      "when an object's centre is measured by another rule than in its last frame (cut by the "
      "image's side or not, a person's trunk found or not, most of it beyond the depth's range "
      "or not; not for centres placed by the height range), the two centres are of different "
      "parts of it: this frame's centre places it (a position-only update) but does not enter "
      "its velocity, and the feedback's motion history of it starts afresh (docs/tracking.md "
      "'Session 22')");
    v("first_frame_motion", first_frame_motion,
      "a new moving track's velocity is measured in its first frame, from the previous frame's "
      "points the flow carries onto its mask (else it starts at its prior, 0 +- 1 m/s)");
    v("first_motion_cut_across_ray", first_motion_cut_across_ray,
      "a new track cut by the image's left or right side takes from its first-frame motion only "
      "the velocity across the line of sight (along it a sliver's motion is biased toward the "
      "camera); off: such a track gets no first-frame motion");
    v("motion_skips_nearer_edge", motion_skips_nearer_edge,
      "an object's rigid motion is fitted without its points within the dense flow's reach (half "
      "its patches' footprint, flow_finest_scale) of a nearer surface (more than depth_band_m "
      "nearer): there the flow carries the nearer surface's motion (a walker coming out from "
      "behind another read the other's 1 m/s across the line of sight), unless fewer than "
      "min_motion_points others remain (docs/tracking.md 'Session 30')");
    v("motion_not_beside_movers", motion_not_beside_movers,
      "with fewer than min_motion_points clear of nearer surfaces, an object whose points lie "
      "mostly beside an instance tracked moving gets no rigid motion that frame (the flow there "
      "is that mover's: a walker emerging from behind another read its speed); beside a standing "
      "surface they are all fitted as before (docs/tracking.md 'Session 32')");
    v("centre_min_points", centre_min_points,
      "fewest points with depth that place an object's centre (fewer: no centre this frame)",
      Range{1, 100000});
    v("flow_finest_scale", flow_finest_scale,
      "the tracker's dense flow (DIS on half-size images): finest pyramid level; its 8 px "
      "patches cover 2^(level+1) * 8 px of the full image (2: 64 px, 1: 32 px, more CPU)",
      Range{0, 6});
    v("flow_refinement_iterations", flow_refinement_iterations,
      "the tracker's dense flow: DIS's variational refinement iterations at each level (0: the "
      "ultrafast preset's none; 5: the fast preset's): fills in what the patch search under-reads "
      "on low-texture surfaces such as smooth clothes, at a cost per pixel",
      Range{0, 100});
    v("own_flow", own_flow,
      "each moving object seen in both frames (a person: its trunk) is carried by its own flow: "
      "DIS on a crop around it with every pixel off its mask and not nearer than it set to one "
      "flat grey, so the patches do not average its motion with the background's (the shared "
      "flow under-read a side-on walker by about a quarter, docs/tracking.md 'Session 33')");
    v("own_flow_fill_offset", own_flow_fill_offset,
      "grey levels between the object's mean brightness and the flat grey set off its mask "
      "(its outline's contrast in the own flow)",
      Range{1, 255});
    v("floor_contact_range", floor_contact_range,
      "a person beyond the depth sensor's range is placed where its soles meet the floor (a "
      "plane fitted to the depth of the image's lower part, averaged in the world frame) instead "
      "of by a stature prior, when the two ranges agree within 3 sigma of the stature's "
      "(docs/tracking.md 'Session 18')");
    v("vertical_speed_sigma_mps", vertical_speed_sigma_mps,
      "people and the objects they push move on the floor: every frame the filter is told the "
      "velocity along the floor's normal is 0 +- this (m/s; a stair climber's rise, ~0.3), which "
      "keeps a gait's bob and the centre's jitter out of the velocity; 0: off (docs/tracking.md "
      "'Session 19')",
      Range{0, 100});
    v("match_min_score", match_min_score,
      "track-instance match: least (flow-point vote share + mask overlap share) to keep an id",
      Range{0, 2});
    v("depth_band_m", depth_band_m,
      "points farther than this (m) from the object's median depth are dropped",
      Range{0, 100, Range::kOpenLow});
    v("centre_behind_surface_m", centre_behind_surface_m,
      "a person's centre lies this far (m) behind the visible surface, along the viewing ray "
      "(other "
      "objects: half their visible width)",
      Range{0, 2});
    v("min_depth_share", min_depth_share,
      "when fewer of the points sampled in an instance's mask than this share have usable depth "
      "(the rest beyond the sensor's range or without a return), the centre of those that do is "
      "not the object's: its position counts as unknown to the filter",
      Range{0, 1});
    v("min_motion_points", min_motion_points,
      "fewest 3D-2D correspondences for a rigid-motion estimate", Range{6, 100000});
    v("ransac_iterations", ransac_iterations, "EPnP-RANSAC iterations per object and frame",
      Range{1, 100000});
    v("ransac_reprojection_px", ransac_reprojection_px, "EPnP-RANSAC inlier threshold (px)",
      Range{0, 100, Range::kOpenLow});
    v("refine_huber_px", refine_huber_px, "Ceres refinement: Huber loss scale (px)",
      Range{0, 100, Range::kOpenLow});
    v("refine_iterations", refine_iterations,
      "Ceres refinement: most Levenberg-Marquardt iterations", Range{0, 1000});
    v("accel_sigma_mps2", accel_sigma_mps2,
      "Kalman filter: unmodelled acceleration (m/s^2; across the direction of travel once it is "
      "clear, in every direction before)",
      Range{0, 100, Range::kOpenLow});
    v("pace_accel_sigma_mps2", pace_accel_sigma_mps2,
      "Kalman filter: a person's unmodelled acceleration along a clear direction of travel "
      "(m/s^2; a walker's pace is steadier than its heading); 0: as accel_sigma_mps2",
      Range{0, 100});
    v("position_sigma_m", position_sigma_m, "Kalman filter: noise of the measured centre (m)",
      Range{0, 10, Range::kOpenLow});
    v("velocity_sigma_mps", velocity_sigma_mps,
      "Kalman filter: noise of the one-frame centroid velocity (m/s; measured 0.25-0.56 per axis "
      "on "
      "the simulated walkers, with a bias of -0.3 along the walk)",
      Range{0, 100, Range::kOpenLow});
    v("motion_velocity_frames", motion_velocity_frames,
      "the one-frame rigid-motion velocity enters the filter only until the object's centre has "
      "been measured whole (in view, trunk found) this many frames in a row, or while it is not: "
      "its error is a bias (dense flow under-reads smooth clothes) that filtering does not "
      "average out; the centre track's does not have it (-1: always)",
      Range{-1, 100000});
    v("heading_sigma_mps", heading_sigma_mps,
      "after motion_velocity_frames, the rigid-motion velocity's component across the filtered "
      "direction of travel (in the floor's plane) still enters, +- this (m/s): the heading, which "
      "the points follow through a turn while the centre cuts the corner; its length along the "
      "walk does not (0: off; docs/tracking.md 'Session 36')",
      Range{0, 100});
    v("walking_speed_mps", walking_speed_mps,
      "a person walks about this fast (m/s): with walking_speed_sigma_mps, the prior of a new "
      "person track's speed along the direction its first motions clearly measure",
      Range{0, 10});
    v("walking_speed_sigma_mps", walking_speed_sigma_mps,
      "spread of walking_speed_mps (m/s; 0: off, a new track's velocity prior is then 0 +- 1 m/s "
      "in every direction; docs/tracking.md 'Session 37')",
      Range{0, 10});
    v("velocity_known_sigma_mps", velocity_known_sigma_mps,
      "a track reports its velocity as known (objects.jsonl velocity_known) once the filter's "
      "velocity standard deviation (largest axis) is below this (m/s); until then it is the prior",
      Range{0, 100, Range::kOpenLow});
    v("static_after_frames", static_after_frames,
      "an object not found moving for this many frames in a row and measured slower than "
      "static_speed_mps (or not found moving for 3x as many frames) is static: velocity zero",
      Range{0, 1000});
    v("static_speed_mps", static_speed_mps, "see static_after_frames (m/s)", Range{0, 100});
    v("stop_after_slow_frames", stop_after_slow_frames,
      "a person (a prior-dynamic class) whose points' rigid motion reads slower than "
      "static_speed_mps for this many frames in a row is held still at once, whatever the "
      "dynamics stage's verdict, which lags a stop by its scene-flow gap, if those points had "
      "been reading its filtered speed and that speed was at least twice static_speed_mps "
      "(0: never)",
      Range{0, 1000});
    v("path_horizon_s", path_horizon_s, "predicted path: how far ahead (s)", Range{0, 60});
    v("path_step_s", path_step_s, "predicted path: spacing of its points (s)",
      Range{0, 60, Range::kOpenLow});
  }
};

}  // namespace dynanav
