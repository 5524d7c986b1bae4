// Moving-flag scoring against the simulator's objects_gt.jsonl (dynanav eval --stats).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.hpp"
#include "eval/moving_flags.hpp"
#include "support/test_support.hpp"

using namespace dynanav;

namespace {

ObjectTruth box(bool dynamic, int px = 5000) {
  return {2, "box", dynamic, px};
}

TEST(MovingFlags, CountsPerObjectAndSkipsFramesOutOfView) {
  // Frames: box static (not flagged), moving (flagged), moving (missed), static (flagged),
  // moving but only 10 px in view (flagged: not scored).
  const ObjectTruthFrames truth = {
      {box(false)}, {box(true)}, {box(true)}, {box(false)}, {box(true, 10)}};
  const std::vector<std::vector<int>> flagged = {{}, {2}, {}, {2, 7}, {2}};
  const auto scores = scoreMovingFlags(truth, flagged, 100);
  ASSERT_EQ(scores.size(), 1u);
  const MovingFlagScore& s = scores[0];
  EXPECT_EQ(s.id, 2);
  EXPECT_EQ(s.class_name, "box");
  EXPECT_EQ(s.true_positive, 1);
  EXPECT_EQ(s.false_negative, 1);
  EXPECT_EQ(s.false_positive, 1);
  EXPECT_EQ(s.true_negative, 1);
  EXPECT_EQ(s.out_of_view, 1);
  EXPECT_DOUBLE_EQ(s.precision(), 0.5);
  EXPECT_DOUBLE_EQ(s.recall(), 0.5);
}

TEST(MovingFlags, UndefinedRatiosAreNaN) {
  const auto scores = scoreMovingFlags({{box(false)}}, {{}}, 0);
  ASSERT_EQ(scores.size(), 1u);
  EXPECT_TRUE(std::isnan(scores[0].precision()));
  EXPECT_TRUE(std::isnan(scores[0].recall()));
}

TEST(MovingFlags, ReadsTheSimulatorAndRunFiles) {
  const auto dir = test::scratchDir("moving_flags_files");
  std::ofstream(dir / "objects_gt.jsonl")
      << R"({"objects":[{"id":1,"class":"person","dynamic":true,"points":900}],"t":0.0})"
      << "\n"
      << R"({"objects":[{"id":1,"class":"person","dynamic":false,"points":0}],"t":0.1})"
      << "\n";
  std::ofstream(dir / "stats.json")
      << R"({"dynamics":{"enabled":true,"per_frame":{"moving_ids":[[1],[]]}}})";
  const auto truth = readObjectTruth(dir / "objects_gt.jsonl");
  ASSERT_EQ(truth.size(), 2u);
  EXPECT_EQ(truth[0][0].class_name, "person");
  EXPECT_TRUE(truth[0][0].dynamic);
  EXPECT_EQ(truth[0][0].visible_px, 900);
  const auto flags = readMovingFlags(dir / "stats.json");
  ASSERT_EQ(flags.size(), 2u);
  EXPECT_EQ(flags[0], std::vector<int>{1});
}

TEST(MovingFlags, BadInputNamesTheFile) {
  const auto dir = test::scratchDir("moving_flags_bad");
  std::ofstream(dir / "objects_gt.jsonl") << R"({"objects":[{"id":1}]})"
                                          << "\n";
  std::ofstream(dir / "off.json") << R"({"dynamics":{"enabled":false}})";
  try {
    (void)readObjectTruth(dir / "objects_gt.jsonl");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("objects_gt.jsonl:1"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)readMovingFlags(dir / "off.json"), InputError);
  EXPECT_THROW((void)readMovingFlags(dir / "missing.json"), InputError);
}

}  // namespace
