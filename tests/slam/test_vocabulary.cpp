// Vocabulary: training, TF-IDF bag of words, L1 score, direct index, file round trip and checks.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "core/error.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/bow_matching.hpp"
#include "slam/vocabulary/kmajority_tree.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "support/test_support.hpp"
#include "test_orb_images.hpp"

namespace dynanav {
namespace {

// Descriptors of 24 synthetic places, and a small vocabulary trained on them (shared by tests).
class VocabularyTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    OrbExtractor extractor{OrbConfig{}};
    std::vector<cv::KeyPoint> kps;
    descriptors_ = new std::vector<cv::Mat>();
    for (int i = 0; i < 24; ++i) {
      cv::Mat d;
      extractor.extract(test::texturedImage(640, 480, 100 + i), kps, d);
      descriptors_->push_back(d);
    }
    VocabularyTrainOptions options;
    options.levels = 4;
    options.source = "synthetic test images";
    vocabulary_ = new Vocabulary(Vocabulary::train(*descriptors_, options));
  }
  static void TearDownTestSuite() {
    delete vocabulary_;
    delete descriptors_;
  }
  static inline std::vector<cv::Mat>* descriptors_ = nullptr;
  static inline Vocabulary* vocabulary_ = nullptr;
};

TEST_F(VocabularyTest, TreeHasTheRequestedShape) {
  const Vocabulary& v = *vocabulary_;
  EXPECT_EQ(v.info().branching, 10);
  EXPECT_EQ(v.info().levels, 4);
  EXPECT_EQ(v.info().training_images, 24u);
  // ~24k descriptors into at most 10^4 leaves: most leaves exist.
  EXPECT_GT(v.words(), 5000u);
  EXPECT_LE(v.words(), 10000u);
  EXPECT_GT(v.nodes(), v.words());
  for (size_t w = 0; w < v.words(); ++w) {
    ASSERT_GE(v.weight(static_cast<WordId>(w)), 0.0f);
    ASSERT_LE(v.weight(static_cast<WordId>(w)), std::log(24.0f) + 1e-5f);
  }
}

TEST(KMajorityTree, SeparatesObviousClustersAndIsDeterministic) {
  // Three clusters around far-apart centres, 2 flipped bits each.
  std::vector<Descriptor256> data;
  cv::RNG rng(5);
  const Descriptor256 centres[3] = {{{0, 0, 0, 0}}, {{~0ull, ~0ull, 0, 0}}, {{0, 0, ~0ull, ~0ull}}};
  for (int i = 0; i < 300; ++i) {
    Descriptor256 d = centres[i % 3];
    for (int f = 0; f < 2; ++f) {
      const int b = rng.uniform(0, 256);
      d.words[b >> 6] ^= uint64_t{1} << (b & 63);
    }
    data.push_back(d);
  }
  const KMajorityTree tree = buildKMajorityTree(data, 3, 1, 7, 10);
  ASSERT_EQ(tree.parent.size(), 4u);  // root + 3 children
  std::vector<bool> found(3, false);
  for (size_t n = 1; n < 4; ++n)
    for (int c = 0; c < 3; ++c)
      if (hamming(tree.centre[n], centres[c]) == 0) found[c] = true;
  EXPECT_TRUE(found[0] && found[1] && found[2]) << "k-majority centres are the cluster centres";
  const KMajorityTree again = buildKMajorityTree(data, 3, 1, 7, 10);
  EXPECT_EQ(again.parent, tree.parent);
  EXPECT_EQ(again.centre, tree.centre);
}

