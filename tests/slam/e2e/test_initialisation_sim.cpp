// The map starts at the first frame of a corridor with the built-in configuration. In the
// simulated `approach` hall the far part lies beyond the depth range, and its first frames hold
// fewer than 500 keypoints with depth (the default until session 25): the run never started SLAM
// without a config override. The tracker needs 30 local-map inliers, so 150 points with depth
// leave it a fivefold margin.
#include <gtest/gtest.h>

#include "io/json_io.hpp"
#include "keyframe_gap.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

TEST(InitialisationSim, AHallBeyondTheDepthRangeStartsAtItsFirstFrame) {
  const fs::path seq = test::scratchDir("init_hall_seq");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario approach --frames 12 --out " + seq.string(), &log), 0)
      << log;
  const fs::path out = test::scratchDir("init_hall_out");
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --dynamic off --deterministic --quiet",
                         &log),
            0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["tracked"].get<int>(), 12) << stats.dump();
  EXPECT_EQ(stats["lost"].get<int>(), 0);
}

// Without a vocabulary too (no loop closing): local bundle adjustment alone moved keyframes by
// up to 1 cm on 60 frames of this walk, and their own frames were written where they had been.
TEST(InitialisationSim, AKeyframesFrameIsWrittenAtItsKeyframesFinalPose) {
  const fs::path seq = test::scratchDir("anchor_hall_seq");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario approach --frames 60 --out " + seq.string(), &log), 0)
      << log;
  const fs::path out = test::scratchDir("anchor_hall_out");
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --dynamic off --deterministic --quiet",
                         &log),
            0)
      << log;
  EXPECT_LT(test::keyframeFrameGap(out), 1e-6);
}

}  // namespace
}  // namespace dynanav
