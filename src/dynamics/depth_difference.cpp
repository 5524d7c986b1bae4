#include "dynamics/depth_difference.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {

double depthDifferenceThreshold(double depth_m, const DynamicsConfig& config) {
  return config.depth_diff_min_m + config.depth_diff_per_z2 * depth_m * depth_m;
}

double mapPointDepthSigma(double depth_m, double scale, double bf_px_m) {
  if (!(bf_px_m > 0.0)) return 0.0;
  return depth_m * depth_m * scale / bf_px_m;
}

bool failsDepthTest(const DepthCheck& check, const DynamicsConfig& config) {
  if (!(check.measured_depth_m > 0.f) || !(check.predicted_depth_m > 0.f)) return false;
  double lo = check.measured_depth_m, hi = check.measured_depth_m;
  if (check.nearby_min_m > 0.f) {
    lo = std::min(lo, double(check.nearby_min_m));
    hi = std::max(hi, double(check.nearby_max_m));
  }
  const double predicted = check.predicted_depth_m;
  const double threshold = depthDifferenceThreshold(predicted, config) +
                           config.depth_diff_map_sigmas * double(check.predicted_sigma_m);
  return predicted < lo - threshold || predicted > hi + threshold;
}

DepthDifferenceResult classifyByDepthDifference(const std::vector<DepthCheck>& checks,
                                                const DynamicsConfig& config) {
  DepthDifferenceResult result;
  result.keypoint_dynamic.assign(checks.size(), false);
  std::vector<bool> testable(checks.size(), false);
  for (size_t i = 0; i < checks.size(); ++i) {
    const DepthCheck& c = checks[i];
    testable[i] = c.measured_depth_m > 0.f && c.predicted_depth_m > 0.f;
    if (!testable[i]) continue;
    ++result.checked;
    const bool fails = failsDepthTest(c, config);
    result.keypoint_dynamic[i] = fails;
    if (c.instance != 0) {
      InstanceMotionVote& vote = result.instances[c.instance];
      ++vote.checked;
      vote.failing += fails ? 1 : 0;
    }
  }
  for (auto& [id, vote] : result.instances) {
    vote.dynamic = vote.checked >= config.instance_min_points &&
                   double(vote.failing) >= config.instance_dynamic_share * double(vote.checked);
  }
  // The instance decides for all its keypoints, including those the test could not check
  // (no depth, no map point yet): a moving box's new points must not enter the map either.
  for (size_t i = 0; i < checks.size(); ++i) {
    const auto it = result.instances.find(checks[i].instance);
    if (checks[i].instance != 0 && it != result.instances.end()) {
      result.keypoint_dynamic[i] = it->second.dynamic;
    }
    result.dynamic += result.keypoint_dynamic[i] ? 1 : 0;
  }
  return result;
}

}  // namespace dynanav
