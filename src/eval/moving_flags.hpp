#pragma once
// Scoring the dynamics stage's per-frame verdicts against the simulator's ground truth: for each
// object, per frame, "flagged moving" (the run's stats.json dynamics.per_frame.moving_ids) versus
// "moving" (objects_gt.jsonl `dynamic`). Frames where the object is (almost) out of view are
// counted apart: nothing in the image can tell whether it moves there.
#include <filesystem>
#include <string>
#include <vector>

namespace dynanav {

struct ObjectTruth {
  int id = 0;
  std::string class_name;
  bool dynamic = false;
  int visible_px = 0;  ///< pixels of its mask in this frame (objects_gt `points`)
};
using ObjectTruthFrames = std::vector<std::vector<ObjectTruth>>;  ///< per frame

/// Reads a simulator's objects_gt.jsonl (one JSON object per frame). InputError naming the
/// file and line for malformed input.
ObjectTruthFrames readObjectTruth(const std::filesystem::path& path);

/// Per frame, the ids flagged moving (stats.json dynamics.per_frame.moving_ids). InputError if
/// the file has no such series (a run with --dynamic off).
std::vector<std::vector<int>> readMovingFlags(const std::filesystem::path& stats_json);

struct MovingFlagScore {
  int id = 0;
  std::string class_name;
  int true_positive = 0, false_positive = 0, false_negative = 0, true_negative = 0;
  int out_of_view = 0;  ///< frames with fewer than min_visible_px pixels (not scored)
  [[nodiscard]] double precision() const;  ///< NaN when never flagged
  [[nodiscard]] double recall() const;     ///< NaN when never moving in view
};

/// One score per object id (ascending). Frames beyond the shorter of the two series are ignored;
/// the caller checks that the lengths agree.
std::vector<MovingFlagScore> scoreMovingFlags(const ObjectTruthFrames& truth,
                                              const std::vector<std::vector<int>>& flagged,
                                              int min_visible_px);

}  // namespace dynanav
