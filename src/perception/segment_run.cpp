#include "perception/segment_run.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <opencv2/core/utility.hpp>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "perception/mask_files.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

void printProgress(size_t done, size_t total, double elapsed_s) {
  constexpr int kWidth = 30;
  const int filled = total ? int(kWidth * done / total) : kWidth;
  std::fprintf(stderr, "\r[%s%s] %zu/%zu  %.1f frames/s ", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), '.').c_str(), done, total,
               elapsed_s > 0 ? double(done) / elapsed_s : 0.0);
  if (done == total) std::fprintf(stderr, "\n");
}

nlohmann::json summaryJson(const StageTimers& timers) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [stage, s] : timers.summary()) {
    std::vector<double> samples = timers.samples(stage);
    std::sort(samples.begin(), samples.end());
    const double median = samples.empty() ? 0.0 : samples[samples.size() / 2];
    out[stage] = {{"mean", s.mean_ms}, {"median", median}, {"p95", s.p95_ms}, {"max", s.max_ms}};
  }
  return out;
}

}  // namespace

SegmentRunSummary runSegmentation(const SegmentRunOptions& options) {
  const TumSequence sequence = TumSequence::open(options.sequence_dir, options.io, PinholeCamera{});
  SegmenterRequest request = options.request;
  request.sequence_dir = options.sequence_dir;
  auto segmenter = makeSegmenter(request, options.perception);
  fs::create_directories(options.out_dir);
  if (fs::equivalent(options.out_dir, options.sequence_dir))
    throw InputError(options.out_dir.string(), "--out must differ from the sequence folder");

  SegmentRunSummary summary;
  summary.segmenter = segmenter->name();
  MaskFolderWriter masks(options.out_dir);
  StageTimers timers;
  nlohmann::json per_frame = nlohmann::json::array();
  const size_t total = options.max_frames < 0
                           ? sequence.size()
                           : std::min(sequence.size(), size_t(options.max_frames));
  const bool progress = options.progress && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < total; ++i) {
    RgbdFrame frame;
    try {
      frame = sequence.load(i);
    } catch (const InputError& e) {
      spdlog::warn("frame {} skipped: {}", i, e.what());
      ++summary.skipped;
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Instances raw = segmenter->segment(frame);
    const double ms = msSince(t0);
    timers.add("segment", ms);
    nlohmann::json steps = nlohmann::json::object();
    for (const auto& [step, step_ms] : segmenter->lastTiming()) {
      timers.add(step, step_ms);
      steps[step] = step_ms;
    }
    const std::string stem = fs::path(frame.rgb_path).stem().string();
    const Instances written = masks.write(stem, raw);
    const int persons = written.count("person");
    summary.frames_with_person += persons > 0;
    ++summary.frames;
    per_frame.push_back({{"index", frame.index},
                         {"stem", stem},
                         {"ms", ms},
                         {"persons", persons},
                         {"instances", written.items.size()},
                         {"steps", steps}});
    if (options.on_frame) options.on_frame(frame, written);
    if (progress) printProgress(i + 1, total, msSince(start) / 1000.0);
  }
  masks.finish();

  const nlohmann::json stats = {
      {"segmenter", summary.segmenter},  {"frames", summary.frames},
      {"skipped", summary.skipped},      {"frames_with_person", summary.frames_with_person},
      {"threads", cv::getNumThreads()},  {"wall_s", msSince(start) / 1000.0},
      {"stage_ms", summaryJson(timers)}, {"per_frame", per_frame}};
  writeJsonFile(options.out_dir / "stats.json", stats);
  return summary;
}

}  // namespace dynanav
