#pragma once
// What the pipeline reports for each input frame; front ends (CLI, viz, audio) consume only this.
// Later issues add detected objects and warning events.
#include <cstddef>

#include "core/se3.hpp"
#include "slam/tracker.hpp"

namespace dynanav {

struct FrameResult {
  int index = 0;         ///< position in the input sequence
  double stamp_s = 0.0;
  TrackingState state = TrackingState::kNotInitialised;
  bool tracked = false;  ///< pose valid (state ok)
  SE3 T_world_camera = SE3::Identity();
  bool keyframe = false;
  bool recovered = false;  ///< tracking came back after a loss on this frame
  int keypoints = 0;
  int inliers = 0;            ///< local-map inliers
  size_t map_points = 0;      ///< in the map after this frame
  size_t map_keyframes = 0;
  double latency_ms = 0.0;    ///< process() wall time for this frame
};

}  // namespace dynanav
