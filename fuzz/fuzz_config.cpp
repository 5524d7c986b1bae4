// The --config YAML (Config::parse): a config that loads must pass its own validation and
// echo back to the same config.
#include <cstdlib>
#include <string>

#include "core/config.hpp"
#include "core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const dynanav::Config config = dynanav::Config::parse(text, "fuzz.yaml");
    config.validate("fuzz.yaml");
    const std::string echo = config.toYaml();
    if (dynanav::Config::parse(echo, "echo").toYaml() != echo) std::abort();
  } catch (const dynanav::ConfigError&) {
  }
  return 0;
}
