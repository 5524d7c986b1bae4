// `dynanav run --passes N` (the long-run test's source): the sequence plays N times, alternately
// forward and backward, with time running on; SLAM keeps tracking through the turns; memory is
// sampled.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "io/sequence.hpp"
#include "io/trajectory.hpp"
#include "pipeline/frame_source.hpp"
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

  // Pose continuity: the passes turn where they ended (no teleport), so the camera holds still
  // over a turn, and the same image later in the run is placed where it was placed before.
  const TumSequence seq = TumSequence::open(dir / "seq", IoConfig{}, std::nullopt);
  const double first_s = seq.pairs().front().rgb.stamp_s, last_s = seq.pairs().back().rgb.stamp_s;
  const double span_s = (last_s - first_s) * 40.0 / 39.0;
  std::map<double, Vec3> position_at;  // by stamp (s), written with 6 decimals
  for (const auto& p : readTrajectory(dir / "out" / "trajectory_online.txt"))
    position_at[p.stamp_s] = p.T_world_camera.translation();
  const auto position = [&](size_t delivered) -> std::optional<Vec3> {
    const PassStep step = passStep(delivered, 40);
    const double stamp =
        passStamp(seq.pairs()[step.index].rgb.stamp_s, step, first_s, last_s, span_s);
    const auto it = position_at.lower_bound(stamp - 2e-6);
    if (it == position_at.end() || it->first > stamp + 2e-6) return std::nullopt;
    return it->second;
  };
  double largest_step_pass1_m = 0.0;
  for (size_t k = 1; k < 40; ++k)
    if (position(k) && position(k - 1))
      largest_step_pass1_m =
          std::max(largest_step_pass1_m, (*position(k) - *position(k - 1)).norm());
  ASSERT_GT(largest_step_pass1_m, 0.0) << "the simulated camera should move";
  int steps_checked = 0, pairs_checked = 0;
  for (size_t k = 40; k < 120; ++k) {
    if (!position(k) || !position(k - 1)) continue;
    ++steps_checked;
    EXPECT_LT((*position(k) - *position(k - 1)).norm(), 1.5 * largest_step_pass1_m + 0.01) << k;
  }
  const std::vector<std::pair<size_t, size_t>> same_image{{39, 40}, {0, 79}, {0, 80}, {39, 119}};
  for (const auto& [a, b] : same_image) {
    if (!position(a) || !position(b)) continue;
    ++pairs_checked;
    EXPECT_LT((*position(a) - *position(b)).norm(), 0.05) << "frames " << a << " and " << b;
  }
  EXPECT_GE(steps_checked, 70);
  EXPECT_GE(pairs_checked, 3);
}

TEST(PassesCli, ZeroPassesIsBadInput) {
  std::string log;
  EXPECT_EQ(test::runCli("run . --out /tmp/x --passes 0", &log), 2);
  EXPECT_NE(log.find("--passes"), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
