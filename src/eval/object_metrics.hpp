#pragma once
// Scoring tracked objects (objects.jsonl) against the simulator's ground truth (objects_gt.jsonl)
// for `dynanav eval-objects`. Frames pair by nearest stamp (within max_dt_s). In each pair every
// estimated object is matched to a ground-truth object by position (greedy, nearest first, within
// max_match_m). Only ground-truth objects at least min_visible_share in view are scored
// (objects_gt `in_view` = visible pixels / pixels of its whole silhouette alone, written by the
// simulator); an estimate matched to a less visible object is neither scored nor false.
// Speed RMSE is given over every matched frame and, separately, over the frames whose estimate
// reports its velocity as known (a new track's first frames carry the prior, velocity zero).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "io/objects_jsonl.hpp"

namespace dynanav {

struct ObjectMetricsOptions {
  double max_match_m = 0.5;
  double min_visible_share = 0.3;
  double max_dt_s = 0.02;
  double moving_mps = 0.05;  ///< ground-truth speed above which an object counts as moving
};

struct ObjectScore {
  uint64_t gt_id = 0;
  std::string class_name;
  int scored_frames = 0;  ///< frames at least min_visible_share in view
  int matched = 0;
  int id_switches = 0;  ///< matched to another track id than the last time it was matched
  double position_rmse_m = 0.0;
  double speed_rmse_mps = 0.0;
  double velocity_rmse_mps = 0.0;  ///< of the vector difference
  int moving_frames = 0;           ///< matched frames with ground-truth speed > moving_mps
  double speed_rmse_moving_mps = 0.0;
  int stopped_frames = 0;  ///< matched frames standing still
  double speed_max_stopped_mps = 0.0;
  double speed_mean_stopped_mps = 0.0;
  /// RMSE of the speed over the stopped frames: the statistic the moving frames are scored with
  double speed_rmse_stopped_mps = 0.0;
  int speed_known_frames = 0;         ///< matched frames whose estimate has velocity_known
  double speed_rmse_known_mps = 0.0;  ///< speed RMSE over those frames only
  [[nodiscard]] double recall() const {
    return scored_frames ? double(matched) / scored_frames : 0.0;
  }
  [[nodiscard]] double switchesPer100() const {
    return scored_frames ? 100.0 * id_switches / scored_frames : 0.0;
  }
};

struct ObjectMetrics {
  int frames = 0;  ///< paired frames
  int scored = 0, matched = 0;
  int id_switches = 0;
  int false_tracks = 0;     ///< estimated objects (per frame) with no ground truth near
  int false_track_ids = 0;  ///< distinct track ids ever counted false
  double position_rmse_m = 0.0;
  double speed_rmse_mps = 0.0;
  double velocity_rmse_mps = 0.0;
  /// Matched frames whose estimate reports its velocity as known (TrackedObject::velocity_known;
  /// a young track's prior is not) and the speed RMSE over them; speed_rmse_mps counts all.
  int speed_known_frames = 0;
  double speed_rmse_known_mps = 0.0;
  std::vector<ObjectScore> objects;  ///< per ground-truth id, ascending
  [[nodiscard]] double recall() const { return scored ? double(matched) / scored : 0.0; }
};

ObjectMetrics scoreObjects(const std::vector<ObjectsFrame>& gt,
                           const std::vector<ObjectsFrame>& est,
                           const ObjectMetricsOptions& options = {});

/// Without ground truth (real sequences): per track, how often its speed lies in a band.
struct TrackSpeedShare {
  uint64_t id = 0;
  std::string class_name;
  int frames = 0;                 ///< frames it was reported
  int dynamic_frames = 0;         ///< of them, reported moving
  int in_band = 0;                ///< dynamic frames with speed in [min, max]
  double median_speed_mps = 0.0;  ///< over dynamic frames
  [[nodiscard]] double share() const {
    return dynamic_frames ? double(in_band) / dynamic_frames : 0.0;
  }
};
std::vector<TrackSpeedShare> trackSpeedShares(const std::vector<ObjectsFrame>& est, double min_mps,
                                              double max_mps);

}  // namespace dynanav
