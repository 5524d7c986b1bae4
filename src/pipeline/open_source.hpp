#pragma once
// Which FrameSource a `dynanav run` input means: `openni://[URI]` a live OpenNI2 camera, a
// `.oni` file its playback, anything else a TUM-layout folder (DESIGN.md §2).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "pipeline/frame_source.hpp"

namespace dynanav {

struct SourceRequest {
  std::string input;  ///< SEQ_DIR, openni://[URI] or FILE.oni
  IoConfig io;
  /// --camera: the intrinsics of a device (else its field of view, or a camera.yaml beside the
  /// .oni), or of a folder that has no calibration of its own.
  std::optional<PinholeCamera> camera;
  std::string camera_origin;  ///< the file it came from, for logs and errors
  std::optional<std::pair<int, int>> blackout;
  int max_frames = 0;
  int passes = 1;
};

/// Throws InputError naming the input (or option) when it cannot be opened.
std::unique_ptr<FrameSource> openFrameSource(const SourceRequest& request);

}  // namespace dynanav
