// dynanav eval-masks SIM_DIR SEG_DIR: person recall and mask IoU of a segment run on a simulated
// sequence, against the simulator's exact masks (src/eval/mask_scores.hpp).
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "eval/mask_scores.hpp"

namespace dynanav::cli {

void registerEvalMasks(CLI::App& root, Action& chosen) {
  auto* sub = root.add_subcommand(
      "eval-masks",
      "person recall and mask IoU of `dynanav segment` output on a simulated sequence");
  struct Args {
    std::string sim, seg;
    MaskScoreOptions options;
    bool json = false, per_frame = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("SIM_DIR", args->sim, "simulated sequence (masks/, masks.json, objects_gt.jsonl)")
      ->required();
  sub->add_option("SEG_DIR", args->seg, "dynanav segment --out folder (masks/, masks.json)")
      ->required();
  sub->add_option("--min-in-view", args->options.min_in_view,
                  "score a person when this share of its silhouette shows (objects_gt in_view)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  sub->add_option("--min-height-px", args->options.min_height_px,
                  "... and its visible mask is at least this tall")
      ->capture_default_str();
  sub->add_option("--match-iou", args->options.match_iou, "IoU at which a person counts as found")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  sub->add_flag("--json", args->json, "print the results as JSON");
  sub->add_flag("--per-frame", args->per_frame, "with --json: every scored (frame, person)");
  sub->callback([&chosen, args] {
    chosen = [args] {
      const MaskScoreSummary s = scorePersonMasks(args->sim, args->seg, args->options);
      if (args->json) {
        nlohmann::json out = {{"frames", s.frames},
                              {"scored", s.scored.size()},
                              {"found", s.found},
                              {"recall", s.recall()},
                              {"median_iou_found", s.median_iou_found},
                              {"median_iou_all", s.median_iou_all}};
        if (args->per_frame) {
          out["per_frame"] = nlohmann::json::array();
          for (const PersonMaskScore& p : s.scored)
            out["per_frame"].push_back({{"stem", p.stem},
                                        {"id", p.id},
                                        {"in_view", p.in_view},
                                        {"height_px", p.height_px},
                                        {"iou", p.iou}});
        }
        std::cout << out.dump(2) << std::endl;
        return kExitOk;
      }
      std::cout << fmt::format(
          "persons in view (>= {:.0f} % of the silhouette, >= {} px tall): {} (frame, person) "
          "pairs "
          "in {} frames; found (IoU >= {:.2f}) {} = {:.1f} %; median IoU {:.3f} of the found, "
          "{:.3f} "
          "of all\n",
          100.0 * args->options.min_in_view, args->options.min_height_px, s.scored.size(), s.frames,
          args->options.match_iou, s.found, 100.0 * s.recall(), s.median_iou_found,
          s.median_iou_all);
      return kExitOk;
    };
  });
}

}  // namespace dynanav::cli
