// The map starts at the first frame of a corridor with the built-in configuration. In the
// simulated `approach` hall the far part lies beyond the depth range, and its first frames hold
// fewer than 500 keypoints with depth (the default until session 25): the run never started SLAM
// without a config override. The tracker needs 30 local-map inliers, so 150 points with depth
// leave it a fivefold margin.
#include <gtest/gtest.h>

#include <string>

#include "io/json_io.hpp"
#include "keyframe_gap.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// Simulates `frames` frames of the hall and runs them with the built-in configuration; returns
/// the run's folder (empty when a command failed, with its output in `log`).
fs::path runTheHall(int frames, const std::string& tag, std::string& log) {
  const fs::path seq = test::scratchDir(tag + "_seq");
  if (test::runCli("simulate --scenario approach --frames " + std::to_string(frames) + " --out " +
                       seq.string(),
                   &log) != 0)
    return {};
  const fs::path out = test::scratchDir(tag + "_out");
  if (test::runCli("run " + seq.string() + " --out " + out.string() +
                       " --dynamic off --deterministic --quiet",
                   &log) != 0)
    return {};
  return out;
}

TEST(InitialisationSim, AHallBeyondTheDepthRangeStartsAtItsFirstFrame) {
  std::string log;
  const fs::path out = runTheHall(12, "init_hall", log);
  ASSERT_FALSE(out.empty()) << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["tracked"].get<int>(), 12) << stats.dump();
  EXPECT_EQ(stats["lost"].get<int>(), 0);
}

// Without a vocabulary too (no loop closing): local bundle adjustment alone moved keyframes by
// up to 1 cm on 60 frames of this walk, and their own frames were written where they had been.
TEST(InitialisationSim, AKeyframesFrameIsWrittenAtItsKeyframesFinalPose) {
  std::string log;
  const fs::path out = runTheHall(60, "anchor_hall", log);
  ASSERT_FALSE(out.empty()) << log;
  EXPECT_LT(test::keyframeFrameGap(out), 1e-6);
}

}  // namespace
}  // namespace dynanav
