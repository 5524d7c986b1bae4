// Perception timings per frame on the Bonn crowd window (../shared/data/rgbd_bonn_crowd, 500
// frames, skipped when absent) with the shared models (skipped when absent). Issue 6 targets:
// detector ≤ 15 ms, detector + masks + keypoints for 2 people ≤ 40 ms, propagation ≤ 6 ms.
//
// Each benchmark runs once over the frames (image decoding excluded) and reports, as counters,
// the median / p90 per frame and the median of every step, so the question "where does the
// time go" has an answer: pre-processing (resize + blob), forward, post-processing (decode +
// NMS), per-box crop / forward / decode, flow / warp / depth; the frame preparation (grey images
// and the tracker's dense flow). Arguments: OpenCV threads
// (cv::setNumThreads) and, for the detector, the input side.
//   build/<dir>/bin/bench_perception [--benchmark_filter=Detector]
// DYNANAV_BENCH_FRAMES=N limits the frames (default: all 500).
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <opencv2/core/utility.hpp>
#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "core/timer.hpp"
#include "io/sequence.hpp"
#include "perception/frame_prep.hpp"
#include "perception/model_files.hpp"
#include "perception/propagation.hpp"
#include "perception/segmenters.hpp"

namespace fs = std::filesystem;
using namespace dynanav;

namespace {

using Clock = std::chrono::steady_clock;

/// CPU time of the whole process (all threads), ms. On a machine shared with other jobs the
/// wall time per frame inflates with the load; the CPU time per frame does much less, so both
/// are reported (frame_med = wall, frame_cpu_med = CPU).
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

/// As `dynanav segment` does: keep freed frame-sized buffers in the heap (fresh pages cost
/// page faults; see docs/perception.md). DYNANAV_BENCH_DEFAULT_MALLOC=1 keeps glibc's defaults.
const bool kAllocatorTuned = [] {
  if (const char* env = std::getenv("DYNANAV_BENCH_DEFAULT_MALLOC"); env && std::string(env) == "1")
    return false;
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  return true;
}();

fs::path bonnDir() {
  return fs::path(DYNANAV_SHARED_DIR) / "data" / "rgbd_bonn_crowd";
}

fs::path modelsDir() {
  return findModelsDir("", dnnModelFiles(true));
}

size_t frameLimit(size_t available) {
  const char* env = std::getenv("DYNANAV_BENCH_FRAMES");
  return env ? std::min(available, size_t(std::max(1, std::atoi(env)))) : available;
}

/// Per-step samples → median / p90 counters.
class Samples {
 public:
  void add(const std::string& step, double ms) { samples_[step].push_back(ms); }
  void report(benchmark::State& state) {
    for (auto& [step, v] : samples_) {
      std::sort(v.begin(), v.end());
      state.counters[step + "_med"] = v[v.size() / 2];
      if (step == "frame")
        state.counters["frame_p90"] = v[std::min(v.size() - 1, v.size() * 9 / 10)];
    }
    if (samples_.count("frame")) state.counters["frames"] = double(samples_["frame"].size());
    state.counters["malloc_tuned"] = kAllocatorTuned ? 1 : 0;
  }

 private:
  std::map<std::string, std::vector<double>> samples_;
};

/// Calls body(frame) for each frame with decoding outside the timed region; reports counters.
template <class Body>
bool forEachFrame(benchmark::State& state, Body&& body) {
  if (!fs::is_directory(bonnDir())) {
    state.SkipWithError("../shared/data/rgbd_bonn_crowd not found: skipped");
    return false;
  }
  const TumSequence sequence = TumSequence::open(bonnDir(), IoConfig{});
  const size_t n = frameLimit(sequence.size());
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) {
      state.PauseTiming();
      const RgbdFrame frame = sequence.load(i);
      state.ResumeTiming();
      body(frame);
    }
  }
  return true;
}

