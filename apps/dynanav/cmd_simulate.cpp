// Placeholder registration, replaced by the module's owner as the feature lands.
#include <spdlog/spdlog.h>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"

namespace dynanav::cli {

void registerSimulate(CLI::App& root, Action& chosen) {
  auto* sub = root.add_subcommand("simulate", "(not built yet)");
  sub->allow_extras();
  sub->callback([&chosen] {
    chosen = [] {
      spdlog::error("'simulate' is not built yet");
      return kExitBadInput;
    };
  });
}

}  // namespace dynanav::cli
