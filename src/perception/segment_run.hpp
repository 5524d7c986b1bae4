#pragma once
// `dynanav segment`: segments a sequence and writes
//   OUT/masks/<rgb stem>.png + OUT/masks.json   (the format the `masks` segmenter reads back)
//   OUT/stats.json                               (per-frame and per-step timing, counts)
// and hands every frame with its instances to `on_frame`, where the CLI draws the overlay video
// and contact sheets (viz/, which depends on perception, not the other way round).
#include <filesystem>
#include <functional>
#include <string>

#include "core/config/io.hpp"
#include "core/config/perception.hpp"
#include "perception/segmenter.hpp"

namespace dynanav {

struct SegmentRunOptions {
  std::filesystem::path sequence_dir;
  std::filesystem::path out_dir;
  SegmenterRequest request;  ///< sequence_dir is filled from the field above
  PerceptionConfig perception;
  IoConfig io;
  int max_frames = -1;   ///< < 0: all
  bool progress = true;  ///< progress bar on stderr when it is a terminal
  /// Called with each segmented frame and the instances written for it (may be empty).
  std::function<void(const RgbdFrame&, const Instances&)> on_frame;
};

struct SegmentRunSummary {
  int frames = 0;              ///< frames segmented
  int skipped = 0;             ///< frames that could not be read
  int frames_with_person = 0;  ///< frames with at least one person instance
  std::string segmenter;
};

/// Throws InputError for a bad sequence folder or segmenter request.
SegmentRunSummary runSegmentation(const SegmentRunOptions& options);

}  // namespace dynanav