void BM_Detector(benchmark::State& state) {
  const fs::path models = modelsDir();
  if (models.empty()) return state.SkipWithError("models not found: skipped");
  cv::setNumThreads(int(state.range(0)));
  PerceptionConfig config;
  config.detector_input_px = int(state.range(1));
  YoloDetector detector(models, config);
  (void)detector.detect(cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(100)));  // warm-up allocations
  Samples s;
  forEachFrame(state, [&](const RgbdFrame& f) {
    const auto t0 = Clock::now();
    const double c0 = processCpuMs();
    const auto detections = detector.detect(f.bgr);
    s.add("frame", msSince(t0));
    s.add("frame_cpu", processCpuMs() - c0);
    s.add("pre", detector.lastTiming().preprocess_ms);
    s.add("forward", detector.lastTiming().forward_ms);
    s.add("post", detector.lastTiming().postprocess_ms);
    benchmark::DoNotOptimize(detections);
  });
  s.report(state);
}
BENCHMARK(BM_Detector)
    ->ArgsProduct({{1, 2}, {320, 288, 256}})
    ->ArgNames({"threads", "input"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

/// detector + selfie masks + depth refinement + MoveNet; medians over all frames and over the
/// frames with exactly two people, plus per-person costs.
void BM_DnnSegmenter(benchmark::State& state) {
  const fs::path models = modelsDir();
  if (models.empty()) return state.SkipWithError("models not found: skipped");
  cv::setNumThreads(int(state.range(0)));
  PerceptionConfig config;
  config.keypoints = state.range(1) != 0;
  config.parallel_person_models = state.range(2) != 0;
  config.detector_input_px = int(state.range(3));
  DnnSegmenter segmenter(models, config);
  Samples s;
  bool first = true;
  forEachFrame(state, [&](const RgbdFrame& f) {
    if (first) {  // warm-up: the first forward of each net allocates its buffers
      (void)segmenter.segment(f);
      first = false;
    }
    const auto t0 = Clock::now();
    const double c0 = processCpuMs();
    const Instances out = segmenter.segment(f);
    const double ms = msSince(t0), cpu_ms = processCpuMs() - c0;
    const int persons = out.count("person");
    s.add("frame", ms);
    s.add("frame_cpu", cpu_ms);
    if (persons == 2) s.add("frame_2people", ms), s.add("frame_2people_cpu", cpu_ms);
    const auto timing = segmenter.lastTiming();
    for (const auto& [step, step_ms] : timing) s.add(step, step_ms);
    if (persons > 0) {
      s.add("mask_per_person", timing.at("masks") / persons);
      if (config.keypoints) s.add("kpt_per_person", timing.at("keypoints") / persons);
    }
  });
  s.report(state);
}
BENCHMARK(BM_DnnSegmenter)
    ->Args({2, 1, 1, 320})
    ->Args({2, 1, 1, 288})
    ->Args({2, 1, 1, 256})
    ->Args({2, 1, 0, 320})
    ->Args({1, 1, 0, 320})
    ->Args({2, 0, 1, 320})
    ->ArgNames({"threads", "keypoints", "parallel", "input"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

/// The per-box networks alone on the first person box of each frame: crop, forward, decode.
void BM_BoxModels(benchmark::State& state) {
  const fs::path models = modelsDir();
  if (models.empty()) return state.SkipWithError("models not found: skipped");
  cv::setNumThreads(int(state.range(0)));
  PerceptionConfig config;
  YoloDetector detector(models, config);
  SelfieSegmenter selfie(models, config);
  KeypointDetector keypoints(models, config);
  Samples s;
  forEachFrame(state, [&](const RgbdFrame& f) {
    state.PauseTiming();
    const auto detections = detector.detect(f.bgr);
    state.ResumeTiming();
    for (const Detection& d : detections) {
      if (d.class_id != 0 || d.score < config.person_min_score) continue;
      (void)selfie.maskInBox(f.bgr, d.box);
      s.add("selfie_crop", selfie.lastTiming().crop_ms);
      s.add("selfie_forward", selfie.lastTiming().forward_ms);
      s.add("selfie_decode", selfie.lastTiming().decode_ms);
      (void)keypoints.detect(f.bgr, d.box);
      s.add("movenet_crop", keypoints.lastTiming().crop_ms);
      s.add("movenet_forward", keypoints.lastTiming().forward_ms);
      s.add("movenet_decode", keypoints.lastTiming().decode_ms);
      break;
    }
  });
  s.report(state);
}
BENCHMARK(BM_BoxModels)
    ->Arg(2)
    ->Arg(1)
    ->ArgName("threads")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

/// Propagation of the previous frame's dnn labels to the next frame (labels from the segmenter
/// computed outside the timed region), at flow scale 1/2 (default) and 1/4.
void BM_Propagation(benchmark::State& state) {
  const fs::path models = modelsDir();
  if (models.empty()) return state.SkipWithError("models not found: skipped");
  cv::setNumThreads(int(state.range(0)));
  PerceptionConfig config;
  config.flow_scale = 1.0 / double(state.range(1));
  config.keypoints = false;
  DnnSegmenter segmenter(models, config);
  MaskPropagator propagator(config);
  Samples s;
  forEachFrame(state, [&](const RgbdFrame& f) {
    if (propagator.hasReference()) {
      const auto t0 = Clock::now();
      const double c0 = processCpuMs();
      const Instances out = propagator.propagate(f);
      s.add("frame", msSince(t0));
      s.add("frame_cpu", processCpuMs() - c0);
      s.add("flow", propagator.lastTiming().flow_ms);
      s.add("warp", propagator.lastTiming().warp_ms);
      s.add("depth", propagator.lastTiming().depth_ms);
      benchmark::DoNotOptimize(out);
    }
    state.PauseTiming();
    propagator.setReference(f, segmenter.segment(f));  // always from a fresh segmentation
    state.ResumeTiming();
  });
  s.report(state);
}
BENCHMARK(BM_Propagation)
    ->ArgsProduct({{1, 2}, {2, 4}})
    ->ArgNames({"threads", "flow_div"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

/// The per-frame preparation whose dense flow carries the tracker's object points
/// (perception/frame_prep.hpp: grey, half-size grey, DIS ultrafast flow), at DIS's finest
/// pyramid level 2 (the preset's; 8 px patches cover 64 px of the full image) and 1 (32 px),
/// the `objects.flow_finest_scale` setting, without and with 5 variational refinement iterations
/// (`objects.flow_refinement_iterations`). One OpenCV thread: the CPU cost of the choice.
void BM_FramePrep(benchmark::State& state) {
  cv::setNumThreads(1);
  FramePrep prep({.half = true,
                  .flow = true,
                  .flow_finest_scale = int(state.range(0)),
                  .flow_refinement_iterations = int(state.range(1))});
  Samples s;
  forEachFrame(state, [&](const RgbdFrame& f) {
    const auto t0 = Clock::now();
    const double c0 = processCpuMs();
    const PreparedFrame out = prep.prepare(f);
    s.add("frame", msSince(t0));
    s.add("frame_cpu", processCpuMs() - c0);
    benchmark::DoNotOptimize(out.flow_half.data);
  });
  s.report(state);
}
BENCHMARK(BM_FramePrep)
    ->Args({2, 0})
    ->Args({1, 0})
    ->Args({1, 5})
    ->ArgNames({"finest_scale", "refinement_iterations"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

/// Pre-processing alone: blobFromImage resizing the 640x480 frame itself vs. resize + blob.
void BM_Preprocess(benchmark::State& state) {
  cv::setNumThreads(2);
  cv::Mat frame(480, 640, CV_8UC3);
  cv::randu(frame, 0, 255);
  cv::Mat small, blob;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      blob =
          cv::dnn::blobFromImage(frame, 1.0 / 255, cv::Size(320, 320), cv::Scalar(), true, false);
    } else {
      cv::resize(frame, small, cv::Size(320, 320), 0, 0, cv::INTER_LINEAR);
      cv::dnn::blobFromImage(small, blob, 1.0 / 255, cv::Size(), cv::Scalar(), true, false);
    }
    benchmark::DoNotOptimize(blob.data);
  }
}
BENCHMARK(BM_Preprocess)->Arg(0)->Arg(1)->ArgName("separate_resize")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
