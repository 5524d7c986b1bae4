// `dynanav vocabulary train|info` end to end: train on a folder of images, inspect, reject bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "slam/vocabulary/vocabulary.hpp"
#include "support/test_support.hpp"
#include "slam/test_orb_images.hpp"

namespace dynanav {
namespace {

TEST(VocabularyCli, TrainsOnAFolderAndReportsWhatItBuilt) {
  const auto dir = test::scratchDir("vocabulary_cli");
  const auto images = dir / "images";
  std::filesystem::create_directories(images / "sub");
  for (int i = 0; i < 6; ++i)
    cv::imwrite((images / (i < 3 ? "" : "sub") / ("place" + std::to_string(i) + ".png")).string(),
                test::texturedImage(640, 480, 40 + i));
  const std::string out = (dir / "voc.dnvoc").string();
  std::string log;
  ASSERT_EQ(test::runCli("vocabulary train " + images.string() + " --out " + out + " --levels 3 --k 8", &log), 0)
      << log;
  const Vocabulary v = Vocabulary::load(out);
  EXPECT_EQ(v.info().branching, 8);
  EXPECT_EQ(v.info().levels, 3);
  EXPECT_EQ(v.info().training_images, 6u);  // the sub-folder is searched too
  EXPECT_GT(v.words(), 200u);

  ASSERT_EQ(test::runCli("vocabulary info " + out, &log), 0) << log;
  EXPECT_NE(log.find("k: 8"), std::string::npos) << log;
  EXPECT_NE(log.find("levels: 3"), std::string::npos) << log;
  EXPECT_NE(log.find("words: " + std::to_string(v.words())), std::string::npos) << log;
  EXPECT_NE(log.find("source: 6 images"), std::string::npos) << log;

  // Same input, same seed: the same bytes.
  const std::string again = (dir / "again.dnvoc").string();
  ASSERT_EQ(test::runCli("vocabulary train " + images.string() + " --out " + again + " --levels 3 --k 8"), 0);
  EXPECT_EQ(test::readFile(out), test::readFile(again));

  ASSERT_EQ(test::runCli("vocabulary train " + images.string() + " --out " + again + " --levels 3 --max-images 2", &log), 0) << log;
  EXPECT_EQ(Vocabulary::load(again).info().training_images, 2u);
}

TEST(VocabularyCli, BadInputExitsWithTwoAndNamesIt) {
  const auto dir = test::scratchDir("vocabulary_cli_bad");
  std::string log;
  EXPECT_EQ(test::runCli("vocabulary info " + (dir / "missing.dnvoc").string(), &log), 2);
  EXPECT_NE(log.find("missing.dnvoc"), std::string::npos) << log;
  const auto junk = dir / "junk.dnvoc";
  std::ofstream(junk) << "not a vocabulary";
  EXPECT_EQ(test::runCli("vocabulary info " + junk.string(), &log), 2);
  EXPECT_NE(log.find("junk.dnvoc"), std::string::npos) << log;
  EXPECT_EQ(test::runCli("vocabulary train " + (dir / "nothing_here").string() + " --out " + (dir / "v").string(), &log), 2);
  EXPECT_NE(log.find("nothing_here"), std::string::npos) << log;
  std::filesystem::create_directories(dir / "empty");
  EXPECT_EQ(test::runCli("vocabulary train " + (dir / "empty").string() + " --out " + (dir / "v").string(), &log), 2);
  EXPECT_EQ(test::runCli("vocabulary train " + (dir / "empty").string() + " --out x --k 1", &log), 2);
}

}  // namespace
}  // namespace dynanav
