#pragma once
// Trajectory accuracy exactly as the TUM RGB-D benchmark scripts compute it (DESIGN.md §3):
//  - ATE: evaluate_ate.py (associate within 0.02 s greedily by smallest gap, Horn/Kabsch SE(3)
//    alignment of estimate onto ground truth, no scale; statistics of translation residuals).
//  - RPE: evaluate_rpe.py --fixed_delta --delta 1 --delta_unit f (pairs of consecutive estimated
//    poses, the nearest ground-truth stamp without interpolation, the pair ending at the last pose
//    dropped, pairs dropped when a ground-truth stamp is > 2x the median GT interval away).
#include <optional>
#include <vector>

#include "io/trajectory.hpp"

namespace dynanav {

struct ErrorStats {
  double rmse = 0, mean = 0, median = 0, std = 0, min = 0, max = 0;
  size_t count = 0;
};
/// Statistics as numpy computes them in the TUM scripts (std is the population std).
ErrorStats errorStats(const std::vector<double>& errors);

struct AteResult {
  ErrorStats translation_m;
  SE3 T_gt_est = SE3::Identity();  ///< alignment applied to the estimate
  size_t matched = 0;              ///< estimated poses with a ground-truth pose within max_dt
  size_t estimated = 0;
  /// Per matched pose, in time order: (the estimate's stamp in s, its aligned error in m).
  std::vector<std::pair<double, double>> error_by_stamp_m;
};

struct RpeResult {
  ErrorStats translation_m;
  ErrorStats rotation_deg;
  size_t pairs = 0;
};

struct Coverage {
  size_t tracked_frames = 0;    ///< estimated poses
  size_t total_frames = 0;      ///< input frames, when known (0 = unknown)
  double covered_span_s = 0.0;  ///< time of the GT span covered by the estimate
  double gt_span_s = 0.0;       ///< GT span (restricted to the input frames' span when known)
};

/// Greedy association of two stamp lists (associate.py): index pairs sorted by the first list.
std::vector<std::pair<size_t, size_t>> associateStamps(const std::vector<double>& first,
                                                       const std::vector<double>& second,
                                                       double max_dt_s, double offset_s = 0.0);

/// find_closest_index() of the TUM scripts (a binary search that keeps the best visited entry).
size_t findClosestIndex(const std::vector<double>& sorted, double t);

/// Horn/Kabsch alignment: T such that T * model_i ~ data_i in the least-squares sense.
SE3 alignRigid(const std::vector<Vec3>& model, const std::vector<Vec3>& data);

/// Throws InputError when fewer than 3 poses match.
AteResult computeAte(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est,
                     double max_dt_s = 0.02);

/// Throws InputError when fewer than 2 pairs remain.
RpeResult computeRpe(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est);

/// Coverage of the GT span by the estimate. A gap between consecutive estimated poses longer than
/// `max_gap_s` counts as uncovered. `frame_span` (first, last input frame stamp) restricts the GT
/// span to the part the input frames could cover.
Coverage computeCoverage(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est,
                         size_t total_frames, double max_gap_s,
                         std::optional<std::pair<double, double>> frame_span = std::nullopt);

}  // namespace dynanav
