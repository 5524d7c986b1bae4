#pragma once
// Scale pyramid constants shared by frames, keyframes and the matcher (ORB-SLAM2's
// mvScaleFactors / mvLevelSigma2): level i is the image scaled down by scale_factor^i, and a
// keypoint found at level i has a measurement variance of scale_factor^(2i) px^2.
#include <cmath>
#include <vector>

#include "core/config/orb.hpp"

namespace dynanav {

struct PyramidScales {
  int levels = 8;
  double scale_factor = 1.2;
  double log_scale_factor = std::log(1.2);
  std::vector<float> scale;         ///< scale_factor^i
  std::vector<float> inv_scale;     ///< 1 / scale_factor^i
  std::vector<float> sigma2;        ///< scale_factor^(2i)
  std::vector<float> inv_sigma2;    ///< 1 / scale_factor^(2i)

  static PyramidScales fromConfig(const OrbConfig& config) {
    PyramidScales s;
    s.levels = config.n_levels;
    s.scale_factor = config.scale_factor;
    s.log_scale_factor = std::log(config.scale_factor);
    float f = 1.0f;
    for (int i = 0; i < s.levels; ++i) {
      s.scale.push_back(f);
      s.inv_scale.push_back(1.0f / f);
      s.sigma2.push_back(f * f);
      s.inv_sigma2.push_back(1.0f / (f * f));
      f *= static_cast<float>(config.scale_factor);
    }
    return s;
  }

  /// Pyramid level at which a point with scale-invariance limit `max_distance_m` is expected
  /// when seen from `distance_m` (ORB-SLAM2 MapPoint::PredictScale).
  [[nodiscard]] int predictLevel(double max_distance_m, double distance_m) const {
    const double ratio = max_distance_m / distance_m;
    int level = static_cast<int>(std::ceil(std::log(ratio) / log_scale_factor));
    if (level < 0) level = 0;
    if (level >= levels) level = levels - 1;
    return level;
  }
};

}  // namespace dynanav
