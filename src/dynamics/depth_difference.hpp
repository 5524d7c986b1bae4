#pragma once
// Non-prior movers (a pushed box, a moved chair) by the depth-difference test of DynaSLAM
// (Bescos et al., RA-L 2018, §III-C) with the paper's change (Ou et al. 2022, §3.2): instead of
// region growing from dynamic points, the instance mask decides — if enough of an instance's
// keypoints fail the test, the whole instance is dynamic. Keypoints outside any mask are judged
// one by one.
//
// Inputs are per keypoint, after the initial pose: the depth the sensor measured and the depth
// its matched map point should have when projected with that pose.
#include <cstdint>
#include <map>
#include <vector>

#include "core/config/dynamics.hpp"

namespace dynanav {

struct DepthCheck {
  float measured_depth_m = 0.f;   ///< sensor depth at the keypoint (<= 0: none)
  float predicted_depth_m = 0.f;  ///< depth of its map point in this frame (<= 0: no map point)
  uint16_t instance = 0;          ///< instance label under the keypoint (0 = none)
  /// Range of the depths within the pixels the keypoint may be misregistered by while the camera
  /// moves (depth_tolerance.hpp); 0 = none: the keypoint's own depth only.
  float nearby_min_m = 0.f;
  float nearby_max_m = 0.f;
  /// Depth sigma of the map point under the SLAM's RGB-D model (mapPointDepthSigma); 0 = exact.
  float predicted_sigma_m = 0.f;
};

struct InstanceMotionVote {
  int checked = 0;  ///< keypoints with both depths
  int failing = 0;  ///< of them, failing the depth test
  bool dynamic = false;
};

struct DepthDifferenceResult {
  std::vector<bool> keypoint_dynamic;                ///< one per input keypoint
  std::map<uint16_t, InstanceMotionVote> instances;  ///< by instance id (ordered: deterministic)
  int checked = 0;
  int dynamic = 0;
};

/// Threshold grows with depth squared, like structured-light depth noise.
double depthDifferenceThreshold(double depth_m, const DynamicsConfig& config);

/// Depth sigma (m) of a map point at `depth_m` seen by a keypoint at pyramid scale `scale`
/// under the SLAM's RGB-D model: the virtual right image's u_r = u - bf/z has a sigma of `scale`
/// px, so one sigma of u_r is a depth change of z² · scale / bf. Bundle adjustment weighs the
/// depth that way, so a far, coarse point's map depth is little better than this.
double mapPointDepthSigma(double depth_m, double scale, double bf_px_m);

/// True if a keypoint fails the depth test: both depths valid and the predicted depth lies more
/// than the threshold (depthDifferenceThreshold + depth_diff_map_sigmas × predicted_sigma_m)
/// beyond the measured depths (its own, and the nearby range when given).
bool failsDepthTest(const DepthCheck& check, const DynamicsConfig& config);

/// Runs the test on every keypoint and the instance vote; a keypoint is dynamic if it fails the
/// test itself, or lies in an instance voted dynamic.
DepthDifferenceResult classifyByDepthDifference(const std::vector<DepthCheck>& checks,
                                                const DynamicsConfig& config);

}  // namespace dynanav
