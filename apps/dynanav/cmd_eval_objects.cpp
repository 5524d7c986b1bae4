// dynanav eval-objects: tracked objects (objects.jsonl) against the simulator's ground truth
// (objects_gt.jsonl): speed and position RMSE, id switches, recall, false tracks. Without --gt
// (real sequences): per track, the share of its moving frames whose speed lies in --speed-band.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "eval/object_metrics.hpp"

namespace dynanav::cli {
namespace {

struct EvalObjectsOptions {
  std::string gt_path;
  std::string est_path;
  ObjectMetricsOptions metrics;
  std::string speed_band = "0.2:2.5";
  bool json = false;
};

int speedBands(const EvalObjectsOptions& opt, const std::vector<ObjectsFrame>& est) {
  double lo = 0, hi = 0;
  if (std::sscanf(opt.speed_band.c_str(), "%lf:%lf", &lo, &hi) != 2 || !(lo < hi))
    throw InputError("--speed-band", "expected MIN:MAX in m/s, got '" + opt.speed_band + "'");
  const auto shares = trackSpeedShares(est, lo, hi);
  if (opt.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& s : shares)
      out.push_back({{"id", s.id},
                     {"class", s.class_name},
                     {"frames", s.frames},
                     {"dynamic_frames", s.dynamic_frames},
                     {"in_band", s.in_band},
                     {"share", s.share()},
                     {"median_speed_mps", s.median_speed_mps}});
    std::cout << nlohmann::json{{"speed_band", {lo, hi}}, {"tracks", out}}.dump(2) << std::endl;
    return kExitOk;
  }
  for (const auto& s : shares)
    std::cout << fmt::format(
        "track {:4d} {:8s} frames {:4d}  moving {:4d}  speed in [{}, {}] m/s: "
        "{:5.1f} %  median {:.2f} m/s\n",
        s.id, s.class_name, s.frames, s.dynamic_frames, lo, hi, 100.0 * s.share(),
        s.median_speed_mps);
  return kExitOk;
}

int runEvalObjects(const EvalObjectsOptions& opt) {
  const auto est = readObjectsJsonl(opt.est_path);
  if (opt.gt_path.empty()) return speedBands(opt, est);
  const auto gt = readObjectsJsonl(opt.gt_path);
  if (gt.empty()) throw InputError(opt.gt_path, "no frames");
  const ObjectMetrics m = scoreObjects(gt, est, opt.metrics);
  if (opt.json) {
    nlohmann::json objects = nlohmann::json::array();
    for (const ObjectScore& s : m.objects)
      objects.push_back({{"id", s.gt_id},
                         {"class", s.class_name},
                         {"scored_frames", s.scored_frames},
                         {"matched", s.matched},
                         {"recall", s.recall()},
                         {"id_switches", s.id_switches},
                         {"id_switches_per_100", s.switchesPer100()},
                         {"position_rmse_m", s.position_rmse_m},
                         {"speed_rmse_mps", s.speed_rmse_mps},
                         {"velocity_rmse_mps", s.velocity_rmse_mps},
                         {"moving_frames", s.moving_frames},
                         {"speed_rmse_moving_mps", s.speed_rmse_moving_mps},
                         {"speed_known_frames", s.speed_known_frames},
                         {"speed_rmse_known_mps", s.speed_rmse_known_mps},
                         {"stopped_frames", s.stopped_frames},
                         {"speed_mean_stopped_mps", s.speed_mean_stopped_mps},
                         {"speed_max_stopped_mps", s.speed_max_stopped_mps},
                         {"speed_rmse_stopped_mps", s.speed_rmse_stopped_mps}});
    std::cout << nlohmann::json{{"frames", m.frames},
                                {"scored", m.scored},
                                {"matched", m.matched},
                                {"recall", m.recall()},
                                {"id_switches", m.id_switches},
                                {"position_rmse_m", m.position_rmse_m},
                                {"speed_rmse_mps", m.speed_rmse_mps},
                                {"velocity_rmse_mps", m.velocity_rmse_mps},
                                {"speed_known_frames", m.speed_known_frames},
                                {"speed_rmse_known_mps", m.speed_rmse_known_mps},
                                {"false_tracks", m.false_tracks},
                                {"false_track_ids", m.false_track_ids},
                                {"objects", objects}}
                     .dump(2)
              << std::endl;
    return kExitOk;
  }
  std::cout << fmt::format(
      "objects  {} frames paired; {} of {} visible object-frames matched (recall {:.3f}); "
      "{} id switches; {} false track-frames ({} track ids)\n",
      m.frames, m.matched, m.scored, m.recall(), m.id_switches, m.false_tracks, m.false_track_ids);
  std::cout << fmt::format("rmse     position {:.4f} m  speed {:.4f} m/s  velocity {:.4f} m/s\n",
                           m.position_rmse_m, m.speed_rmse_mps, m.velocity_rmse_mps);
  std::cout << fmt::format(
      "known    speed {:.4f} m/s over the {} of {} matched frames whose velocity "
      "is known (velocity_known)\n",
      m.speed_rmse_known_mps, m.speed_known_frames, m.matched);
  for (const ObjectScore& s : m.objects)
    std::cout << fmt::format(
        "object {} {}: {}/{} frames (recall {:.3f}), {} id switches ({:.2f} per 100 "
        "frames), position {:.4f} m, speed {:.4f} m/s (known {} frames: {:.4f}; moving {} "
        "frames: {:.4f}; stopped {} frames: mean {:.4f} max {:.4f} rmse {:.4f} m/s)\n",
        s.class_name, s.gt_id, s.matched, s.scored_frames, s.recall(), s.id_switches,
        s.switchesPer100(), s.position_rmse_m, s.speed_rmse_mps, s.speed_known_frames,
        s.speed_rmse_known_mps, s.moving_frames, s.speed_rmse_moving_mps, s.stopped_frames,
        s.speed_mean_stopped_mps, s.speed_max_stopped_mps, s.speed_rmse_stopped_mps);
  return kExitOk;
}

}  // namespace

void registerEvalObjects(CLI::App& root, Action& chosen) {
  auto opt = std::make_shared<EvalObjectsOptions>();
  auto* sub = root.add_subcommand(
      "eval-objects",
      "Tracked objects against ground truth: speed and position RMSE, id switches, "
      "recall, false tracks (objects seen at least --min-visible share are scored)");
  sub->add_option(
      "--gt", opt->gt_path,
      "ground truth (a simulated sequence's objects_gt.jsonl); without it: speed bands per track");
  sub->add_option("--est", opt->est_path, "a run's objects.jsonl")->required();
  sub->add_option("--max-match", opt->metrics.max_match_m, "largest track-to-truth distance (m)")
      ->capture_default_str();
  sub->add_option("--min-visible", opt->metrics.min_visible_share,
                  "objects less in view than this share (objects_gt in_view) are not scored")
      ->capture_default_str();
  sub->add_option("--speed-band", opt->speed_band, "without --gt: MIN:MAX speed band (m/s)")
      ->capture_default_str();
  sub->add_flag("--json", opt->json, "print the results as JSON");
  sub->callback([opt, &chosen] { chosen = [opt] { return runEvalObjects(*opt); }; });
}

}  // namespace dynanav::cli
