#pragma once
// What the pipeline reports for each frame it processed (DESIGN.md §1): the contract every front
// end and writer consumes (trajectory, stats, objects, events, video, map, audio). Nothing else
// leaves the pipeline per frame.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/feedback_event.hpp"
#include "core/se3.hpp"
#include "core/tracked_object.hpp"
#include "core/tracking_state.hpp"
#include "dynamics/frame_dynamics.hpp"
#include "perception/instances.hpp"

namespace dynanav {

/// The static/dynamic verdict on one of the frame's instances.
struct InstanceVerdict {
  uint16_t id = 0;             ///< label in FrameResult::instances
  bool prior_dynamic = false;  ///< its class may move (people): cut out of SLAM whatever it does
  bool moving = false;  ///< found moving this frame (depth test, scene flow, or still cut out)
  bool verified_static = false;  ///< a prior object scene flow found standing still
};

struct FrameResult {
  int index = 0;  ///< position in the input sequence
  double stamp_s = 0.0;
  double arrival_s =
      0.0;  ///< when the source delivered it (steady clock, seconds since the run began)
  TrackingState state = TrackingState::kNotInitialised;
  bool tracked = false;  ///< pose valid (state ok)
  SE3 T_world_camera = SE3::Identity();
  bool keyframe = false;
  bool recovered = false;  ///< tracking came back after a loss on this frame
  int keypoints = 0;
  int inliers = 0;        ///< local-map inliers
  size_t map_points = 0;  ///< in the map after this frame
  size_t map_keyframes = 0;
  Instances instances;  ///< the frame's people and objects (labels CV_16U + records)
  std::vector<InstanceVerdict> verdicts;  ///< one per instance, in instance order
  std::optional<FrameDynamics> dynamics;  ///< what the dynamics steps decided (none: dynamics off)
  std::vector<TrackedObject> objects;     ///< step 8: tracked movers and obstacles
  std::vector<FeedbackEvent> events;      ///< step 9: messages raised on this frame
  double latency_ms = 0.0;                ///< from arrival to this result
};

}  // namespace dynanav
