// ORB extraction time per 640x480 frame on one core (target <= 8 ms, issue 3).
// Uses the first frame of ../shared/data/rgbd_dataset_freiburg1_xyz (skipped when absent).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "slam/orb_extractor.hpp"

namespace {

cv::Mat benchFrame() {
  const std::filesystem::path dir = std::filesystem::path(DYNANAV_SHARED_DIR) /
                                    "data/rgbd_dataset_freiburg1_xyz/rgb";
  if (!std::filesystem::is_directory(dir)) return {};
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files.empty() ? cv::Mat() : cv::imread(files.front().string(), cv::IMREAD_GRAYSCALE);
}

void BM_OrbExtract(benchmark::State& state) {
  cv::setNumThreads(0);  // one core, as the target says
  const cv::Mat gray = benchFrame();
  if (gray.empty()) {
    state.SkipWithError("../shared/data/rgbd_dataset_freiburg1_xyz/rgb not found: skipped");
    return;
  }
  dynanav::OrbExtractor extractor{dynanav::OrbConfig{}};
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  for (auto _ : state) {
    extractor.extract(gray, keypoints, descriptors);
    benchmark::DoNotOptimize(descriptors.data);
  }
  state.counters["features"] = static_cast<double>(keypoints.size());
  std::vector<int> per_level(extractor.levels(), 0);
  for (const auto& kp : keypoints) ++per_level[kp.octave];
  for (int l = 0; l < extractor.levels(); ++l)
    state.counters["L" + std::to_string(l)] = per_level[l];
}
BENCHMARK(BM_OrbExtract)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
