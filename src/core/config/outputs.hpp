#pragma once
// Config section `outputs` (see core/config.hpp for how sections are loaded and echoed): the
// optional products of a run (issue 15): static map, annotated video, top view, run report.
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().

#include <string>

#include "core/config/range.hpp"

namespace dynanav {

/// Static maps (mapping/) and visual outputs (viz/) written at the end of `dynanav run`.
struct OutputsConfig {
  bool map = false;
  bool video = false;
  bool report = false;
  double cloud_voxel_m = 0.01;
  double octree_resolution_m = 0.05;
  double max_depth_m = 4.0;
  int keyframe_downscale = 2;
  double map_frame_interval_s = 0.5;
  int cloud_pixel_step = 1;
  int octree_pixel_step = 6;
  int mask_dilation_px = 5;
  double walk_min_height_m = 0.3;
  double walk_max_height_m = 1.8;
  double grid_cell_m = 0.05;
  // x264's fastest preset on the video's own worker thread: OpenCV's defaults (preset medium,
  // 3 frame threads + lookahead) cost ~20 ms of CPU per 640x480 frame (docs/maps_and_outputs.md).
  std::string video_encoder_options = "preset=ultrafast,threads=1";
  template <class V>
  void visit(V&& v) {
    v("map", map,
      "write map.ply (dense static cloud), map.bt (OctoMap), occupancy.png and topview.png "
      "(--map)");
    v("video", video, "write annotated.mp4 (or annotated.avi when no H.264 encoder) (--video)");
    v("report", report, "write report.html: accuracy, timing, speeds, messages (--report)");
    v("cloud_voxel_m", cloud_voxel_m, "voxel size of map.ply's downsampling (m)",
      Range{0, 1, Range::kOpenLow});
    v("octree_resolution_m", octree_resolution_m, "OctoMap leaf size of map.bt (m)",
      Range{0, 1, Range::kOpenLow});
    v("max_depth_m", max_depth_m,
      "depth beyond this is not mapped (Kinect depth noise grows with the square of range)",
      Range{0, 100, Range::kOpenLow});
    v("keyframe_downscale", keyframe_downscale,
      "keyframe images are kept at 1/k resolution until the end of the run (bounds memory)",
      Range{1, 16});
    v("map_frame_interval_s", map_frame_interval_s,
      "besides keyframes, keep a frame for the map when this long has passed since the last kept "
      "one (a wearer standing still makes no keyframes, yet the scene may change); 0 = keyframes "
      "only",
      Range{0, 3600});
    v("cloud_pixel_step", cloud_pixel_step,
      "map.ply takes every k-th pixel (rows and columns) of the kept keyframe images",
      Range{1, 64});
    v("octree_pixel_step", octree_pixel_step,
      "map.bt casts a ray for every k-th pixel of the kept images (ray casting dominates the "
      "cost)",
      Range{1, 64});
    v("mask_dilation_px", mask_dilation_px,
      "dynamic instances' masks grow by this many full-resolution pixels before removal (mask "
      "edges lag the body)",
      Range{0, 200});
    v("walk_min_height_m", walk_min_height_m, "occupancy grid: lowest obstacle height above floor",
      Range{-10, 10});
    v("walk_max_height_m", walk_max_height_m, "occupancy grid: highest obstacle height above floor",
      Range{-10, 10});
    v("grid_cell_m", grid_cell_m, "occupancy grid cell size (m)", Range{0, 1, Range::kOpenLow});
    v("video_encoder_options", video_encoder_options,
      "annotated.mp4's libx264 options, key=value,... (FFmpeg's names: preset, crf, tune, "
      "threads, x264-params); an unknown one makes the video fall back to MPEG-4");
  }
};

}  // namespace dynanav
