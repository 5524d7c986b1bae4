#pragma once
// Residuals "against the static map" for mover rejection (issue 18: movers the detector misses).
// A keypoint is matched either to an established map point (observed from two keyframes or more)
// or to a young one (one keyframe so far: mapped from that keyframe's depth alone, possibly on a
// person nobody masked). Young points on something that moves sideways pass the depth test and
// pull the frame's pose with them, so their residual under the frame's own pose understates
// their motion. Refitting the pose to the established points alone, and measuring every match
// against that pose, gives each keypoint's residual against the part of the map that has
// already been seen to stay put.
#include <vector>

#include "core/config/tracking.hpp"
#include "slam/frame.hpp"

namespace dynanav {

struct MapResidual {
  bool valid = false;  ///< a usable match, and a pose refitted to enough established points
  bool young = false;  ///< its map point is observed by fewer than two keyframes
  /// The frame's own pose optimisation rejected the match (a mover's point, or a false match);
  /// only residualsToBackground() measures such matches.
  bool outlier = false;
  float du_px = 0.f;     ///< measured minus projected pixel, undistorted (x)
  float dv_px = 0.f;     ///< (y)
  float sigma_px = 1.f;  ///< the keypoint's pyramid level's pixel sigma
  /// The keypoint was blurred (slam/observation_noise.hpp): `whitened` is its residual in units of
  /// its noise, the level's sigma across its streak and more along it.
  bool blurred = false;
  Eigen::Vector2f whitened = Eigen::Vector2f::Zero();

  /// The residual in units of its noise: (du, dv) / sigma, or `whitened` for a blurred keypoint.
  [[nodiscard]] Eigen::Vector2d normalised() const {
    return blurred ? Eigen::Vector2d(whitened.cast<double>())
                   : Eigen::Vector2d(du_px / sigma_px, dv_px / sigma_px);
  }
};

/// Per keypoint of `frame`: its residual under the frame's pose refitted (from the frame's
/// current pose, which is not changed) to the matches of established points only. All invalid
/// when fewer than `min_established` established points are matched. The caller holds the map
/// lock.
std::vector<MapResidual> residualsToEstablishedPoints(const Frame& frame,
                                                      const TrackingConfig& config,
                                                      int min_established);

/// Per keypoint of `frame` with a match (its own pose's outliers too): its residual under the
/// frame's pose refitted to the established points outside every instance (keypoint
/// instance_id 0: the background). An object the segmenter outlines but nobody has found moving
/// yet (a box pushed sideways) has established points that can pull the frame's own pose, and
/// with it the pose refitted to all established points; the background's pose shows it. All
/// invalid when fewer than `min_established` background points are matched. The caller holds
/// the map lock.
std::vector<MapResidual> residualsToBackground(const Frame& frame, const TrackingConfig& config,
                                               int min_established);

}  // namespace dynanav
