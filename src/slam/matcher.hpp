#pragma once
// Descriptor matching between frames, keyframes and map points (ORB-SLAM2 ORBmatcher, without
// bag-of-words: where ORB-SLAM2 restricts candidates by vocabulary node we match by brute force
// with a ratio test). Keypoints whose `usable` flag is cleared are never matched.
#include <vector>

#include "core/se3.hpp"
#include "slam/frame.hpp"
#include "slam/keyframe.hpp"

namespace dynanav::matcher {

inline constexpr int kDistanceHigh = 100;  ///< ORB-SLAM2 TH_HIGH
inline constexpr int kDistanceLow = 50;    ///< ORB-SLAM2 TH_LOW

/// Projects the last frame's matched points into `current` (pose already predicted) and matches
/// them in a window of radius_px * scale around the projection (motion-model tracking).
int matchLastFrame(Frame& current, const Frame& last, float radius_px, bool check_orientation);

/// Matches map points prepared by the local-map updater (track_in_view set, projection and
/// predicted level stored on the point) in `frame`. Returns the number of new matches.
int matchLocalPoints(Frame& frame, const std::vector<MapPointPtr>& points, float radius_factor,
                     float nn_ratio);

/// Matches the keyframe's map points to the frame's keypoints by descriptor alone.
int matchKeyFrame(const KeyFrame& keyframe, Frame& frame, float nn_ratio, bool check_orientation);

struct IndexPair {
  int first;
  int second;
};
/// Unmatched keypoint pairs of two keyframes that satisfy the epipolar constraint of F_12
/// (x2^T F_12 x1 ... as ORB-SLAM2: line in image 2 = x1^T F_12).
std::vector<IndexPair> matchForTriangulation(const KeyFrame& kf1, const KeyFrame& kf2,
                                             const Mat3& F12, bool check_orientation);

/// Projects points into the keyframe and merges them with the keypoint's existing point or adds
/// an observation (ORB-SLAM2 Fuse). Returns fused-or-added count.
int fuse(KeyFrame& keyframe, const std::vector<MapPointPtr>& points, float radius_px);

/// Keeps only matches whose keypoint-angle difference falls in the three most common bins of a
/// 30-bin histogram (ORB-SLAM2's rotation consistency check). `pairs` hold
/// (query index, angle difference in degrees); returns the indices to drop.
std::vector<int> rotationOutliers(const std::vector<std::pair<int, float>>& pairs);

}  // namespace dynanav::matcher
