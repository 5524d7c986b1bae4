#pragma once
// Shared test helpers: locating ../shared, scratch folders, running the CLI.
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace dynanav::test {

/// ../shared (or $DYNANAV_SHARED); empty path if it does not exist.
std::filesystem::path sharedDir();
/// A sequence folder under ../shared/data, or empty if absent.
std::filesystem::path sharedSequence(const std::string& name);
/// ../shared/models (or $DYNANAV_MODELS), or empty if absent.
std::filesystem::path sharedModels();
/// A fresh empty folder under the system temp dir, unique per test.
std::filesystem::path scratchDir(const std::string& tag);
/// Removes a per-process scratch folder (a suite's, named with its pid: a fixed-name folder is
/// reused by the next run, a pid-named one would pile up in the temp dir, ~0.2 GB per run)
/// unless $DYNANAV_KEEP_TEST_OUTPUT is set (to look at a failed run's files).
void removeScratchDir(const std::filesystem::path& dir);
/// Runs `<build>/bin/dynanav ARGS`, capturing stdout+stderr into `output`; returns the exit code.
int runCli(const std::string& args, std::string* output = nullptr);
/// Starts `<build>/bin/dynanav ARGS`, sends `signal_number` after `delay` (none if it has ended
/// by then) and waits: the exit code, -1 when it could not start, -1000 - N when signal N ended
/// it.
int runAndSignal(const std::vector<std::string>& args, int signal_number,
                 std::chrono::milliseconds delay);
/// As above, but the signal goes once `ready()` holds (polled every 50 ms; a loaded machine
/// starts the CLI late, so a fixed delay can come before it has written anything), or at
/// `timeout`; no signal when the process has already ended.
int runAndSignalWhen(const std::vector<std::string>& args, int signal_number,
                     const std::function<bool()>& ready, std::chrono::milliseconds timeout);
/// ATE RMSE (m) of `est` against `gt` as the project's own `dynanav eval --json` computes it;
/// a failed evaluation is reported as a test failure and returns 1e9.
double ateRmse(const std::filesystem::path& gt, const std::filesystem::path& est);
/// The message of the InputError `f` throws ("" when it throws none).
std::string errorOf(const std::function<void()>& f);
/// Whole file as a string ("" if missing).
std::string readFile(const std::filesystem::path& path);

}  // namespace dynanav::test

/// Skip the current test with a message when a shared sequence is absent.
#define DYNANAV_REQUIRE_SEQUENCE(var, name)               \
  const auto var = ::dynanav::test::sharedSequence(name); \
  if (var.empty()) GTEST_SKIP() << "../shared/data/" << name << " not found: skipped"
