#pragma once
// Each subcommand registers itself on the root app and, when chosen, stores its action.
// The action returns the process exit code; InputError thrown from it becomes exit code 2.
#include <CLI/CLI.hpp>
#include <functional>

namespace dynanav::cli {

using Action = std::function<int()>;

void registerRun(CLI::App& root, Action& chosen);         // cmd_run.cpp
void registerEval(CLI::App& root, Action& chosen);        // cmd_eval.cpp
void registerSimulate(CLI::App& root, Action& chosen);    // cmd_simulate.cpp
void registerSegment(CLI::App& root, Action& chosen);     // cmd_segment.cpp
void registerVocabulary(CLI::App& root, Action& chosen);  // cmd_vocabulary.cpp
void registerRenderMap(CLI::App& root, Action& chosen);   // cmd_render_map.cpp
void registerVideoFrame(CLI::App& root, Action& chosen);  // cmd_video_frame.cpp

}  // namespace dynanav::cli
