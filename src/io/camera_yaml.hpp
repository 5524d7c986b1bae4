#pragma once
// camera.yaml: the calibration file a sequence folder may carry (the simulator writes one).
//   width: 640
//   height: 480
//   fx: 525.0
//   fy: 525.0
//   cx: 319.5
//   cy: 239.5
//   distortion: [k1, k2, p1, p2, k3]   # optional, default zeros
//   depth_factor: 5000                  # optional
//   baseline_m: 0.08                    # optional, virtual stereo baseline
//   rolling_shutter_readout_ms: 0       # optional, colour camera readout
// Valid ranges (anything else, NaN, infinity or an unknown key is an InputError naming the file
// and key): width, height 16..8192 whole pixels; fx, fy 1..100000; cx in [0, width], cy in
// [0, height]; each distortion coefficient in [-100, 100]; depth_factor 0.001..1e6; baseline_m
// 0.001..10; rolling_shutter_readout_ms 0..1000.
#include <filesystem>

#include "core/camera.hpp"

namespace dynanav {

/// Throws InputError naming the file and key on a missing key or bad value.
PinholeCamera loadCameraYaml(const std::filesystem::path& path);
void saveCameraYaml(const std::filesystem::path& path, const PinholeCamera& camera);

}  // namespace dynanav
