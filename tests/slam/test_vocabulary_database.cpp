// Keyframe database: inverted-file queries, ordering, erase, covisibility grouping, and place
// recognition of a shifted and turned view (synthetic places, and opencv-doc photos if installed).
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "slam/keyframe_database.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "test_orb_images.hpp"

namespace dynanav {
namespace {

BowVector bow(std::initializer_list<std::pair<WordId, float>> entries) { return BowVector{entries}; }

TEST(KeyframeDatabase, QueriesScoreSharedWordsInADeterministicOrder) {
  KeyframeDatabase db;
  db.add(7, bow({{1, 0.5f}, {2, 0.5f}}));
  db.add(3, bow({{1, 0.5f}, {2, 0.5f}}));   // same as 7: tie broken by id
  db.add(5, bow({{1, 0.25f}, {9, 0.75f}}));
  db.add(8, bow({{4, 1.0f}}));              // shares nothing
  EXPECT_EQ(db.size(), 4u);
  PlaceQuery q;
  q.min_common_words_ratio = 0.0;
  auto result = db.query(bow({{1, 0.5f}, {2, 0.5f}}), q);
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result[0].id, 3u);
  EXPECT_EQ(result[1].id, 7u);
  EXPECT_EQ(result[2].id, 5u);
  EXPECT_NEAR(result[0].score, 1.0, 1e-6);
  EXPECT_NEAR(result[2].score, 0.25, 1e-6);
  EXPECT_EQ(result[0].common_words, 2);

  q.min_score = 0.3;  // drops 5
  EXPECT_EQ(db.query(bow({{1, 0.5f}, {2, 0.5f}}), q).size(), 2u);
  q.min_score = 0.0;
  q.min_common_words_ratio = 1.0;  // 5 shares 1 word of the best 2
  EXPECT_EQ(db.query(bow({{1, 0.5f}, {2, 0.5f}}), q).size(), 2u);
  q.exclude = [](KeyframeId id) { return id == 3; };
  result = db.query(bow({{1, 0.5f}, {2, 0.5f}}), q);
  ASSERT_EQ(result.size(), 1u);
  EXPECT_EQ(result[0].id, 7u);

  db.erase(7);
  db.erase(42);  // unknown: ignored
  EXPECT_FALSE(db.contains(7));
  EXPECT_EQ(db.query(bow({{1, 0.5f}, {2, 0.5f}}), PlaceQuery{}).front().id, 3u);
  db.add(3, bow({{4, 1.0f}}));  // replaced: no longer under words 1 and 2
  EXPECT_TRUE(db.query(bow({{2, 1.0f}}), PlaceQuery{}).empty());
  db.clear();
  EXPECT_EQ(db.size(), 0u);
}

TEST(KeyframeDatabase, CovisibleGroupsOutweighALoneKeyframe) {
  KeyframeDatabase db;
  db.add(1, bow({{1, 0.6f}, {2, 0.4f}}));   // the best single match, alone
  db.add(10, bow({{1, 0.5f}, {3, 0.5f}}));  // a group of three medium matches
  db.add(11, bow({{1, 0.5f}, {4, 0.5f}}));
  db.add(12, bow({{1, 0.5f}, {5, 0.5f}}));
  PlaceQuery q;
  q.min_common_words_ratio = 0.0;
  q.covisible = [](KeyframeId id) {
    if (id >= 10) return std::vector<KeyframeId>{10, 11, 12};
    return std::vector<KeyframeId>{};
  };
  const auto result = db.query(bow({{1, 1.0f}}), q);
  // Lone: 0.6. Group members: 0.5 each, accumulated 1.5. 0.6 < 0.75 * 1.5: the lone one goes.
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result[0].id, 10u);
  EXPECT_NEAR(result[0].accumulated_score, 1.5, 1e-6);
}

// Trains a vocabulary on `train`, adds `places` to a database and checks that a shifted, turned,
// noisy view of each place finds that place first, by `margin` over the runner-up. (These small
// test vocabularies have few words, so unrelated images still score ~0.18; the project's
// vocabulary separates much more, see docs/orb_vocabulary.md.)
void expectViewsFindTheirPlace(const std::vector<cv::Mat>& train, const std::vector<cv::Mat>& places,
                               double margin) {
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps;
  std::vector<cv::Mat> train_descriptors;
  for (const cv::Mat& image : train) {
    cv::Mat d;
    extractor.extract(image, kps, d);
    train_descriptors.push_back(d);
  }
  VocabularyTrainOptions options;
  options.levels = 4;
  const Vocabulary vocabulary = Vocabulary::train(train_descriptors, options);
  KeyframeDatabase db;
  for (size_t i = 0; i < places.size(); ++i) {
    cv::Mat d;
    BowVector v;
    extractor.extract(places[i], kps, d);
    vocabulary.transform(d, v);
    db.add(100 + i, v);
  }
  for (size_t i = 0; i < places.size(); ++i) {
    cv::Mat d;
    BowVector v;
    extractor.extract(test::perturbedView(places[i], 5.0, 0.95, {12, 7}, i), kps, d);
    vocabulary.transform(d, v);
    const auto candidates = db.query(v, PlaceQuery{});
    ASSERT_FALSE(candidates.empty()) << "place " << i;
    EXPECT_EQ(candidates.front().id, 100 + i) << "place " << i;
    if (candidates.size() > 1) {
      EXPECT_GT(candidates[0].score, margin * candidates[1].score) << "place " << i;
    }
  }
}

TEST(KeyframeDatabase, SyntheticPlacesAreRecognisedFromANewView) {
  std::vector<cv::Mat> train, places;
  for (int i = 0; i < 16; ++i) train.push_back(test::texturedImage(640, 480, 500 + i));
  for (int i = 0; i < 10; ++i) places.push_back(test::texturedImage(640, 480, 900 + i));
  expectViewsFindTheirPlace(train, places, 1.25);
}

TEST(KeyframeDatabase, OpencvDocPhotosAreRecognisedFromANewView) {
  const std::filesystem::path dir = "/usr/share/doc/opencv-doc/examples/data";
  // Trained on half of the photos, queried with the other half: the places are new to the tree.
  const std::vector<std::string> train_names = {"aero1.jpg", "baboon.jpg", "building.jpg", "fruits.jpg",
                                                "graf1.png", "home.jpg", "apple.jpg", "messi5.jpg"};
  const std::vector<std::string> place_names = {"box_in_scene.png", "leuvenA.jpg", "starry_night.jpg",
                                                "stuff.jpg", "board.jpg", "butterfly.jpg"};
  std::vector<cv::Mat> train, places;
  for (const auto& n : train_names) train.push_back(cv::imread((dir / n).string(), cv::IMREAD_GRAYSCALE));
  for (const auto& n : place_names) places.push_back(cv::imread((dir / n).string(), cv::IMREAD_GRAYSCALE));
  for (const auto& list : {&train, &places})
    for (const cv::Mat& m : *list)
      if (m.empty()) GTEST_SKIP() << dir << " (Debian package opencv-doc) not installed: skipped";
  expectViewsFindTheirPlace(train, places, 1.25);
}

}  // namespace
}  // namespace dynanav
