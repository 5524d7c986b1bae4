// Issue 16, long run: on two turned passes of the Bonn window, local mapping culls keyframes and
// every culled keyframe is freed (the KeyFrame objects alive exceed the map's keyframes only by
// the few the tracker still holds for a frame), so over a long run memory follows the live map.
// Before the anchors moved off culled keyframes, every culled one stayed in memory.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

TEST(LongRunMemory, CulledKeyFramesAreFreedOverTwoPassesOfBonn) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_bonn_crowd");
  const fs::path out = test::scratchDir("long_run_memory");
  std::string log;
  // Deterministic and without segmentation: the same keyframes are culled every run (8 at the
  // time of writing), in about a minute and a half of CPU.
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --passes 2 --segmenter none --deterministic --quiet",
                         &log),
            0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["frames"], 1000);
  ASSERT_GT(stats["keyframes_culled"].get<int>(), 0) << "nothing culled: the test shows nothing";
  EXPECT_LE(stats["keyframes_in_memory"].get<int>(), stats["keyframes"].get<int>() + 2);
  ASSERT_FALSE(stats["keyframes_curve"].empty());
  // Along the run the tracker's local map may still hold a few keyframes culled this frame.
  for (const auto& sample : stats["keyframes_curve"])
    EXPECT_LE(sample[2].get<int>(), sample[1].get<int>() + 5) << sample.dump();
}

}  // namespace
}  // namespace dynanav
