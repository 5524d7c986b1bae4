// ORB extraction time per 640x480 frame on one core (target <= 8 ms, issue 3).
// Uses the first frame of ../shared/data/rgbd_dataset_freiburg1_xyz (skipped when absent).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "slam/orb_extractor.hpp"

namespace {

std::vector<std::filesystem::path> frameFiles() {
  const std::filesystem::path dir = std::filesystem::path(DYNANAV_SHARED_DIR) /
                                    "data/rgbd_dataset_freiburg1_xyz/rgb";
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

cv::Mat benchFrame() {
  const auto files = frameFiles();
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
  for (int l = 0; l < extractor.levels(); ++l) {
    std::string name = "L";  // (not "L" + to_string: GCC 12 warns falsely about that)
    name += std::to_string(l);
    state.counters[name] = per_level[l];
  }
}
BENCHMARK(BM_OrbExtract)->Unit(benchmark::kMillisecond);

// 50 frames spread over the whole sequence (some blurred by fast motion): time per frame and the
// fewest features any of them gave.
void BM_OrbExtractSequence(benchmark::State& state) {
  cv::setNumThreads(0);
  const auto files = frameFiles();
  if (files.empty()) {
    state.SkipWithError("../shared/data/rgbd_dataset_freiburg1_xyz/rgb not found: skipped");
    return;
  }
  std::vector<cv::Mat> frames;
  for (size_t i = 0; i < 50; ++i)
    frames.push_back(cv::imread(files[i * files.size() / 50].string(), cv::IMREAD_GRAYSCALE));
  dynanav::OrbExtractor extractor{dynanav::OrbConfig{}};
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  size_t i = 0, fewest = 1000000;
  for (auto _ : state) {
    extractor.extract(frames[i++ % frames.size()], keypoints, descriptors);
    fewest = std::min(fewest, keypoints.size());
  }
  state.counters["min_features"] = static_cast<double>(fewest);
}
BENCHMARK(BM_OrbExtractSequence)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
