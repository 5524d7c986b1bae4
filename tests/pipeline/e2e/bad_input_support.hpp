#pragma once
// Helpers of the bad-input matrix (test_bad_input_matrix.cpp, test_bad_frames.cpp): the CLI run
// under a time limit, and a small simulated sequence to damage.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace dynanav::test {

struct CliResult {
  int code = -1;  ///< exit status; -1 = killed by a signal (a crash)
  std::string output;
};

/// Runs `dynanav ARGS` (stdout and stderr together) under `timeout`: a hang shows as 124.
/// `redirect` replaces the default "2>&1" (e.g. ">&- 2>&1" to close stdout).
inline CliResult runCliTimed(const std::string& args, int timeout_s = 240,
                             const std::string& redirect = "2>&1") {
  const std::string cmd =
      "timeout -k 5 " + std::to_string(timeout_s) + " \"" DYNANAV_CLI "\" " + args + " " + redirect;
  CliResult result;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), int(buffer.size()), pipe)) result.output += buffer.data();
  const int status = pclose(pipe);
  result.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

/// A simulated static-room sequence of `frames` frames, made once per process per name.
inline std::filesystem::path simulatedSequence(const std::string& name, int frames) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("dynanav_test_badinput_" + name);
  if (std::filesystem::exists(dir / "groundtruth.txt")) return dir;
  std::filesystem::remove_all(dir);
  const CliResult sim = runCliTimed("simulate --scenario static-room --frames " +
                                    std::to_string(frames) + " --out " + dir.string());
  EXPECT_EQ(sim.code, 0) << sim.output;
  return dir;
}

}  // namespace dynanav::test

/// Exit 2 and a message naming `token` (a file, key or option); never a crash, hang or exit 1.
#define EXPECT_BAD_INPUT(result, token)                 \
  do {                                                  \
    const auto& r_ = (result);                          \
    EXPECT_EQ(r_.code, 2) << r_.output;                 \
    EXPECT_NE(r_.output.find(token), std::string::npos) \
        << "message should name " << (token) << ":\n"   \
        << r_.output;                                   \
  } while (0)
