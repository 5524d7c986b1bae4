#pragma once
// A whole run over a TUM-layout sequence (what `dynanav run` does): a SequenceSource feeds the
// System, in order (deterministic) or at the camera's pace (real time); the sinks write
// OUT/trajectory.txt as it goes, keyframes.txt and stats.json at the end; config_used.yaml first.
#include <filesystem>
#include <optional>
#include <utility>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "pipeline/sinks.hpp"

namespace dynanav {

struct RunOptions {
  std::filesystem::path sequence_dir;
  std::filesystem::path out_dir;
  Config config;
  std::optional<PinholeCamera> fallback_camera;  ///< used when the folder says nothing
  std::optional<std::pair<int, int>> blackout;   ///< inclusive 0-based frame range
  int max_frames = 0;                            ///< 0 = all
  int passes = 1;                                ///< --passes: play the sequence this many times
  bool progress = false;                         ///< progress bar on stderr
};

/// Runs the sequence; throws InputError for bad input (missing folder, lists, camera).
RunSummary runSequence(const RunOptions& options);

}  // namespace dynanav
