// dynanav eval-events: a run's messages (events.jsonl) against the simulator's ground truth
// (objects_gt.jsonl and groundtruth.txt): per person the time of its closest approach and the
// lead time of the first urgent warning before it; counts per priority; the most non-urgent
// messages in any --window seconds; messages repeated unchanged (issue 14).
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "eval/event_metrics.hpp"
#include "io/events_jsonl.hpp"

namespace dynanav::cli {
namespace {

struct EvalEventsOptions {
  std::string gt_path;
  std::string events_path;
  std::string poses_path;  // default: groundtruth.txt beside --gt
  EventMetricsOptions metrics;
  bool json = false;
};

nlohmann::json orNull(double v) {
  return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v);
}

std::string seconds(double v) {
  return v < 0.0 ? std::string("none") : fmt::format("{:.2f} s", v);
}

int runEvalEvents(const EvalEventsOptions& opt) {
  const auto gt = readObjectsJsonl(opt.gt_path);
  if (gt.empty()) throw InputError(opt.gt_path, "no frames");
  const std::filesystem::path poses_path =
      opt.poses_path.empty() ? std::filesystem::path(opt.gt_path).parent_path() / "groundtruth.txt"
                             : std::filesystem::path(opt.poses_path);
  if (!std::filesystem::is_regular_file(poses_path))
    throw InputError(poses_path.string(),
                     "ground-truth camera poses not found (give --poses GROUNDTRUTH.txt)");
  const auto poses = readTrajectory(poses_path);
  const auto events = readEventsJsonl(opt.events_path);
  const EventMetrics m = scoreEvents(gt, poses, events, opt.metrics);
  if (opt.json) {
    nlohmann::json people = nlohmann::json::array();
    for (const PersonEncounter& p : m.people)
      people.push_back({{"id", p.gt_id},
                        {"t_closest", p.t_closest_s},
                        {"closest_m", p.closest_m},
                        {"in_corridor", p.in_corridor},
                        {"urgent", p.urgent},
                        {"advisory", p.advisory},
                        {"info", p.info},
                        {"first_urgent", orNull(p.first_urgent_s)},
                        {"lead_s", orNull(p.lead_s)},
                        {"lead_audio_s", orNull(p.lead_audio_s)},
                        {"first_advisory", orNull(p.first_advisory_s)}});
    std::cout << nlohmann::json{{"events", m.events},
                                {"urgent", m.urgent},
                                {"advisory", m.advisory},
                                {"info", m.info},
                                {"window_s", opt.metrics.window_s},
                                {"max_non_urgent_in_window", m.max_non_urgent_in_window},
                                {"unchanged_repeats", m.unchanged_repeats},
                                {"unmatched", m.unmatched},
                                {"people", people}}
                     .dump(2)
              << std::endl;
    return kExitOk;
  }
  std::cout << fmt::format(
      "events   {} messages: {} urgent, {} advisory, {} info; at most {} non-urgent in any {:g} s; "
      "{} repeated unchanged; {} not about a person\n",
      m.events, m.urgent, m.advisory, m.info, m.max_non_urgent_in_window, opt.metrics.window_s,
      m.unchanged_repeats, m.unmatched);
  for (const PersonEncounter& p : m.people)
    std::cout << fmt::format(
        "person {}: closest {:.2f} m at {:.2f} s ({} the {:g} m corridor); messages {} urgent, {} "
        "advisory, {} info; first urgent {} (lead {}, from audio start {}); first advisory {}\n",
        p.gt_id, p.closest_m, p.t_closest_s, p.in_corridor ? "inside" : "outside",
        opt.metrics.corridor_m, p.urgent, p.advisory, p.info, seconds(p.first_urgent_s),
        seconds(p.lead_s), seconds(p.lead_audio_s), seconds(p.first_advisory_s));
  return kExitOk;
}

}  // namespace

void registerEvalEvents(CLI::App& root, Action& chosen) {
  auto opt = std::make_shared<EvalEventsOptions>();
  auto* sub = root.add_subcommand(
      "eval-events",
      "Messages against ground truth: lead time of the first urgent warning before each "
      "person's closest approach, counts per priority, rate, unchanged repeats");
  sub->add_option("--gt", opt->gt_path, "a simulated sequence's objects_gt.jsonl")->required();
  sub->add_option("--events", opt->events_path, "a run's events.jsonl")->required();
  sub->add_option("--poses", opt->poses_path,
                  "ground-truth camera poses (default: groundtruth.txt beside --gt)");
  sub->add_option("--window", opt->metrics.window_s, "rate window (s)")
      ->capture_default_str()
      ->check(finiteRange(0.001, 3600));
  sub->add_option("--corridor", opt->metrics.corridor_m,
                  "closest approaches within this (m) count as inside the corridor")
      ->capture_default_str()
      ->check(finiteRange(0, 100));
  sub->add_option("--match", opt->metrics.match_m,
                  "largest message-to-person distance (m) for a match")
      ->capture_default_str()
      ->check(finiteRange(0, 100));
  sub->add_flag("--json", opt->json, "print the results as JSON");
  sub->callback([opt, &chosen] { chosen = [opt] { return runEvalEvents(*opt); }; });
}

}  // namespace dynanav::cli
