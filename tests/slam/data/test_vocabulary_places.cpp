// The project's vocabulary (trained by the build on opencv-doc images only) on real RGB-D frames
// it has never seen: frames of one room find that room among frames of another.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "slam/keyframe_database.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {
namespace fs = std::filesystem;

std::vector<BowVector> bowsOf(const fs::path& sequence, size_t step, const Vocabulary& vocabulary) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(sequence / "rgb")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps;
  std::vector<BowVector> bows;
  for (size_t i = 0; i < files.size(); i += step) {
    cv::Mat d;
    extractor.extract(cv::imread(files[i].string(), cv::IMREAD_GRAYSCALE), kps, d);
    bows.emplace_back();
    vocabulary.transform(d, bows.back());
  }
  return bows;
}

TEST(VocabularyPlaces, Fr1XyzFramesFindTheirRoomAmongBonnFrames) {
  DYNANAV_REQUIRE_SEQUENCE(fr1, "rgbd_dataset_freiburg1_xyz");
  DYNANAV_REQUIRE_SEQUENCE(bonn, "rgbd_bonn_crowd");
  fs::path path;
  try {
    path = findVocabulary();
  } catch (const std::exception& e) {
    GTEST_SKIP() << e.what();
  }
  const Vocabulary vocabulary = Vocabulary::load(path.string());
  const auto room = bowsOf(fr1, 10, vocabulary);
  const auto other = bowsOf(bonn, 20, vocabulary);
  KeyframeDatabase db;
  for (size_t i = 0; i < room.size(); i += 2) db.add(i, room[i]);
  for (size_t i = 0; i < other.size(); ++i) db.add(100000 + i, other[i]);
  int found = 0, queries = 0;
  for (size_t i = 1; i < room.size(); i += 2, ++queries) {
    const auto result = db.query(room[i], PlaceQuery{});
    found += !result.empty() && result.front().id < 100000;
  }
  EXPECT_EQ(found, queries) << "fr1_xyz frames whose best match is an fr1_xyz keyframe";
}

}  // namespace
}  // namespace dynanav
