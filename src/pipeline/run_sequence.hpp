#pragma once
// A whole run over a TUM-layout sequence (what `dynanav run` does): feeds frames to the System,
// writes OUT/trajectory.txt as it goes, keyframes.txt, stats.json and config_used.yaml at the
// end. Corrupt frames are skipped, counted and logged; a blackout range is replaced by black
// images with invalid depth (a tracking-loss drill).
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"

namespace dynanav {

struct RunOptions {
  std::filesystem::path sequence_dir;
  std::filesystem::path out_dir;
  Config config;
  std::optional<PinholeCamera> fallback_camera;   ///< used when the folder says nothing
  std::optional<std::pair<int, int>> blackout;    ///< inclusive 0-based frame range
  int max_frames = 0;                             ///< 0 = all
  bool progress = false;                          ///< progress bar on stderr
};

struct RunSummary {
  int frames = 0;
  int tracked = 0;
  int lost = 0;
  int skipped = 0;  ///< unreadable frames
  bool initialised = false;
  std::vector<int> relocalisation_frames;  ///< input frames on which tracking came back (issue 4)
};

/// Runs the sequence; throws InputError for bad input (missing folder, lists, camera).
RunSummary runSequence(const RunOptions& options);

}  // namespace dynanav
