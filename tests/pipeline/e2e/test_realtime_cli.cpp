// `dynanav run --realtime` end to end on a short simulated scene: paced like a camera, every
// frame accounted for (processed or dropped), latency and drops in stats.json; --unpaced drops
// nothing; --unpaced alone is bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

class RealtimeCli : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { test::removeScratchDir(dir_); }
  static void SetUpTestSuite() {
    dir_ = test::scratchDir("realtime_cli_" +
                            std::to_string(getpid()));  // one per test process (ctest -j)
    std::string log;
    ASSERT_EQ(test::runCli("simulate --scenario office --out " + (dir_ / "seq").string() +
                               " --frames 60 --seed 1",
                           &log),
              0)
        << log;
  }
  static nlohmann::json run(const std::string& name, const std::string& flags) {
    std::string log;
    const fs::path out = dir_ / name;
    EXPECT_EQ(test::runCli("run " + (dir_ / "seq").string() + " --out " + out.string() +
                               " --segmenter masks " + flags + " --quiet",
                           &log),
              0)
        << log;
    return nlohmann::json::parse(test::readFile(out / "stats.json"));
  }
  static fs::path dir_;
};
fs::path RealtimeCli::dir_;

TEST_F(RealtimeCli, PacedRunAccountsForEveryFrame) {
  const auto stats = run("paced", "--realtime");
  EXPECT_EQ(stats["mode"], "realtime");
  const int frames = stats["frames"];
  const int dropped = stats["dropped"];
  EXPECT_EQ(frames + dropped, 60);
  EXPECT_GT(frames, 0);
  EXPECT_GT(stats["tracked"].get<int>(), 0);
  EXPECT_GT(stats["latency_ms"]["p95"].get<double>(), 0.0);
  EXPECT_TRUE(stats["stage_ms"].contains("tracking"));
  EXPECT_TRUE(
      stats["stage_ms"].contains("segmenter_thread"));  // segmentation ran in its own thread
  // Paced at the simulator's 30 Hz: the run cannot be much shorter than the 2 s of camera time.
  EXPECT_GT(stats["wall_s"].get<double>(), 1.8);
  EXPECT_FALSE(test::readFile(dir_ / "paced" / "trajectory.txt").empty());
}

TEST_F(RealtimeCli, UnpacedRunDropsNothing) {
  const auto stats = run("unpaced", "--realtime --unpaced");
  EXPECT_EQ(stats["mode"], "realtime-unpaced");
  EXPECT_EQ(stats["frames"], 60);
  EXPECT_EQ(stats["dropped"], 0);
}

TEST_F(RealtimeCli, UnpacedNeedsRealtime) {
  std::string log;
  EXPECT_EQ(test::runCli("run " + (dir_ / "seq").string() + " --out " + (dir_ / "bad").string() +
                             " --unpaced",
                         &log),
            2);
  EXPECT_NE(log.find("--unpaced"), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
