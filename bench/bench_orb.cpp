// ORB extraction time per 640x480 frame on one core (target <= 8 ms, issue 3).
// Uses the first frame of ../shared/data/rgbd_dataset_freiburg1_xyz (skipped when absent).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
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

// Matching quality, not speed: frame pairs (i, i + gap) every 10 frames; ratio-test matches
// (0.8, Hamming < 64), then RANSAC fundamental matrix (1 px). Mean inliers per pair for our
// extractor and for OpenCV's ORB with its defaults (strongest Harris corners, no spreading).
void BM_OrbMatchInliers(benchmark::State& state) {
  const auto files = frameFiles();
  if (files.empty()) {
    state.SkipWithError("../shared/data/rgbd_dataset_freiburg1_xyz/rgb not found: skipped");
    return;
  }
  const int gap = static_cast<int>(state.range(0));
  dynanav::OrbExtractor extractor{dynanav::OrbConfig{}};
  const auto opencv = cv::ORB::create(1000, 1.2f, 8);
  const auto inliers = [](const std::vector<cv::KeyPoint>& ka, const cv::Mat& da,
                          const std::vector<cv::KeyPoint>& kb, const cv::Mat& db) {
    std::vector<std::vector<cv::DMatch>> knn;
    cv::BFMatcher(cv::NORM_HAMMING).knnMatch(da, db, knn, 2);
    std::vector<cv::Point2f> pa, pb;
    for (const auto& k : knn) {
      if (k.size() == 2 && k[0].distance < 0.8f * k[1].distance && k[0].distance < 64) {
        pa.push_back(ka[k[0].queryIdx].pt);
        pb.push_back(kb[k[0].trainIdx].pt);
      }
    }
    if (pa.size() < 8) return 0;
    cv::Mat mask;
    cv::findFundamentalMat(pa, pb, cv::FM_RANSAC, 1.0, 0.999, mask);
    return cv::countNonZero(mask);
  };
  double ours = 0.0, reference = 0.0;
  int pairs = 0;
  for (auto _ : state) {
    cv::setRNGSeed(1);  // RANSAC draws from OpenCV's global RNG
    for (size_t i = 0; i + gap < files.size(); i += 10, ++pairs) {
      const cv::Mat a = cv::imread(files[i].string(), cv::IMREAD_GRAYSCALE);
      const cv::Mat b = cv::imread(files[i + gap].string(), cv::IMREAD_GRAYSCALE);
      std::vector<cv::KeyPoint> ka, kb;
      cv::Mat da, db;
      extractor.extract(a, ka, da);
      extractor.extract(b, kb, db);
      ours += inliers(ka, da, kb, db);
      opencv->detectAndCompute(a, cv::noArray(), ka, da);
      opencv->detectAndCompute(b, cv::noArray(), kb, db);
      reference += inliers(ka, da, kb, db);
    }
  }
  state.counters["inliers_ours"] = pairs ? ours / pairs : 0.0;
  state.counters["inliers_cv_orb"] = pairs ? reference / pairs : 0.0;
  state.counters["pairs"] = pairs;
}
BENCHMARK(BM_OrbMatchInliers)->Arg(1)->Arg(5)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
