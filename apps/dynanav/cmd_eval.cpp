// dynanav eval: trajectory accuracy (ATE, RPE) and coverage with the TUM benchmark conventions.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "eval/moving_flags.hpp"
#include "eval/trajectory_metrics.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"

namespace dynanav::cli {
namespace {

struct EvalOptions {
  std::string gt_path;
  std::string est_path;
  std::string sequence_dir;
  double max_dt_s = 0.02;
  std::string stats_path;     // a run's stats.json: score its moving flags (simulated sequences)
  int min_visible_px = 3072;  // 1 % of a 640x480 image
  bool json = false;
  std::string errors_path;  // CSV of each matched pose's aligned ATE error (issue 18's plot)
};

nlohmann::json toJson(const ErrorStats& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median}, {"std", s.std},
          {"min", s.min},   {"max", s.max},   {"count", s.count}};
}

/// Moving-flag precision/recall per simulated object, or empty without --stats.
std::vector<MovingFlagScore> scoreFlags(const EvalOptions& opt) {
  if (opt.stats_path.empty()) return {};
  if (opt.sequence_dir.empty())
    throw InputError("--stats", "needs --sequence SIM_DIR (its objects_gt.jsonl)");
  const auto truth = readObjectTruth(std::filesystem::path(opt.sequence_dir) / "objects_gt.jsonl");
  const auto flagged = readMovingFlags(opt.stats_path);
  if (truth.size() != flagged.size())
    throw InputError(opt.stats_path,
                     fmt::format("{} frames of moving flags but {} ground-truth frames in {} "
                                 "(score a run over the whole sequence)",
                                 flagged.size(), truth.size(), opt.sequence_dir));
  return scoreMovingFlags(truth, flagged, opt.min_visible_px);
}

nlohmann::json toJson(const std::vector<MovingFlagScore>& scores) {
  nlohmann::json out = nlohmann::json::array();
  auto number = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  for (const MovingFlagScore& s : scores)
    out.push_back({{"id", s.id},
                   {"class", s.class_name},
                   {"precision", number(s.precision())},
                   {"recall", number(s.recall())},
                   {"true_positive", s.true_positive},
                   {"false_positive", s.false_positive},
                   {"false_negative", s.false_negative},
                   {"true_negative", s.true_negative},
                   {"out_of_view", s.out_of_view}});
  return out;
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
  const std::vector<MovingFlagScore> flags = scoreFlags(opt);
  AteResult ate;
  RpeResult rpe;
  try {
    ate = computeAte(gt, est, opt.max_dt_s);
    rpe = computeRpe(gt, est);
  } catch (const InputError& e) {
    throw InputError("--gt " + opt.gt_path + " --est " + opt.est_path, e.what());
  }
  if (!opt.errors_path.empty()) {
    std::string csv = "stamp_s,ate_error_m\n";
    for (const auto& [stamp_s, error_m] : ate.error_by_stamp_m)
      csv += fmt::format("{:.6f},{:.6f}\n", stamp_s, error_m);
    writeTextFile(opt.errors_path, csv);
  }
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
    nlohmann::json out = {{"ate_m", toJson(ate.translation_m)},
                          {"rpe_translation_m", toJson(rpe.translation_m)},
                          {"rpe_rotation_deg", toJson(rpe.rotation_deg)},
                          {"matched_poses", ate.matched},
                          {"estimated_poses", ate.estimated},
                          {"rpe_pairs", rpe.pairs},
                          {"coverage",
                           {{"tracked_frames", cov.tracked_frames},
                            {"total_frames", cov.total_frames},
                            {"covered_span_s", cov.covered_span_s},
                            {"gt_span_s", cov.gt_span_s},
                            {"span_share", span_share}}}};
    if (!opt.stats_path.empty()) out["moving_flags"] = toJson(flags);
    std::cout << out.dump(2) << std::endl;
    return kExitOk;
  }
  const auto& a = ate.translation_m;
  std::cout << fmt::format(
      "ATE  rmse {:.6f} m  mean {:.6f}  median {:.6f}  std {:.6f}  max {:.6f}  "
      "({} of {} estimated poses matched)\n",
      a.rmse, a.mean, a.median, a.std, a.max, ate.matched, ate.estimated);
  std::cout << fmt::format(
      "RPE  translation rmse {:.6f} m/frame  rotation rmse {:.6f} deg/frame  "
      "({} pairs)\n",
      rpe.translation_m.rmse, rpe.rotation_deg.rmse, rpe.pairs);
  const std::string frames =
      cov.total_frames
          ? fmt::format("{}/{} frames tracked", cov.tracked_frames, cov.total_frames)
          : fmt::format("{} poses (pass --sequence for frame coverage)", cov.tracked_frames);
  std::cout << fmt::format("coverage  {}; {:.2f} s of {:.2f} s ground-truth span ({:.1f} %)\n",
                           frames, cov.covered_span_s, cov.gt_span_s, 100.0 * span_share);
  for (const MovingFlagScore& f : flags)
    std::cout << fmt::format(
        "moving flag  {} {}: precision {:.3f}  recall {:.3f}  (tp {} fp {} fn {} tn {}; "
        "{} frames out of view)\n",
        f.class_name, f.id, f.precision(), f.recall(), f.true_positive, f.false_positive,
        f.false_negative, f.true_negative, f.out_of_view);
  return kExitOk;
}

}  // namespace

void registerEval(CLI::App& root, Action& chosen) {
  auto opt = std::make_shared<EvalOptions>();
  auto* sub = root.add_subcommand(
      "eval",
      "Trajectory accuracy: ATE RMSE after SE(3) alignment and per-frame RPE, as the TUM "
      "benchmark's evaluate_ate.py / evaluate_rpe.py --fixed_delta --delta 1 --delta_unit f");
  sub->add_option("--gt", opt->gt_path, "ground-truth trajectory (TUM format)")->required();
  sub->add_option("--est", opt->est_path, "estimated trajectory (TUM format)")->required();
  sub->add_option(
      "--sequence", opt->sequence_dir,
      "sequence folder: report tracked/total frames and restrict the span to its frames");
  sub->add_option("--max-dt", opt->max_dt_s, "largest stamp gap for ATE association (s)")
      ->check(finiteRange(1e-6, 1.0))
      ->capture_default_str();
  sub->add_option("--stats", opt->stats_path,
                  "a run's stats.json: score each simulated object's per-frame moving flag against "
                  "--sequence's objects_gt.jsonl (precision, recall)");
  sub->add_option("--min-visible-px", opt->min_visible_px,
                  "with --stats: frames where an object shows fewer pixels are not scored")
      ->check(finiteRange(0, 1e8))
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "print the results as JSON");
  sub->add_option("--errors", opt->errors_path,
                  "write each matched pose's aligned ATE error to this CSV (stamp_s,ate_error_m; "
                  "scripts/plot_errors.py draws it)");
  sub->callback([opt, &chosen] { chosen = [opt] { return runEval(*opt); }; });
}

}  // namespace dynanav::cli
