// Simulator throughput: scene building, rendering, sensor models and PNG encoding per frame
// (640x480). Run: build/<dir>/bin/bench_sim ; whole-CLI throughput: see docs/simulator.md.
#include <benchmark/benchmark.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include "sim/simulator.hpp"

namespace {

using dynanav::sim::SimOptions;
using dynanav::sim::Simulator;

SimOptions options(const std::string& scenario, bool noiseless = false) {
  SimOptions o;
  o.scenario = scenario;
  o.noiseless = noiseless;
  return o;
}

void BM_BuildScenario(benchmark::State& state, const std::string& scenario) {
  for (auto _ : state) {
    Simulator sim(options(scenario));
    benchmark::DoNotOptimize(sim.frameCount());
  }
}
BENCHMARK_CAPTURE(BM_BuildScenario, office, std::string("office"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildScenario, loop, std::string("loop"))->Unit(benchmark::kMillisecond);

/// Render + sensor models + ground truth of one frame (no file writing).
void BM_RenderFrame(benchmark::State& state, const std::string& scenario, bool noiseless) {
  Simulator sim(options(scenario, noiseless));
  int i = 0;
  for (auto _ : state) {
    auto frame = sim.render(i);
    benchmark::DoNotOptimize(frame.bgr.data);
    i = (i + 1) % sim.frameCount();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_RenderFrame, office, std::string("office"), false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderFrame, office_noiseless, std::string("office"), true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderFrame, loop, std::string("loop"), false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// The same on one thread: the CPU cost of a frame, whatever else runs on the machine.
void BM_RenderFrameOneThread(benchmark::State& state) {
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  Simulator sim(options("office"));
  int i = 0;
  for (auto _ : state) {
    auto frame = sim.render(i);
    benchmark::DoNotOptimize(frame.bgr.data);
    i = (i + 1) % sim.frameCount();
  }
  cv::setNumThreads(threads);
}
BENCHMARK(BM_RenderFrameOneThread)->Unit(benchmark::kMillisecond);

/// Encoding the three PNGs of a frame into memory (what writing costs besides the disk).
void BM_EncodeFrame(benchmark::State& state) {
  Simulator sim(options("office"));
  const auto frame = sim.render(30);
  cv::Mat depth16;
  frame.depth_m.convertTo(depth16, CV_16U, 5000.0);
  std::vector<uchar> buffer;
  for (auto _ : state) {
    cv::imencode(".png", frame.bgr, buffer);
    cv::imencode(".png", depth16, buffer);
    cv::imencode(".png", frame.instance, buffer);
    benchmark::DoNotOptimize(buffer.data());
  }
}
BENCHMARK(BM_EncodeFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One image, arg 0 = rgb/depth/mask, arg 1 = PNG strategy (-1 = OpenCV's defaults: SUB filter,
/// zlib level 1, RLE). Passing IMWRITE_PNG_COMPRESSION makes OpenCV 4.6 try every PNG filter
/// (slow).
void BM_EncodePng(benchmark::State& state) {
  static Simulator sim(options("office"));
  static const auto frame = sim.render(30);
  cv::Mat depth16;
  frame.depth_m.convertTo(depth16, CV_16U, 5000.0);
  const cv::Mat& img = state.range(0) == 0   ? frame.bgr
                       : state.range(0) == 1 ? depth16
                                             : frame.instance;
  std::vector<int> params;
  if (state.range(1) >= 0) params = {cv::IMWRITE_PNG_STRATEGY, int(state.range(1))};
  std::vector<uchar> buffer;
  for (auto _ : state) {
    cv::imencode(".png", img, buffer, params);
    benchmark::DoNotOptimize(buffer.data());
  }
  state.counters["kB"] = double(buffer.size()) / 1000.0;
}
BENCHMARK(BM_EncodePng)->ArgsProduct({{0, 1, 2}, {-1, 0, 2}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
