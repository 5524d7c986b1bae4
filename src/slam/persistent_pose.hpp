#pragma once
// A frame's pose found on the persistent part of the map (issue 18: movers nobody masked, and
// geometry alone when there is no segmenter). Where walkers fill most of the view, most of a
// frame's matches are to points mapped on them in the last keyframes; they move together, so a
// pose fitted to every match follows the crowd (Bonn crowd with `--segmenter none`: 3-4 cm per
// frame while the camera moved 1-3 mm). A walker's points do not stay matched for long under a
// pose held by the static structure (at 1 m/s and 3 m, 6 px per frame: rejected within a frame
// or two), so points that were mapped seconds ago and are still matched are, almost all, the
// static structure. When enough of them are in view the pose is fitted to them alone, every
// other match is judged against that pose (chi-square at 99.9 %: a young static point's
// keyframe error passes, a mover's motion does not), and the pose is refined from there with all
// the matches that pass. With fewer of them (the map's first seconds, a view never seen before)
// every match poses the frame, as before.
#include "core/config/tracking.hpp"
#include "slam/frame.hpp"

namespace dynanav {

/// Keypoint `keypoint` of `frame` is matched to a keyframe-mapped point first mapped at least
/// `min_age_s` before the frame (frame-only points of the motion model never are).
bool isPersistentMatch(const Frame& frame, int keypoint, double min_age_s);

struct PersistentPose {
  bool applied = false;  ///< the pose was found this way (else the frame is untouched)
  int persistent = 0;    ///< persistent matches
  int rejected = 0;      ///< other matches judged off the persistent pose (outliers)
};

/// Poses `frame` as above when config.persistent_point_age_s > 0 and at least
/// config.persistent_min_matches persistent matches exist: sets frame.T_camera_world and
/// frame.outlier (the rejected matches and the final fit's outliers). Otherwise changes nothing.
PersistentPose optimizePoseOnPersistentPoints(Frame& frame, const TrackingConfig& config);

}  // namespace dynanav
