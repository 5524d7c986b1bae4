// Place recognition on the simulator's loop (the wearer walks ~21 m through two rooms and back):
// with the project's vocabulary (trained on opencv-doc images only, never on renders), frames that
// revisit a place find a frame of that place, taken more than 10 s earlier or later, as their best
// bag-of-words match. This is what loop detection stands on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <opencv2/imgcodecs.hpp>

#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {
namespace fs = std::filesystem;

struct Sample {
  double stamp_s, x, z;
};

TEST(VocabularySimLoop, RevisitedPlacesAreRecognised) {
  fs::path vocabulary_path;
  try {
    vocabulary_path = findVocabulary();
  } catch (const std::exception& e) {
    GTEST_SKIP() << e.what();
  }
  const auto dir = test::scratchDir("vocabulary_sim_loop");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario loop --fps 2 --seed 3 --out " + dir.string(), &log), 0) << log;

  std::vector<Sample> gt;
  std::ifstream file(dir / "groundtruth.txt");
  for (std::string line; std::getline(file, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Sample g{};
    double y;
    s >> g.stamp_s >> g.x >> y >> g.z;
    gt.push_back(g);
  }
  std::vector<fs::path> frames;
  for (const auto& e : fs::directory_iterator(dir / "rgb")) frames.push_back(e.path());
  std::sort(frames.begin(), frames.end(), [](const fs::path& a, const fs::path& b) {
    return std::stod(a.stem().string()) < std::stod(b.stem().string());
  });
  ASSERT_EQ(frames.size(), gt.size());

  const Vocabulary vocabulary = Vocabulary::load(vocabulary_path.string());
  OrbExtractor extractor{OrbConfig{}};
  std::vector<BowVector> bows(frames.size());
  std::vector<cv::KeyPoint> kps;
  for (size_t i = 0; i < frames.size(); ++i) {
    cv::Mat d;
    extractor.extract(cv::imread(frames[i].string(), cv::IMREAD_GRAYSCALE), kps, d);
    vocabulary.transform(d, bows[i]);
  }
  const auto apart = [&](size_t a, size_t b) { return std::abs(gt[a].stamp_s - gt[b].stamp_s) >= 10.0; };
  const auto distance_m = [&](size_t a, size_t b) { return std::hypot(gt[a].x - gt[b].x, gt[a].z - gt[b].z); };
  int revisits = 0, recognised = 0;
  for (size_t q = 0; q < frames.size(); ++q) {
    bool revisit = false;
    size_t best = q;
    double best_score = -1.0;
    for (size_t c = 0; c < frames.size(); ++c) {
      if (!apart(q, c)) continue;
      revisit |= distance_m(q, c) < 0.7;
      if (const double s = l1Score(bows[q], bows[c]); s > best_score) best_score = s, best = c;
    }
    if (!revisit) continue;
    ++revisits;
    recognised += distance_m(q, best) < 1.5;
  }
  std::printf("revisits recognised: %d of %d\n", recognised, revisits);
  ASSERT_GE(revisits, 10) << "the loop scenario should come back to where it started";
  EXPECT_GE(recognised, revisits * 9 / 10) << recognised << " of " << revisits;
}

}  // namespace
}  // namespace dynanav
