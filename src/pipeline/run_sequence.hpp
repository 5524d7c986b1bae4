#pragma once
// A whole run over a TUM-layout sequence, an OpenNI2 camera or an .oni recording (what `dynanav
// run` does): a FrameSource (open_source.hpp) feeds the System, in order (deterministic) or at the
// camera's pace (real time); the sinks write OUT/trajectory.txt as it goes, keyframes.txt and
// stats.json at the end; config_used.yaml first.
#include <filesystem>
#include <optional>
#include <utility>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "pipeline/sinks.hpp"

namespace dynanav {

struct RunOptions {
  std::filesystem::path sequence_dir;  ///< SEQ_DIR, openni://[URI] or FILE.oni
  std::filesystem::path out_dir;
  Config config;
  /// --camera: a device's intrinsics, or a folder's when the folder says nothing.
  std::optional<PinholeCamera> fallback_camera;
  std::string camera_origin;                    ///< the file fallback_camera came from
  std::optional<std::pair<int, int>> blackout;  ///< inclusive 0-based frame range
  int max_frames = 0;                           ///< 0 = all
  int passes = 1;                               ///< --passes: play the sequence this many times
  bool progress = false;                        ///< progress bar on stderr
};

/// Runs the sequence; throws InputError for bad input (missing folder, lists, camera).
RunSummary runSequence(const RunOptions& options);

}  // namespace dynanav
