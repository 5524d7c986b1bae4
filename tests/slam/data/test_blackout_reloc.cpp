// Issue 4's tracking-loss drill on real data: 16 black frames (100..115) in fr1_xyz; tracking must
// come back by relocalisation within 5 frames of the images returning, with ATE over all tracked
// frames under 0.015 m. And on bonn_crowd (people walking, no revisit) no loop may be accepted.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// The CLI finds the vocabulary the same way (next to the executables); without it relocalisation
/// and loop closing are off and these tests say nothing.
bool vocabularyBuilt() {
  try {
    findVocabulary();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

using test::ateRmse;  // ATE RMSE as `dynanav eval --json` prints it

TEST(BlackoutDrill, RelocalisesWithinFiveFramesAndKeepsAccuracy) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  if (!vocabularyBuilt())
    GTEST_SKIP() << "no vocabulary built (target dynanav_vocabulary): skipped";
  const fs::path out = test::scratchDir("blackout_reloc");
  std::string log;
  ASSERT_EQ(
      test::runCli("run " + seq.string() + " --out " + out.string() + " --blackout 100:115 --quiet",
                   &log),
      0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["frames"], 244);
  ASSERT_GE(stats["relocalisations"].get<int>(), 1) << stats.dump();
  const int first = stats["relocalisation_frames"][0].get<int>();
  EXPECT_GE(first, 116) << "black frames cannot relocalise";
  EXPECT_LE(first, 120) << "relocalised within 5 frames of the images returning";
  EXPECT_LE(stats["lost"].get<int>(), 16 + 4);
  const double ate = ateRmse(seq / "groundtruth.txt", out / "trajectory.txt");
  std::printf("blackout 100:115: relocalised at frame %d, %d tracked, ATE %.4f m\n", first,
              stats["tracked"].get<int>(), ate);
  EXPECT_LE(ate, 0.015);
}

TEST(LoopClosing, NoFalseLoopOnBonnCrowd) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_bonn_crowd");
  if (!vocabularyBuilt())
    GTEST_SKIP() << "no vocabulary built (target dynanav_vocabulary): skipped";
  const fs::path out = test::scratchDir("bonn_no_loop");
  std::string log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() + " --quiet", &log), 0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  std::printf("bonn_crowd: %d loops, %d keyframes\n", stats["loops"].get<int>(),
              stats["keyframes"].get<int>());
  EXPECT_EQ(stats["loops"], 0) << stats["loop_details"].dump();
}

}  // namespace
}  // namespace dynanav
