// Bag-of-words transform and keyframe-database query per frame, with the vocabulary the build
// trained (share/dynanav/orb_vocabulary.dnvoc next to bin/) on frames of
// ../shared/data/rgbd_dataset_freiburg1_xyz (both skipped when absent). The counters give the
// mean L1 score of frames 10 apart (same place) and of fr1_xyz against rgbd_bonn_crowd frames
// (different places).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "slam/keyframe_database.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"

namespace {
namespace fs = std::filesystem;

std::vector<fs::path> frames(const std::string& sequence) {
  const fs::path dir = fs::path(DYNANAV_SHARED_DIR) / "data" / sequence / "rgb";
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct Fixture {
  dynanav::Vocabulary vocabulary;
  std::vector<cv::Mat> descriptors;  // fr1_xyz, every 10th frame
  std::vector<cv::Mat> other;        // bonn_crowd, every 20th frame
  std::string error;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture f;
    try {
      f.vocabulary = dynanav::Vocabulary::load(dynanav::findVocabulary().string());
    } catch (const std::exception& e) {
      f.error = e.what();
      return f;
    }
    dynanav::OrbExtractor extractor{dynanav::OrbConfig{}};
    std::vector<cv::KeyPoint> kps;
    const auto load = [&](const std::string& seq, size_t step, std::vector<cv::Mat>& out) {
      const auto files = frames(seq);
      for (size_t i = 0; i < files.size(); i += step) {
        cv::Mat d;
        extractor.extract(cv::imread(files[i].string(), cv::IMREAD_GRAYSCALE), kps, d);
        out.push_back(d);
      }
    };
    load("rgbd_dataset_freiburg1_xyz", 10, f.descriptors);
    load("rgbd_bonn_crowd", 20, f.other);
    if (f.descriptors.empty()) f.error = "../shared/data/rgbd_dataset_freiburg1_xyz not found: skipped";
    return f;
  }();
  return f;
}

void BM_BowTransform(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  dynanav::BowVector bow;
  dynanav::FeatureVector features;
  size_t i = 0;
  for (auto _ : state) {
    f.vocabulary.transform(f.descriptors[i++ % f.descriptors.size()], bow, &features, 2);
    benchmark::DoNotOptimize(bow.entries.data());
  }
  state.counters["words"] = static_cast<double>(f.vocabulary.words());
  state.counters["bow_entries"] = static_cast<double>(bow.size());
}
BENCHMARK(BM_BowTransform)->Unit(benchmark::kMillisecond);

void BM_DatabaseQuery(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.error.empty()) return state.SkipWithError(f.error.c_str());
  std::vector<dynanav::BowVector> same(f.descriptors.size()), other(f.other.size());
  for (size_t i = 0; i < same.size(); ++i) f.vocabulary.transform(f.descriptors[i], same[i]);
  for (size_t i = 0; i < other.size(); ++i) f.vocabulary.transform(f.other[i], other[i]);
  dynanav::KeyframeDatabase db;
  for (size_t i = 0; i < same.size(); i += 2) db.add(i, same[i]);  // every 20th frame as keyframe
  for (size_t i = 0; i < other.size(); ++i) db.add(100000 + i, other[i]);
  size_t q = 1, top_is_same_sequence = 0, top_is_adjacent = 0, queries = 0;
  for (auto _ : state) {
    const auto result = db.query(same[q], dynanav::PlaceQuery{});
    benchmark::DoNotOptimize(result.data());
    ++queries;
    if (!result.empty() && result[0].id < 100000) ++top_is_same_sequence;
    if (!result.empty() && (result[0].id + 1 == q || result[0].id == q + 1)) ++top_is_adjacent;
    q = (q + 2) % same.size() | 1;  // odd frames: not in the database
  }
  double near_score = 0.0, far_score = 0.0;
  size_t n_near = 0, n_far = 0;
  for (size_t i = 0; i + 1 < same.size(); ++i, ++n_near) near_score += dynanav::l1Score(same[i], same[i + 1]);
  size_t neighbour_wins = 0;  // frame 10 apart scores above every frame of the other sequence
  for (size_t i = 0; i < same.size(); ++i) {
    double best_other = 0.0;
    for (size_t j = 0; j < other.size(); ++j, ++n_far) {
      const double s = dynanav::l1Score(same[i], other[j]);
      far_score += s;
      best_other = std::max(best_other, s);
    }
    if (i + 1 < same.size() && dynanav::l1Score(same[i], same[i + 1]) > best_other) ++neighbour_wins;
  }
  state.counters["neighbour_wins"] =
      same.size() > 1 ? static_cast<double>(neighbour_wins) / static_cast<double>(same.size() - 1) : 0.0;
  state.counters["keyframes"] = static_cast<double>(db.size());
  state.counters["top1_adjacent"] = static_cast<double>(top_is_adjacent) / static_cast<double>(queries);
  state.counters["top1_same_seq"] = static_cast<double>(top_is_same_sequence) / static_cast<double>(queries);
  state.counters["score_10_apart"] = n_near ? near_score / static_cast<double>(n_near) : 0.0;
  state.counters["score_other_seq"] = n_far ? far_score / static_cast<double>(n_far) : 0.0;
}
BENCHMARK(BM_DatabaseQuery)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
