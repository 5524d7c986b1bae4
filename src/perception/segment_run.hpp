#pragma once
// `dynanav segment`: segments a sequence and writes
//   OUT/masks/<rgb stem>.png + OUT/masks.json   (the format the `masks` segmenter reads back)
//   OUT/overlay.mp4 (H.264, else MPEG-4) or OUT/overlay.avi (MJPG) when no MP4 encoder exists
//   OUT/stats.json                               (per-frame and per-step timing, counts)
//   OUT/contact/sheet_NNN.png (optional)         overlays of 48 frames per sheet, numbered, for
//                                                checking by eye what the segmenter found
#include <filesystem>
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
  bool video = true;     ///< write the overlay video
  bool progress = true;  ///< progress bar on stderr when it is a terminal
  bool contact_sheets = false;  ///< OUT/contact/sheet_NNN.png: 48 overlay thumbnails each
};

struct SegmentRunSummary {
  int frames = 0;              ///< frames segmented
  int skipped = 0;             ///< frames that could not be read
  int frames_with_person = 0;  ///< frames with at least one person instance
  std::string segmenter;
  std::filesystem::path video;  ///< empty when no video was written
};

/// Throws InputError for a bad sequence folder or segmenter request.
SegmentRunSummary runSegmentation(const SegmentRunOptions& options);

}  // namespace dynanav
