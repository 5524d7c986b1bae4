// camera.yaml (loadCameraYaml): a camera that loads must be usable (finite, positive focal).
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "io/camera_yaml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "camera.yaml");
  try {
    const dynanav::PinholeCamera camera = dynanav::loadCameraYaml(path);
    if (!(camera.fx > 0 && camera.fy > 0 && std::isfinite(camera.cx) && std::isfinite(camera.cy) &&
          camera.width > 0 && camera.height > 0 && camera.depth_factor > 0))
      std::abort();  // validation let an unusable camera through
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
