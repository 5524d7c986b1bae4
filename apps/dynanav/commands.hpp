#pragma once
// Each subcommand registers itself on the root app and, when chosen, stores its action.
// The action returns the process exit code; InputError thrown from it becomes exit code 2.
#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <string>

namespace dynanav::cli {

using Action = std::function<int()>;

/// A number in [lo, hi]; unlike CLI::Range it also refuses NaN and infinity. CLI11 names the
/// option in its message (exit 2).
inline CLI::Validator finiteRange(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < lo ||
            value > hi)
          return "value " + text + " not a number in [" + CLI::detail::to_string(lo) + ", " +
                 CLI::detail::to_string(hi) + "]";
        return {};
      },
      "NUMBER in [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]");
}

void registerRun(CLI::App& root, Action& chosen);          // cmd_run.cpp
void registerEval(CLI::App& root, Action& chosen);         // cmd_eval.cpp
void registerEvalMasks(CLI::App& root, Action& chosen);    // cmd_eval_masks.cpp
void registerEvalObjects(CLI::App& root, Action& chosen);  // cmd_eval_objects.cpp
void registerEvalEvents(CLI::App& root, Action& chosen);   // cmd_eval_events.cpp
void registerSimulate(CLI::App& root, Action& chosen);     // cmd_simulate.cpp
void registerSegment(CLI::App& root, Action& chosen);      // cmd_segment.cpp
void registerVocabulary(CLI::App& root, Action& chosen);   // cmd_vocabulary.cpp
void registerRenderMap(CLI::App& root, Action& chosen);    // cmd_render_map.cpp
void registerVideoFrame(CLI::App& root, Action& chosen);   // cmd_video_frame.cpp

}  // namespace dynanav::cli
