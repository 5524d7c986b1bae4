#include "pipeline/open_source.hpp"

#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "pipeline/device_source.hpp"

namespace fs = std::filesystem;

namespace dynanav {

std::unique_ptr<FrameSource> openFrameSource(const SourceRequest& request) {
  if (!isDeviceInput(request.input))
    return std::make_unique<SequenceSource>(
        SequenceSourceOptions{request.input, request.io, request.camera, request.blackout,
                              request.max_frames, request.passes});
  if (request.passes > 1)
    throw InputError("--passes", "plays a sequence folder again; " + request.input +
                                     " is a camera or recording");
  DeviceSourceOptions options{deviceRequestFor(request.input), request.camera,
                              request.camera_origin, request.blackout, request.max_frames};
  // A recording may carry its calibration beside it, as a sequence folder does.
  if (!options.camera && options.request.is_file) {
    const fs::path beside = fs::path(request.input).parent_path() / "camera.yaml";
    std::error_code ec;
    if (fs::is_regular_file(beside, ec)) {
      options.camera = loadCameraYaml(beside);
      options.camera_origin = beside.string();
    }
  }
  return std::make_unique<DeviceSource>(options, openOpenNi2Device);
}

}  // namespace dynanav
