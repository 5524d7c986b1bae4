#pragma once
// Shared by the libFuzzer targets: most parsers read files, so each input is written to a
// scratch file (one per process, in $TMPDIR) and the parser is called on its path. InputError
// is the parser saying "bad input" (the CLI's exit 2) and is expected; any other exception, a
// crash or a sanitizer report is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace dynanav::fuzz {

/// Writes the input to <tmp>/dynanav_fuzz_<pid>/<name> and returns that path.
inline std::filesystem::path writeInput(const uint8_t* data, size_t size, const std::string& name) {
  static const std::filesystem::path dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    auto d = std::filesystem::path(tmp && *tmp ? tmp : "/tmp") /
             ("dynanav_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace dynanav::fuzz
