#include "eval/trajectory_metrics.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/error.hpp"

namespace dynanav {

ErrorStats errorStats(const std::vector<double>& errors) {
  ErrorStats s;
  s.count = errors.size();
  if (errors.empty()) return s;
  const double n = double(errors.size());
  double sum = 0, sum_sq = 0;
  for (const double e : errors) {
    sum += e;
    sum_sq += e * e;
  }
  s.mean = sum / n;
  s.rmse = std::sqrt(sum_sq / n);
  double var = 0;
  for (const double e : errors) var += (e - s.mean) * (e - s.mean);
  s.std = std::sqrt(var / n);
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  const size_t mid = sorted.size() / 2;
  s.median = sorted.size() % 2 ? sorted[mid] : 0.5 * (sorted[mid - 1] + sorted[mid]);
  s.min = sorted.front();
  s.max = sorted.back();
  return s;
}

std::vector<std::pair<size_t, size_t>> associateStamps(const std::vector<double>& first,
                                                       const std::vector<double>& second,
                                                       double max_dt_s, double offset_s) {
  std::vector<std::tuple<double, size_t, size_t>> candidates;
  for (size_t i = 0; i < first.size(); ++i) {
    // second is sorted: only a window of it can be within max_dt.
    auto it = std::lower_bound(second.begin(), second.end(), first[i] - offset_s - max_dt_s);
    for (size_t j = size_t(it - second.begin()); j < second.size(); ++j) {
      const double gap = std::abs(first[i] - (second[j] + offset_s));
      if (second[j] + offset_s > first[i] + max_dt_s) break;
      if (gap < max_dt_s) candidates.emplace_back(gap, i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> used_first(first.size()), used_second(second.size());
  std::vector<std::pair<size_t, size_t>> matches;
  for (const auto& [gap, i, j] : candidates) {
    if (used_first[i] || used_second[j]) continue;
    used_first[i] = used_second[j] = true;
    matches.emplace_back(i, j);
  }
  std::sort(matches.begin(), matches.end());
  return matches;
}

size_t findClosestIndex(const std::vector<double>& sorted, double t) {
  size_t beginning = 0, end = sorted.size(), best = 0;
  double difference = std::abs(sorted[0] - t);
  while (beginning < end) {
    const size_t middle = (end + beginning) / 2;
    if (std::abs(sorted[middle] - t) < difference) {
      difference = std::abs(sorted[middle] - t);
      best = middle;
    }
    if (t == sorted[middle]) return middle;
    if (sorted[middle] > t) {
      end = middle;
    } else {
      beginning = middle + 1;
    }
  }
  return best;
}

SE3 alignRigid(const std::vector<Vec3>& model, const std::vector<Vec3>& data) {
  const size_t n = model.size();
  Vec3 model_mean = Vec3::Zero(), data_mean = Vec3::Zero();
  for (size_t i = 0; i < n; ++i) {
    model_mean += model[i];
    data_mean += data[i];
  }
  model_mean /= double(n);
  data_mean /= double(n);
  Mat3 W = Mat3::Zero();  // sum of outer(model_i, data_i), zero-centred (evaluate_ate.py align)
  for (size_t i = 0; i < n; ++i) W += (model[i] - model_mean) * (data[i] - data_mean).transpose();
  Eigen::JacobiSVD<Mat3> svd(W.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 S = Mat3::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2, 2) = -1;
  SE3 T = SE3::Identity();
  T.linear() = svd.matrixU() * S * svd.matrixV().transpose();
  T.translation() = data_mean - T.linear() * model_mean;
  return T;
}

namespace {
std::vector<double> stampsOf(const std::vector<StampedPose>& poses) {
  std::vector<double> stamps(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) stamps[i] = poses[i].stamp_s;
  return stamps;
}
}  // namespace

AteResult computeAte(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est,
                     double max_dt_s) {
  AteResult result;
  result.estimated = est.size();
  const auto matches = associateStamps(stampsOf(gt), stampsOf(est), max_dt_s);
  result.matched = matches.size();
  if (matches.size() < 3) {
    throw InputError("", "only " + std::to_string(matches.size()) +
                             " estimated poses have a ground-truth pose within " +
                             std::to_string(max_dt_s) + " s: wrong files or time base?");
  }
  std::vector<Vec3> model, data;
  for (const auto& [i_gt, i_est] : matches) {
    data.push_back(gt[i_gt].T_world_camera.translation());
    model.push_back(est[i_est].T_world_camera.translation());
  }
  result.T_gt_est = alignRigid(model, data);
  std::vector<double> errors;
  for (size_t k = 0; k < model.size(); ++k) {
    errors.push_back((result.T_gt_est * model[k] - data[k]).norm());
    result.error_by_stamp_m.emplace_back(est[matches[k].second].stamp_s, errors.back());
  }
  std::sort(result.error_by_stamp_m.begin(), result.error_by_stamp_m.end());
  result.translation_m = errorStats(errors);
  return result;
}

RpeResult computeRpe(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est) {
  if (gt.size() < 2 || est.size() < 2)
    throw InputError("", "RPE needs at least 2 poses in each file");
  const auto stamps_gt = stampsOf(gt);
  const auto stamps_est = stampsOf(est);
  std::vector<double> intervals;
  for (size_t k = 1; k < stamps_gt.size(); ++k)
    intervals.push_back(stamps_gt[k] - stamps_gt[k - 1]);
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  double median = intervals[intervals.size() / 2];
  if (intervals.size() % 2 == 0) {  // numpy.median averages the two middle values
    const double lower =
        *std::max_element(intervals.begin(), intervals.begin() + intervals.size() / 2);
    median = 0.5 * (median + lower);
  }
  const double gt_max_dt = 2.0 * median;

  std::vector<double> trans, rot;
  const size_t n = est.size();
  for (size_t i = 0; i < n; ++i) {
    // Fixed delta of one frame: j is the closest index to i + 1; pairs ending at the last
    // pose are dropped, as in evaluate_rpe.py.
    const size_t j = std::min(i + 1, n - 1);
    if (j == n - 1) continue;
    const size_t g0 = findClosestIndex(stamps_gt, stamps_est[i]);
    const size_t g1 = findClosestIndex(stamps_gt, stamps_est[j]);
    if (std::abs(stamps_gt[g0] - stamps_est[i]) > gt_max_dt ||
        std::abs(stamps_gt[g1] - stamps_est[j]) > gt_max_dt) {
      continue;
    }
    const SE3 rel_est = est[j].T_world_camera.inverse() * est[i].T_world_camera;
    const SE3 rel_gt = gt[g1].T_world_camera.inverse() * gt[g0].T_world_camera;
    const SE3 error = rel_est.inverse() * rel_gt;
    trans.push_back(error.translation().norm());
    rot.push_back(rotationAngle(error.linear()) * 180.0 / M_PI);
  }
  if (trans.size() < 2)
    throw InputError("", "RPE: fewer than 2 pose pairs overlap the ground truth");
  RpeResult result;
  result.translation_m = errorStats(trans);
  result.rotation_deg = errorStats(rot);
  result.pairs = trans.size();
  return result;
}

Coverage computeCoverage(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est,
                         size_t total_frames, double max_gap_s,
                         std::optional<std::pair<double, double>> frame_span) {
  Coverage c;
  c.tracked_frames = est.size();
  c.total_frames = total_frames;
  if (gt.empty()) return c;
  double lo = gt.front().stamp_s, hi = gt.back().stamp_s;
  if (frame_span) {
    lo = std::max(lo, frame_span->first);
    hi = std::min(hi, frame_span->second);
  }
  c.gt_span_s = std::max(0.0, hi - lo);
  for (size_t k = 1; k < est.size(); ++k) {
    const double a = std::max(lo, est[k - 1].stamp_s), b = std::min(hi, est[k].stamp_s);
    if (b > a && est[k].stamp_s - est[k - 1].stamp_s <= max_gap_s) c.covered_span_s += b - a;
  }
  return c;
}

}  // namespace dynanav
