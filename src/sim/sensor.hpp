#pragma once
// Sensor models turning the renderer's exact images into what a Kinect-like RGB-D camera gives.
// Depth (structured light): axial noise growing with z^2 (Nguyen et al., 3DIMPVT 2012:
// sigma_z = 0.0012 + 0.0019 (z - 0.4)^2 m), disparity quantisation (1/8 px sub-pixel steps),
// no return outside [min, max] range, none at depth discontinuities, a few random holes.
// Colour: lens blur, exposure drift, pixel noise. Every random draw comes from a stream keyed by
// (seed, frame, row), so results do not depend on thread scheduling.
#include <cstdint>
#include <opencv2/core.hpp>

namespace dynanav::sim {

struct DepthSensorModel {
  double min_depth_m = 0.4;
  double max_depth_m = 4.5;
  double sigma_a_m = 0.0012;      ///< noise at 0.4 m
  double sigma_b_per_m = 0.0019;  ///< growth with (z - 0.4)^2
  double focal_px = 525.0;
  double baseline_m = 0.075;  ///< projector-camera baseline (disparity = f b / z)
  double disparity_step_px = 0.125;
  double edge_jump_m = 0.04;    ///< a 3x3 depth range above edge_jump_m + edge_jump_rel * z
  double edge_jump_rel = 0.03;  ///< ... is a discontinuity: no return there
  int holes_per_frame = 4;      ///< elliptic dropouts (glossy or dark patches)
  double dropout_probability = 0.002;

  /// The noise level at depth z (m).
  [[nodiscard]] double sigma(double z) const {
    return sigma_a_m + sigma_b_per_m * (z - 0.4) * (z - 0.4);
  }
};

struct ColourSensorModel {
  double blur_sigma_px = 0.6;
  double noise_sigma = 2.0;          ///< per channel, in 8-bit levels
  double exposure_amplitude = 0.05;  ///< slow gain drift of +-5 %
  double exposure_period_s = 5.3;
};

/// Kinect-like depth from exact depth (CV_32F metres, 0 = nothing). Output CV_32F, 0 = invalid.
cv::Mat simulateDepth(const cv::Mat& depth_true_m, const DepthSensorModel& model, uint64_t seed,
                      int frame);

/// Blur, exposure drift and noise applied to a rendered BGR image in place. `noise` false keeps
/// only the blur (the noise-free option).
void simulateColour(cv::Mat& bgr, const ColourSensorModel& model, uint64_t seed, int frame,
                    double t_s, bool noise);

}  // namespace dynanav::sim
