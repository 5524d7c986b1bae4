// Issue 18: the readout estimated online lands within 3 ms of the simulator's true readout. The
// keypoints start re-timed with 0 (a camera whose readout is not known); bundle adjustment
// estimates it with the map (slam/readout_shear.hpp) once the head turns.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/json_io.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

TEST(ReadoutOnlineSim, HeadTurnsGiveBackTheTrueReadoutFromZero) {
  std::string log;
  const fs::path seq = test::scratchDir("readout_online_seq");
  ASSERT_EQ(
      test::runCli("simulate --scenario head-turns --seed 1 --frames 90 --rolling-shutter-ms 25 "
                   "--exposure-ms 10 --out " +
                       seq.string(),
                   &log),
      0)
      << log;
  const fs::path out = test::scratchDir("readout_online_out");
  const fs::path config = out / "online.yaml";
  std::ofstream(config)
      << "tracking:\n  rolling_shutter_readout_ms: 0\n  rolling_shutter_online: true\n";
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + (out / "run").string() +
                             " --dynamic off --deterministic --quiet --config " + config.string(),
                         &log),
            0)
      << log;
  const auto shutter = readJsonFile(out / "run" / "stats.json")["rolling_shutter"];
  ASSERT_FALSE(shutter["online_stages"].empty()) << shutter.dump();
  ASSERT_TRUE(shutter["online_readout_ms"].is_number()) << shutter.dump();
  EXPECT_NEAR(shutter["online_readout_ms"].get<double>(), 25.0, 3.0) << shutter.dump();
}

}  // namespace
}  // namespace dynanav