TEST_F(VocabularyTest, BowVectorIsNormalisedAndScoresLikeL1) {
  BowVector a, b;
  FeatureVector fa;
  vocabulary_->transform((*descriptors_)[0], a, &fa, 2);
  vocabulary_->transform((*descriptors_)[1], b);
  ASSERT_FALSE(a.empty());
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    sum += a.entries[i].second;
    if (i > 0) {
      ASSERT_LT(a.entries[i - 1].first, a.entries[i].first);
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-5);
  EXPECT_NEAR(l1Score(a, a), 1.0, 1e-5);
  EXPECT_NEAR(l1Score(a, b), l1Score(b, a), 1e-12);
  EXPECT_LT(l1Score(a, b), 0.5);
  EXPECT_EQ(l1Score(a, BowVector{}), 0.0);
  // The L1 score against a hand-computed example: |a-b|_1 = 0.6 -> s = 0.7.
  BowVector x{{{1, 0.5f}, {2, 0.5f}}}, y{{{1, 0.2f}, {2, 0.5f}, {7, 0.3f}}};
  EXPECT_NEAR(l1Score(x, y), 0.7, 1e-6);
  EXPECT_EQ(commonWords(x, y), 2);

  // Direct index: every feature exactly once, under nodes at depth <= 2, node ids ascending.
  std::vector<int> seen;
  for (size_t i = 0; i < fa.nodes.size(); ++i) {
    if (i > 0) {
      ASSERT_LT(fa.nodes[i - 1].first, fa.nodes[i].first);
    }
    seen.insert(seen.end(), fa.nodes[i].second.begin(), fa.nodes[i].second.end());
  }
  std::sort(seen.begin(), seen.end());
  std::vector<int> all((*descriptors_)[0].rows);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(seen, all);
  EXPECT_LE(fa.nodes.size(), 100u);  // k^2 nodes at depth 2
  EXPECT_GT(fa.nodes.size(), 30u);
}

TEST_F(VocabularyTest, PerturbedViewScoresHighestWithItsOwnImage) {
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps;
  std::vector<BowVector> places(descriptors_->size());
  for (size_t i = 0; i < places.size(); ++i) vocabulary_->transform((*descriptors_)[i], places[i]);
  for (int i : {0, 5, 13, 23}) {
    cv::Mat d;
    extractor.extract(
        test::perturbedView(test::texturedImage(640, 480, 100 + i), 4.0, 1.05, {8, -5}, i), kps, d);
    BowVector query;
    vocabulary_->transform(d, query);
    size_t best = 0;
    for (size_t j = 1; j < places.size(); ++j)
      if (l1Score(query, places[j]) > l1Score(query, places[best])) best = j;
    EXPECT_EQ(best, static_cast<size_t>(i));
  }
}

TEST_F(VocabularyTest, DirectIndexMatchingFindsTrueCorrespondences) {
  // A place and a view of it turned by 20 degrees and shifted: the true correspondence of each
  // keypoint is known from the warp.
  const cv::Mat image = test::texturedImage(640, 480, 100);
  const double degrees = 20.0;
  const cv::Point2d shift(15, -10);
  const cv::Mat view = test::perturbedView(image, degrees, 1.0, shift, 9);
  cv::Mat warp = cv::getRotationMatrix2D(cv::Point2f(320, 240), degrees, 1.0);
  warp.at<double>(0, 2) += shift.x;
  warp.at<double>(1, 2) += shift.y;

  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> ka, kb;
  cv::Mat da, db;
  extractor.extract(image, ka, da);
  extractor.extract(view, kb, db);
  BowVector bow;
  FeatureVector fa, fb;
  vocabulary_->transform(da, bow, &fa, 2);
  vocabulary_->transform(db, bow, &fb, 2);
  const auto matches = matchByDirectIndex(fa, da, ka, fb, db, kb);
  ASSERT_GE(matches.size(), 100u);
  int correct = 0;
  std::vector<int> used_b(kb.size(), 0);
  for (const auto& m : matches) {
    ++used_b[m.trainIdx];
    const cv::Point2f p = ka[m.queryIdx].pt;
    const cv::Point2d expected(
        warp.at<double>(0, 0) * p.x + warp.at<double>(0, 1) * p.y + warp.at<double>(0, 2),
        warp.at<double>(1, 0) * p.x + warp.at<double>(1, 1) * p.y + warp.at<double>(1, 2));
    if (cv::norm(cv::Point2d(kb[m.trainIdx].pt) - expected) <
        2.0 * extractor.scaleFactors()[ka[m.queryIdx].octave] + 1.0)
      ++correct;
    EXPECT_LE(m.distance, 50.0f);
  }
  EXPECT_EQ(*std::max_element(used_b.begin(), used_b.end()), 1) << "one A feature per B feature";
  EXPECT_GE(correct, static_cast<int>(matches.size()) * 9 / 10)
      << correct << " of " << matches.size();

  // Only usable A features take part.
  const auto even =
      matchByDirectIndex(fa, da, ka, fb, db, kb, {}, [](int a) { return a % 2 == 0; });
  EXPECT_FALSE(even.empty());
  for (const auto& m : even) EXPECT_EQ(m.queryIdx % 2, 0);
  // The orientation check drops matches that disagree with the dominant rotation.
  BowMatchOptions loose;
  loose.check_orientation = false;
  EXPECT_GE(matchByDirectIndex(fa, da, ka, fb, db, kb, loose).size(), matches.size());
}

