// dynanav command-line entry point: subcommands per DESIGN.md §2.
#include <malloc.h>
#include <spdlog/spdlog.h>

#include <iostream>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  // Keep freed frame-sized buffers in the heap: glibc otherwise maps and unmaps each multi-MB
  // image buffer, and the page faults of fresh pages cost up to ~15 ms per 2.4 MB buffer on the
  // dev machine (bench_perception, docs/perception.md). Every per-frame command benefits.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  CLI::App app{"dynanav: dynamic RGB-D SLAM and navigation assistance for blind and visually "
               "impaired walkers"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "dynanav 0.1.0");
  dynanav::cli::Action chosen;
  dynanav::cli::registerRun(app, chosen);
  dynanav::cli::registerEval(app, chosen);
  dynanav::cli::registerSimulate(app, chosen);
  dynanav::cli::registerSegment(app, chosen);
  dynanav::cli::registerVocabulary(app, chosen);
  dynanav::cli::registerRenderMap(app, chosen);
  dynanav::cli::registerVideoFrame(app, chosen);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : dynanav::kExitBadInput;
  }
  try {
    return chosen ? chosen() : dynanav::kExitBadInput;
  } catch (const dynanav::InputError& e) {
    spdlog::error("{}", e.what());
    return dynanav::kExitBadInput;
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", e.what());
    return 1;
  }
}
