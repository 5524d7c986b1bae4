// dynanav command-line entry point: subcommands per DESIGN.md §2.
#include <spdlog/spdlog.h>

#include <iostream>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
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
