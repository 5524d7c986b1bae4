#pragma once
// When to make the current frame a keyframe, and making it (ORB-SLAM2 Tracking::NeedNewKeyFrame
// and CreateNewKeyFrame for RGB-D).
#include "core/config/tracking.hpp"
#include "slam/frame.hpp"
#include "slam/keyframe.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct KeyFrameDecisionInput {
  uint64_t frames_since_last_keyframe = 0;
  int matches_inliers = 0;       ///< local-map inliers of the current frame
  bool mapper_idle = true;       ///< local mapping is waiting for work
  bool mapper_accepts = true;    ///< local mapping's queue has room
  size_t map_keyframes = 0;
};

/// ORB-SLAM2's rules: insert when the frame tracks too few of the reference keyframe's points
/// (or too few close points while many close ones are untracked) and either enough frames have
/// passed, mapping is idle, or tracking is getting weak.
bool needNewKeyFrame(const Frame& frame, const KeyFrame& reference, const KeyFrameDecisionInput& in,
                     const TrackingConfig& config);

/// Makes the frame a keyframe in `map` and creates map points for its closest unmatched
/// keypoints with depth (all closer than the close-depth threshold, at least
/// `config.new_points_min`). The frame's matches are updated to the new points. The keyframe's
/// observations of existing points are added by local mapping.
KeyFramePtr createKeyFrame(Frame& frame, Map& map, const TrackingConfig& config);

}  // namespace dynanav
