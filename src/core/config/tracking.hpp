#pragma once
// Config section `tracking` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
// Defaults follow ORB-SLAM2 (Mur-Artal & Tardos, T-RO 2017) for RGB-D input.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Camera-tracking thresholds.
struct TrackingConfig {
  double depth_max_m = 8.0;  // depths beyond this are treated as invalid
  // ORB-SLAM2 starts an RGB-D map from a frame of over 500 keypoints, with depth or not; 500 *with*
  // depth kept a hall whose far end lies beyond the depth range from ever starting. Tracking needs
  // local_map_min_inliers (30): 150 points leave it a fivefold margin.
  int init_min_depth_features = 150;
  int motion_search_radius_px = 15;
  int motion_min_matches = 20;
  int reference_min_matches = 15;
  int min_map_matches = 10;
  int local_map_min_inliers = 30;
  double local_search_radius_factor = 1.0;
  double local_nn_ratio = 0.8;
  int max_local_keyframes = 80;
  int pose_rounds = 4;
  int pose_iterations = 10;
  int keyframe_max_frames = 30;
  double keyframe_ref_ratio = 0.75;
  int keyframe_close_tracked_min = 100;
  int keyframe_close_untracked_max = 70;
  int new_points_min = 100;
  double rolling_shutter_readout_ms = -1.0;
  bool rolling_shutter_online = false;
  double rolling_shutter_online_max_sigma_ms = 1.0;
  // slam/observation_noise: a keypoint blurred over the exposure is found somewhere along its
  // streak; uniformly anywhere on it, the standard deviation is 1/sqrt(12) ~ 0.29 of its length.
  double exposure_ms = -1.0;
  double motion_blur_share = 0.29;
  // slam/persistent_pose: a walker's points do not stay matched for seconds under a pose held
  // by the static structure; what has stayed put that long is the static structure.
  double persistent_point_age_s = 2.0;
  int persistent_min_matches = 30;
  // slam/depth_surface: the static depth outside the masks as pose evidence beside the keypoints.
  double depth_alignment_samples = 100.0;
  int depth_alignment_step_px = 8;
  double depth_alignment_min_sigma_m = 0.01;
  template <class V>
  void visit(V&& v) {
    v("depth_max_m", depth_max_m, "depth samples beyond this distance (m) are ignored",
      Range{0, 100, Range::kOpenLow});
    v("init_min_depth_features", init_min_depth_features,
      "keypoints with valid depth needed to initialise the map from one frame", Range{1, 100000});
    v("motion_search_radius_px", motion_search_radius_px,
      "motion-model projection search radius (px at level 0; doubled on a retry)", Range{1, 1000});
    v("motion_min_matches", motion_min_matches, "matches below which the motion model fails",
      Range{1, 100000});
    v("reference_min_matches", reference_min_matches,
      "descriptor matches with the reference keyframe below which that fallback fails",
      Range{1, 100000});
    v("min_map_matches", min_map_matches, "inlier map matches needed after the first pose fit",
      Range{1, 100000});
    v("local_map_min_inliers", local_map_min_inliers,
      "inliers after local-map tracking below which the frame is lost", Range{1, 100000});
    v("local_search_radius_factor", local_search_radius_factor,
      "local-map projection search radius factor (ORB-SLAM2: 1 for RGB-D)",
      Range{0, 100, Range::kOpenLow});
    v("local_nn_ratio", local_nn_ratio, "best/second-best descriptor ratio in local-map search",
      Range{0, 1, Range::kOpenLow});
    v("max_local_keyframes", max_local_keyframes, "cap on keyframes in the local map",
      Range{1, 10000});
    v("pose_rounds", pose_rounds, "pose-only optimisation rounds (outliers re-classified each)",
      Range{1, 100});
    v("pose_iterations", pose_iterations, "solver iterations per pose-optimisation round",
      Range{1, 1000});
    v("keyframe_max_frames", keyframe_max_frames,
      "frames after which a keyframe may be inserted regardless of mapping state",
      Range{1, 100000});
    v("keyframe_ref_ratio", keyframe_ref_ratio,
      "insert a keyframe when tracked matches fall below this share of the reference's points",
      Range{0, 1});
    v("keyframe_close_tracked_min", keyframe_close_tracked_min,
      "close points tracked below which (with many untracked close ones) a keyframe is needed",
      Range{0, 100000});
    v("keyframe_close_untracked_max", keyframe_close_untracked_max,
      "untracked close points above which (with few tracked) a keyframe is needed",
      Range{0, 100000});
    v("new_points_min", new_points_min,
      "map points created from depth per keyframe before stopping at far points", Range{0, 100000});
    v("rolling_shutter_readout_ms", rolling_shutter_readout_ms,
      "colour camera's rolling-shutter readout time (ms) for keypoint re-timing; -1 = the "
      "camera's own (camera.yaml / built-in calibration), 0 = treat as global shutter",
      Range{-1, 1000});
    v("rolling_shutter_online", rolling_shutter_online,
      "estimate the readout in local bundle adjustment, with the map, starting from "
      "rolling_shutter_readout_ms, and re-time keypoints with each well-determined estimate "
      "(stats.json rolling_shutter.online_stages)");
    v("exposure_ms", exposure_ms,
      "colour camera's exposure time (ms) for the motion blur of keypoints; -1 = the camera's "
      "own (camera.yaml exposure_ms; none known: no blur is modelled), 0 = no blur",
      Range{-1, 1000});
    v("motion_blur_share", motion_blur_share,
      "while the camera moves, a keypoint's position is uncertain along its blur streak (its "
      "motion over the exposure) by this share of the streak's length, as a standard deviation "
      "added to its pyramid level's, in tracking and bundle adjustment; 0 = off",
      Range{0, 10});
    v("persistent_point_age_s", persistent_point_age_s,
      "with dynamics on, a frame's pose is found on matches to map points mapped at least this "
      "long ago (s) when there are persistent_min_matches of them, and the other matches are "
      "judged against it; 0 = off",
      Range{0, 3600});
    v("persistent_min_matches", persistent_min_matches,
      "persistent matches needed to pose the frame on them (else all matches pose it)",
      Range{6, 100000});
    v("depth_alignment_samples", depth_alignment_samples,
      "the last frame's static depth samples (outside every mask) also pose the frame, by their "
      "point-to-plane distance to its depth, weighing together as at most this many independent "
      "samples; 0 = off",
      Range{0, 100000});
    v("depth_alignment_min_sigma_m", depth_alignment_min_sigma_m,
      "the depth joins a pose fit only where the keypoints alone leave the camera's position "
      "looser than this standard deviation (m) along some direction",
      Range{0, 10});
    v("depth_alignment_step_px", depth_alignment_step_px,
      "grid step of those samples, in pixels of the half-resolution depth", Range{1, 100});
    v("rolling_shutter_online_max_sigma_ms", rolling_shutter_online_max_sigma_ms,
      "a local bundle adjustment's readout estimate is used when its standard error (ms) is below "
      "this",
      Range{0, 100, Range::kOpenLow});
  }
};

}  // namespace dynanav
