// `dynanav run --passes N` (the long-run test's source): the sequence plays N times, alternately
// forward and backward, with time running on; SLAM keeps tracking through the turns; memory is
// sampled.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

TEST(PassesCli, ThreePassesTrackOnWithIncreasingTime) {
  const fs::path dir = test::scratchDir("passes_cli");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario static-room --out " + (dir / "seq").string() +
                             " --frames 40 --seed 1",
                         &log),
            0)
      << log;
  ASSERT_EQ(test::runCli("run " + (dir / "seq").string() + " --out " + (dir / "out").string() +
                             " --dynamic off --deterministic --passes 3 --quiet",
                         &log),
            0)
      << log;
  const auto stats = nlohmann::json::parse(test::readFile(dir / "out" / "stats.json"));
  EXPECT_EQ(stats["frames"], 120);
  EXPECT_GE(stats["tracked"].get<int>(), 110) << "tracking should go on through each turn";
  EXPECT_GE(stats["rss_mb"].size(), 2u);
  std::istringstream lines(test::readFile(dir / "out" / "trajectory_online.txt"));
  double last = -1.0;
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    const double stamp = std::stod(line);
    EXPECT_GT(stamp, last);
    last = stamp;
    ++rows;
  }
  EXPECT_EQ(rows, stats["tracked"].get<int>());
}

TEST(PassesCli, ZeroPassesIsBadInput) {
  std::string log;
  EXPECT_EQ(test::runCli("run . --out /tmp/x --passes 0", &log), 2);
  EXPECT_NE(log.find("--passes"), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
