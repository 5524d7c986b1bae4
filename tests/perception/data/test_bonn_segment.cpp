// `dynanav segment --segmenter dnn` on the first 60 frames of ../shared/data/rgbd_bonn_crowd:
// frames 0-21 show an empty office (checked by eye, docs/perception.md), from frame 22 on a
// person walks in. Skips when the sequence or the models are absent.
#include <gtest/gtest.h>

#include "io/json_io.hpp"
#include "support/test_support.hpp"

using namespace dynanav;

TEST(BonnSegment, PeopleFoundWhereTheyAreAndNotWhereTheyAreNot) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_bonn_crowd");
  const auto models = test::sharedModels();
  if (models.empty()) GTEST_SKIP() << "../shared/models not found: skipped";
  const auto out = test::scratchDir("bonn");
  std::string log;
  ASSERT_EQ(test::runCli("segment " + seq.string() + " --out " + out.string() + " --segmenter dnn --models " +
                             models.string() + " --max-frames 60 --no-video", &log), 0) << log;
  const auto stats = readJsonFile(out / "stats.json");
  ASSERT_EQ(stats["per_frame"].size(), 60u);
  int false_people = 0, found = 0;
  for (const auto& f : stats["per_frame"]) {
    const int index = f["index"].get<int>(), persons = f["persons"].get<int>();
    if (index < 20) false_people += persons > 0;  // the ceiling marker must not count
    if (index >= 22) found += persons > 0;
  }
  EXPECT_EQ(false_people, 0);
  EXPECT_GE(found, 37);  // of 38 frames with a person in view
}
