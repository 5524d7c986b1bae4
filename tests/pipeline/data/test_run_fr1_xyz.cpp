// Whole runs on the real fr1_xyz sequence: accuracy, coverage, outputs, determinism.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

using test::ateRmse;  // ATE RMSE as `dynanav eval --json` prints it

TEST(RunFr1Xyz, TracksEveryFrameAccurately) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  const fs::path out = test::scratchDir("run_fr1_xyz");
  std::string log;
  const int code = test::runCli(
      "run " + seq.string() + " --out " + out.string() + " --dynamic off --quiet", &log);
  ASSERT_EQ(code, 0) << log;
  for (const char* name : {"trajectory.txt", "keyframes.txt", "stats.json", "config_used.yaml"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["frames"], 244);
  EXPECT_EQ(stats["tracked"], 244);
  EXPECT_EQ(stats["lost"], 0);
  EXPECT_GT(stats["keyframes"].get<int>(), 3);
  for (const char* stage : {"extraction", "tracking", "local_map", "local_ba"})
    EXPECT_TRUE(stats["stage_ms"].contains(stage)) << stage;
  const auto est = readTrajectory(out / "trajectory.txt");
  ASSERT_EQ(est.size(), 244u);
  // ORB-SLAM2 gets 0.0102 m here, the issue asks <= 0.0095; we measure 0.0053 (docs/slam.md).
  // The margin absorbs small algorithm changes but not a broken tracker or a lost rolling-shutter
  // re-timing (0.0103 without it).
  EXPECT_LT(ateRmse(seq / "groundtruth.txt", out / "trajectory.txt"), 0.0085);
  const auto keyframes = readTrajectory(out / "keyframes.txt");
  EXPECT_EQ(static_cast<int>(keyframes.size()), stats["keyframes"].get<int>());
}

TEST(RunFr1Xyz, RollingShutterRetimingIsWhatMakesItAccurate) {
  // fr1's built-in camera has a 25 ms readout; a config of 0 treats it as a global shutter.
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  const fs::path out = test::scratchDir("run_fr1_xyz_global_shutter");
  const fs::path config = out / "global_shutter.yaml";
  std::ofstream(config) << "tracking:\n  rolling_shutter_readout_ms: 0\n";
  std::string log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() + " --config " +
                             config.string() + " --dynamic off --quiet",
                         &log),
            0)
      << log;
  EXPECT_GT(ateRmse(seq / "groundtruth.txt", out / "trajectory.txt"), 0.0095);
  EXPECT_NE(test::readFile(out / "config_used.yaml").find("rolling_shutter_readout_ms: 0"),
            std::string::npos);
}

TEST(RunFr1Xyz, DeterministicModeIsBitIdentical) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  std::string first_trajectory, first_keyframes;
  for (int run = 0; run < 2; ++run) {
    const fs::path out = test::scratchDir("determinism_" + std::to_string(run));
    std::string log;
    ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                               " --deterministic --max-frames 90 --dynamic off --quiet",
                           &log),
              0)
        << log;
    const std::string trajectory = test::readFile(out / "trajectory.txt");
    const std::string keyframes = test::readFile(out / "keyframes.txt");
    ASSERT_FALSE(trajectory.empty());
    if (run == 0) {
      first_trajectory = trajectory;
      first_keyframes = keyframes;
    } else {
      EXPECT_EQ(trajectory, first_trajectory);
      EXPECT_EQ(keyframes, first_keyframes);
    }
  }
}

// Threaded mode as fast as frames are processed (--unpaced: nothing dropped, whatever the load).
// Paced real time, which drops frames when the machine is behind, is scripts/realtime_results.sh.
TEST(RunFr1Xyz, ThreadedModeTracksEveryFrame) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  const fs::path out = test::scratchDir("run_fr1_xyz_realtime");
  std::string log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --realtime --unpaced --dynamic off --quiet",
                         &log),
            0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["tracked"], 244);
  EXPECT_LT(ateRmse(seq / "groundtruth.txt", out / "trajectory.txt"), 0.02);
}

TEST(RunFr1Xyz, BlackoutIsLostThenRecovered) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  const fs::path out = test::scratchDir("run_fr1_xyz_blackout");
  std::string log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --blackout 40:49 --max-frames 80 --dynamic off --quiet",
                         &log),
            0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["frames"], 80);
  EXPECT_GE(stats["lost"].get<int>(), 10);  // every black frame is lost, none is faked
  EXPECT_EQ(stats["tracked"].get<int>() + stats["lost"].get<int>(), 80);
  EXPECT_GT(stats["tracked"].get<int>(), 60) << "tracking resumes after the blackout";
  EXPECT_EQ(readTrajectory(out / "trajectory.txt").size(), stats["tracked"].get<size_t>());
}

}  // namespace
}  // namespace dynanav

namespace dynanav {
namespace {
TEST(RunFr1Xyz, NeverInitialisedExitsWithThree) {
  DYNANAV_REQUIRE_SEQUENCE(seq, "rgbd_dataset_freiburg1_xyz");
  const std::filesystem::path out = test::scratchDir("run_never_init");
  std::string log;
  EXPECT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --blackout 0:9 --max-frames 10 --dynamic off --quiet",
                         &log),
            3)
      << log;
}
}  // namespace
}  // namespace dynanav
