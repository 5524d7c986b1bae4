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
#include <filesystem>

#include "core/camera.hpp"

namespace dynanav {

/// Throws InputError naming the file and key on a missing key or bad value.
PinholeCamera loadCameraYaml(const std::filesystem::path& path);
void saveCameraYaml(const std::filesystem::path& path, const PinholeCamera& camera);

}  // namespace dynanav