TEST_F(VocabularyTest, SaveLoadRoundTripIsExact) {
  const auto dir = test::scratchDir("vocabulary_roundtrip");
  const std::string path = (dir / "voc.dnvoc").string();
  vocabulary_->save(path);
  const Vocabulary loaded = Vocabulary::load(path);
  EXPECT_TRUE(loaded == *vocabulary_);
  EXPECT_EQ(loaded.info().source, "synthetic test images");
  ASSERT_EQ(loaded.words(), vocabulary_->words());
  for (size_t w = 0; w < loaded.words(); ++w) {
    ASSERT_EQ(loaded.weight(static_cast<WordId>(w)), vocabulary_->weight(static_cast<WordId>(w)));
    ASSERT_EQ(loaded.wordDescriptor(static_cast<WordId>(w)),
              vocabulary_->wordDescriptor(static_cast<WordId>(w)));
  }
  BowVector a, b;
  FeatureVector fa, fb;
  vocabulary_->transform((*descriptors_)[3], a, &fa);
  loaded.transform((*descriptors_)[3], b, &fb);
  EXPECT_EQ(a, b);
  EXPECT_EQ(fa, fb);
}

// Bytes of a file, changed by `edit`, written back; load must name the file.
void expectRejected(const std::string& path, const std::function<void(std::string&)>& edit,
                    const std::string& reason) {
  std::string bytes = test::readFile(path);
  edit(bytes);
  const std::string bad = path + ".bad";
  std::ofstream(bad, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  try {
    Vocabulary::load(bad);
    ADD_FAILURE() << "accepted a file with " << reason;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
}

TEST_F(VocabularyTest, BadFilesAreRejectedWithTheirName) {
  const auto dir = test::scratchDir("vocabulary_bad");
  const std::string path = (dir / "voc.dnvoc").string();
  vocabulary_->save(path);
  expectRejected(
      path, [](std::string& b) { b.resize(b.size() / 2); }, "a truncated body");
  expectRejected(
      path, [](std::string& b) { b.resize(10); }, "a truncated header");
  expectRejected(
      path, [](std::string& b) { b[0] = 'X'; }, "wrong magic");
  expectRejected(
      path, [](std::string& b) { b[8] = 9; }, "an unknown version");
  expectRejected(
      path, [](std::string& b) { b[b.size() / 2] ^= 0x10; }, "a flipped bit");
  expectRejected(
      path, [](std::string& b) { b.clear(); }, "no bytes");
  EXPECT_THROW(Vocabulary::load((dir / "missing.dnvoc").string()), InputError);
}

// An endless or special file was read until memory ran out (/dev/zero) or blocked for ever (a
// FIFO with no writer); a huge file was read whole. Each is refused before a byte is read.
TEST(VocabularyFile, SpecialAndHugeFilesAreRefusedNamingThem) {
  const auto dir = test::scratchDir("vocabulary_special");
  const std::string fifo = (dir / "fifo.dnvoc").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string huge = (dir / "huge.dnvoc").string();
  std::ofstream(huge).put('D');
  std::filesystem::resize_file(huge, uint64_t{1} << 30);  // sparse: no disk used
  for (const std::string& path : {std::string("/dev/zero"), fifo, dir.string(), huge}) {
    const std::string message = test::errorOf([&] { (void)Vocabulary::load(path); });
    EXPECT_NE(message.find(path), std::string::npos) << path << ": " << message;
  }
  EXPECT_NE(test::errorOf([&] { (void)Vocabulary::load(huge); }).find("larger than"),
            std::string::npos);
}

}  // namespace
}  // namespace dynanav
