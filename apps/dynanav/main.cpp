// dynanav command-line entry point: subcommands per DESIGN.md §2.
#include <fcntl.h>
#include <malloc.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <thread>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"

namespace {

/// A closed stdin, stdout or stderr would hand its number to the next file opened, and whatever
/// is printed would land inside that file (a trajectory, stats.json): keep them open on
/// /dev/null instead.
void keepStandardStreamsOpen() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (fcntl(fd, F_GETFD) != -1) continue;
    const int null_fd = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (null_fd >= 0 && null_fd != fd) {
      dup2(null_fd, fd);
      close(null_fd);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  keepStandardStreamsOpen();
  // Logs go to stderr (spdlog's default logger writes to stdout), so stdout carries only a
  // command's results (eval's figures, info's summary) and can be piped.
  spdlog::set_default_logger(spdlog::stderr_color_mt("dynanav"));
  // Keep freed frame-sized buffers in the heap: glibc otherwise maps and unmaps each multi-MB
  // image buffer, and the page faults of fresh pages cost up to ~15 ms per 2.4 MB buffer on the
  // dev machine (bench_perception, docs/perception.md). Every per-frame command benefits.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  // One arena per core instead of glibc's eight per core: a run's threads hand keyframes, map
  // points and frames to each other, and a chunk freed by one thread goes back to the arena it came
  // from, where only the threads on that arena reuse it. With an arena per thread the free memory
  // of every arena stays resident beside the others'; paced ten-pass Bonn runs grew 11-16 % in
  // resident memory after the first pass with glibc's default and 3-8 % with two arenas
  // (docs/robustness.md "Session 15"). More threads than cores cannot all allocate at once, so
  // sharing costs little.
  mallopt(M_ARENA_MAX, int(std::max(2u, std::thread::hardware_concurrency())));
  CLI::App app{
      "dynanav: dynamic RGB-D SLAM and navigation assistance for blind and visually "
      "impaired walkers"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "dynanav 0.1.0");
  dynanav::cli::Action chosen;
  dynanav::cli::registerRun(app, chosen);
  dynanav::cli::registerEval(app, chosen);
  dynanav::cli::registerEvalMasks(app, chosen);
  dynanav::cli::registerEvalObjects(app, chosen);
  dynanav::cli::registerEvalEvents(app, chosen);
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
  } catch (const std::filesystem::filesystem_error& e) {
    // A symlink loop, a path component that is a file, no permission: the user's input.
    spdlog::error("{}: {}", e.path1().string(), e.code().message());
    return dynanav::kExitBadInput;
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", e.what());
    return 1;
  }
}
