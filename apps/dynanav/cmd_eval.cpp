// dynanav eval: trajectory accuracy (ATE, RPE) and coverage with the TUM benchmark conventions.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "eval/trajectory_metrics.hpp"
#include "io/sequence.hpp"

namespace dynanav::cli {
namespace {

struct EvalOptions {
  std::string gt_path;
  std::string est_path;
  std::string sequence_dir;
  double max_dt_s = 0.02;
  bool json = false;
};

nlohmann::json toJson(const ErrorStats& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"std", s.std},
          {"min", s.min},   {"max", s.max},   {"count", s.count}};
}

int runEval(const EvalOptions& opt) {
  const auto gt = readTrajectory(opt.gt_path);
  const auto est = readTrajectory(opt.est_path);
  if (gt.empty()) throw InputError(opt.gt_path, "no poses");
  if (est.empty()) throw InputError(opt.est_path, "no poses: tracking never succeeded?");

  size_t total_frames = 0;
  std::optional<std::pair<double, double>> frame_span;
  if (!opt.sequence_dir.empty()) {
    IoConfig io;
    io.max_association_dt_s = opt.max_dt_s;
    const auto pairs = TumSequence::open(opt.sequence_dir, io, PinholeCamera{}).pairs();
    total_frames = pairs.size();
    frame_span = std::make_pair(pairs.front().rgb.stamp_s, pairs.back().rgb.stamp_s);
  }
  const AteResult ate = computeAte(gt, est, opt.max_dt_s);
  const RpeResult rpe = computeRpe(gt, est);
  // A gap of more than 3 median frame intervals in the estimate is time not covered.
  std::vector<double> gaps;
  for (size_t k = 1; k < est.size(); ++k) gaps.push_back(est[k].stamp_s - est[k - 1].stamp_s);
  double median_gap = 1.0 / 30.0;
  if (!gaps.empty()) {
    std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
    median_gap = gaps[gaps.size() / 2];
  }
  const Coverage cov = computeCoverage(gt, est, total_frames, 3.0 * median_gap, frame_span);
  const double span_share = cov.gt_span_s > 0 ? cov.covered_span_s / cov.gt_span_s : 0.0;

  if (opt.json) {
    nlohmann::json out = {
        {"ate_m", toJson(ate.translation_m)},
        {"rpe_translation_m", toJson(rpe.translation_m)},
        {"rpe_rotation_deg", toJson(rpe.rotation_deg)},
        {"matched_poses", ate.matched},
        {"estimated_poses", ate.estimated},
        {"rpe_pairs", rpe.pairs},
        {"coverage", {{"tracked_frames", cov.tracked_frames},
                      {"total_frames", cov.total_frames},
                      {"covered_span_s", cov.covered_span_s},
                      {"gt_span_s", cov.gt_span_s},
                      {"span_share", span_share}}}};
    std::cout << out.dump(2) << std::endl;
    return kExitOk;
  }
  const auto& a = ate.translation_m;
  std::cout << fmt::format("ATE  rmse {:.6f} m  mean {:.6f}  median {:.6f}  std {:.6f}  max {:.6f}  "
                           "({} of {} estimated poses matched)\n",
                           a.rmse, a.mean, a.median, a.std, a.max, ate.matched, ate.estimated);
  std::cout << fmt::format("RPE  translation rmse {:.6f} m/frame  rotation rmse {:.6f} deg/frame  "
                           "({} pairs)\n",
                           rpe.translation_m.rmse, rpe.rotation_deg.rmse, rpe.pairs);
  const std::string frames =
      cov.total_frames ? fmt::format("{}/{} frames tracked", cov.tracked_frames, cov.total_frames)
                       : fmt::format("{} poses (pass --sequence for frame coverage)", cov.tracked_frames);
  std::cout << fmt::format("coverage  {}; {:.2f} s of {:.2f} s ground-truth span ({:.1f} %)\n",
                           frames, cov.covered_span_s, cov.gt_span_s, 100.0 * span_share);
  return kExitOk;
}

}  // namespace

void registerEval(CLI::App& root, Action& chosen) {
  auto opt = std::make_shared<EvalOptions>();
  auto* sub = root.add_subcommand(
      "eval", "Trajectory accuracy: ATE RMSE after SE(3) alignment and per-frame RPE, as the TUM "
              "benchmark's evaluate_ate.py / evaluate_rpe.py --fixed_delta --delta 1 --delta_unit f");
  sub->add_option("--gt", opt->gt_path, "ground-truth trajectory (TUM format)")->required();
  sub->add_option("--est", opt->est_path, "estimated trajectory (TUM format)")->required();
  sub->add_option("--sequence", opt->sequence_dir,
                  "sequence folder: report tracked/total frames and restrict the span to its frames");
  sub->add_option("--max-dt", opt->max_dt_s, "largest stamp gap for ATE association (s)")
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "print the results as JSON");
  sub->callback([opt, &chosen] { chosen = [opt] { return runEval(*opt); }; });
}

}  // namespace dynanav::cli
