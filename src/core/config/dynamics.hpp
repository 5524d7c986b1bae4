#pragma once
// Config section `dynamics` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Dynamic-object handling (paper's values as defaults).
struct DynamicsConfig {
  std::vector<std::string> prior_dynamic_classes = {"person", "dog", "cat", "horse", "bird"};
  int prior_mask_dilate_px = 20;
  double prior_box_depth_band_m = 0.4;
  double depth_diff_min_m = 0.10;
  double depth_diff_per_z2 = 0.02;
  double depth_diff_map_sigmas = 1.0;
  double depth_noise_per_z2 = 0.0016;
  double scene_flow_point_sigmas = 3.0;
  double assumed_exposure_ms = 20.0;
  int depth_test_max_radius_px = 24;
  double instance_dynamic_share = 0.30;
  int instance_min_points = 5;
  double scene_flow_point_m = 0.02;
  double scene_flow_share = 0.30;
  int scene_flow_min_points = 10;
  int scene_flow_gap_frames = 3;
  bool scene_flow_mean_check = true;
  int scene_flow_reference_px = 32;
  double scene_flow_prior_depth_band_m = 0.5;
  int scene_flow_end_search_px = 2;
  bool scene_flow_end_parallax = true;
  bool cull_vanished_points = false;
  bool cull_moving_object_points = true;
  int sample_step_px = 5;
  bool moving_evidence = true;
  double moving_prior_log_odds = -1.0;
  double moving_vote_log_odds = 2.0;
  double static_vote_log_odds = 0.5;
  double moving_evidence_min = -2.0;
  double moving_evidence_max = 3.0;
  bool residual_movers = true;
  bool residual_instances = true;
  int residual_min_established = 30;
  double residual_region_radius_px = 40.0;
  double residual_region_depth_band_m = 0.3;
  int residual_region_min_points = 5;
  double residual_region_chi2 = 13.8;
  double residual_region_min_px = 2.0;
  template <class V>
  void visit(V&& v) {
    v("prior_dynamic_classes", prior_dynamic_classes,
      "classes that may move: their keypoints never enter the initial pose estimate or the map");
    v("prior_mask_dilate_px", prior_mask_dilate_px,
      "prior-dynamic masks are grown by this many pixels before ORB extraction (mask edges lag "
      "fast limbs; ORB's 31 px patch straddles the outline)",
      Range{0, 200});
    v("prior_box_depth_band_m", prior_box_depth_band_m,
      "a prior object's box also claims pixels within this depth (m) of its mask's median depth "
      "(catches a head or arm the mask model missed; 0 = masks only)",
      Range{0, 100});
    v("depth_diff_min_m", depth_diff_min_m,
      "depth-difference test: smallest |measured - predicted| depth (m) that flags a keypoint",
      Range{0, 100});
    v("depth_diff_per_z2", depth_diff_per_z2,
      "depth-difference test: extra threshold per m^2 of depth (structured-light noise grows with "
      "z^2)",
      Range{0, 100});
    v("depth_diff_map_sigmas", depth_diff_map_sigmas,
      "depth-difference test: the threshold also grows by this many sigmas of the map point's "
      "depth under the SLAM's own RGB-D model (z^2 * pyramid scale of the keypoint / (fx * "
      "baseline)): a far or coarse point's depth is placed by bundle adjustment with little depth "
      "information, so its predicted depth is no measurement (0 = DynaSLAM's fixed threshold)",
      Range{0, 100});
    v("depth_noise_per_z2", depth_noise_per_z2,
      "depth sensor noise sigma (m) per m^2 of depth (structured light: ~1.6 mm at 1 m, 4 cm at "
      "5 m, Khoshelham & Elberink 2012); scales the scene-flow point threshold",
      Range{0, 1});
    v("scene_flow_point_sigmas", scene_flow_point_sigmas,
      "scene flow: a point moves only if it moved more than this many sigmas of its depth noise "
      "at both ends (and more than scene_flow_point_m); 0 = the fixed threshold only",
      Range{0, 100});
    v("assumed_exposure_ms", assumed_exposure_ms,
      "colour exposure (ms) assumed when camera.yaml gives no exposure_ms: while the camera "
      "moves, the depth test accepts any depth within the pixels a keypoint may have moved over "
      "half the exposure plus the colour-depth stamp offset (motion blur, misregistration)",
      Range{0, 1000});
    v("depth_test_max_radius_px", depth_test_max_radius_px,
      "largest search radius (px) of the motion-aware depth test (0 = compare the keypoint's own "
      "depth only, as DynaSLAM) and of scene flow's search at a flow's end",
      Range{0, 200});
    v("instance_dynamic_share", instance_dynamic_share,
      "an instance moves when this share of its checked keypoints fails the depth test",
      Range{0, 1});
    v("instance_min_points", instance_min_points,
      "fewest checked keypoints for an instance verdict", Range{1, 100000});
    v("scene_flow_point_m", scene_flow_point_m,
      "scene flow: a point moves if it moved more than this (m) between frames after ego-motion "
      "(paper: 0.02)",
      Range{0, 100, Range::kOpenLow});
    v("scene_flow_share", scene_flow_share,
      "scene flow: an object is dynamic when more than this share of its points moves (paper: 30 "
      "%)",
      Range{0, 1});
    v("scene_flow_min_points", scene_flow_min_points,
      "fewest tracked points for a scene-flow verdict", Range{1, 100000});
    v("scene_flow_gap_frames", scene_flow_gap_frames,
      "scene flow is measured between a frame and the one this many frames earlier (a box pushed "
      "at "
      "0.5 m/s moves only 1.7 cm per frame at 30 Hz, under the 0.02 m threshold)",
      Range{1, 1000});
    v("scene_flow_mean_check", scene_flow_mean_check,
      "scene flow: the object's mean displacement vector must also exceed scene_flow_point_m "
      "(depth noise moves single points, not the mean)");
    v("scene_flow_reference_px", scene_flow_reference_px,
      "scene flow of an object outside prior_dynamic_classes (a chair, a box) is judged relative "
      "to the background in a band this many px wide beyond the dense flow's patch footprint "
      "around its mask (other instances left out): its median displacement is taken off and a "
      "point must also move scene_flow_point_sigmas of its robust spread (a flow dragged by a "
      "walker in front or blurred moves both; 0 = against the camera's motion alone)",
      Range{0, 1000});
    v("scene_flow_end_search_px", scene_flow_end_search_px,
      "scene flow: where the depths within this many px of a flow's end span two surfaces "
      "(spread over twice the point threshold), the one nearest to the depth the point would "
      "have had it stood still is taken: a dense flow is off by a pixel or two where depth jumps, "
      "and on a thin or see-through object (a chair) that pixel swaps its depth for the wall's "
      "behind it (default 2: one pixel of the half-size flow the verifier computes; 0 = the end "
      "pixel's own depth)",
      Range{0, 100});
    v("scene_flow_end_parallax", scene_flow_end_parallax,
      "scene flow of an object outside prior_dynamic_classes (a chair): scene_flow_end_search_px "
      "grows by the point's parallax over the gap (fx * camera translation / depth, at most "
      "depth_test_max_radius_px): a dense flow at a depth edge blends the patches of both "
      "surfaces, whose image motions differ by their parallax (people keep the narrow search: a "
      "wide one also finds the floor at a walker's feet at the old depth)");
    v("scene_flow_prior_depth_band_m", scene_flow_prior_depth_band_m,
      "scene flow of a prior-dynamic object (a person) takes only its sampled points within this "
      "depth (m) of their median: a mask grown over an occluder or the background in front of "
      "or behind the body would average their flow into the person's (a body is well under 1 m "
      "deep; objects outside the classes may be any size and keep every point; 0 = every point)",
      Range{0, 100});
    v("cull_vanished_points", cull_vanished_points,
      "a map point whose keypoint now measures deeper than predicted (beyond the depth test) is "
      "gone: "
      "it lay on something that moved, and is removed from the map (off: on Bonn crowd it cost "
      "accuracy, "
      "0.0191 -> 0.0247 m, docs/dynamics.md)");
    v("cull_moving_object_points", cull_moving_object_points,
      "map points matched on an object voted moving (depth vote or scene flow) are removed from "
      "the map: "
      "they were mapped while it stood still and are no longer where the map says");
    v("sample_step_px", sample_step_px,
      "object points are sampled every this many pixels in the mask", Range{1, 1000});
    v("moving_evidence", moving_evidence,
      "outside instance masks, a keypoint is dropped when its map point's depth-test votes over "
      "frames make it more likely moving than not (log-odds below), not on one frame's vote");
    v("moving_prior_log_odds", moving_prior_log_odds,
      "moving evidence: prior log-odds that a map point moves (-1: p = 0.27, so one failed depth "
      "test on a new point drops it, as a one-frame vote would)",
      Range{-20, 20});
    v("moving_vote_log_odds", moving_vote_log_odds,
      "moving evidence: log-odds added by a failed depth test", Range{0, 20});
    v("static_vote_log_odds", static_vote_log_odds,
      "moving evidence: log-odds taken away by a passed depth test (a background point checked "
      "static in 2 frames survives one failure)",
      Range{0, 20});
    v("moving_evidence_min", moving_evidence_min,
      "moving evidence: lower clamp (a long-static point still gives way to two failures in a "
      "row: it may be on something that started moving)",
      Range{-100, 0});
    v("moving_evidence_max", moving_evidence_max,
      "moving evidence: upper clamp (a point voted moving in several frames comes back after 4 "
      "passed tests)",
      Range{0, 100});
    v("residual_movers", residual_movers,
      "young map points (one keyframe) that move together against a pose refitted to the "
      "established points are a mover the segmenter missed: their keypoints are dropped for the "
      "frame (dynamics/residual_movers.hpp)");
    v("residual_instances", residual_instances,
      "a non-prior instance (a chair, a box) whose matches move together against the pose "
      "refitted to the established background points (outside every instance) is moving: cut out "
      "and its map points culled, as by a depth vote (dynamics/residual_movers.hpp; needs "
      "residual_movers)");
    v("residual_min_established", residual_min_established,
      "residual movers: fewest established points matched for the refitted pose (fewer: no test)",
      Range{1, 100000});
    v("residual_region_radius_px", residual_region_radius_px,
      "residual movers: young keypoints this near in the image (px) join one region",
      Range{1, 10000});
    v("residual_region_depth_band_m", residual_region_depth_band_m,
      "residual movers: ... if their depths differ by at most this (m)", Range{0, 100});
    v("residual_region_min_points", residual_region_min_points,
      "residual movers: fewest young keypoints in a region that can be judged", Range{2, 100000});
    v("residual_region_chi2", residual_region_chi2,
      "residual movers: a region moves when n |mean(r / sigma)|^2 exceeds this (13.8: 99.9 % of "
      "chi-square with 2 degrees of freedom: its points' mean residual is not noise) ...",
      Range{0, 1e6});
    v("residual_region_min_px", residual_region_min_px,
      "residual movers: ... and |mean(r / sigma)| is at least this many level-0 pixels (a large "
      "region's tiny common bias is not motion)",
      Range{0, 1000});
  }
};

}  // namespace dynanav
