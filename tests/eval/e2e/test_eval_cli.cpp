// `dynanav eval` from the command line: figures, JSON, and exit code 2 with a clear message.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/trajectory.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
namespace fs = std::filesystem;

namespace {
fs::path writeCircle(const fs::path& dir, const std::string& name, double wobble) {
  std::vector<StampedPose> poses;
  for (int i = 0; i < 120; ++i) {
    const double a = i * 0.05;
    Vec3 t(std::cos(a), std::sin(a), 0.1 * a);
    t.z() += (i % 2 ? wobble : -wobble);
    poses.push_back({50.0 + i / 30.0, makeSE3(Quat(Eigen::AngleAxisd(a, Vec3::UnitZ())), t)});
  }
  writeTrajectory(dir / name, poses);
  return dir / name;
}
}  // namespace

TEST(EvalCli, PrintsAteRpeAndCoverage) {
  const fs::path dir = test::scratchDir("evalcli");
  const auto gt = writeCircle(dir, "gt.txt", 0.0);
  const auto est = writeCircle(dir, "est.txt", 0.002);
  std::string out;
  ASSERT_EQ(test::runCli("eval --gt " + gt.string() + " --est " + est.string(), &out), 0) << out;
  EXPECT_NE(out.find("ATE  rmse 0.002"), std::string::npos) << out;
  EXPECT_NE(out.find("RPE"), std::string::npos);
  EXPECT_NE(out.find("coverage"), std::string::npos);
  ASSERT_EQ(test::runCli("eval --json --gt " + gt.string() + " --est " + est.string(), &out), 0);
  const auto json = nlohmann::json::parse(out);
  EXPECT_NEAR(json["ate_m"]["rmse"].get<double>(), 0.002, 2e-4);
  EXPECT_EQ(json["matched_poses"].get<int>(), 120);
}

TEST(EvalCli, BadInputExitsTwoNamingTheFile) {
  const fs::path dir = test::scratchDir("evalbad");
  const auto gt = writeCircle(dir, "gt.txt", 0.0);
  std::string out;
  EXPECT_EQ(test::runCli("eval --gt " + gt.string() + " --est " + (dir / "missing.txt").string(), &out), 2);
  EXPECT_NE(out.find("missing.txt"), std::string::npos) << out;
  std::ofstream(dir / "broken.txt") << "1 2 3\n";
  EXPECT_EQ(test::runCli("eval --gt " + gt.string() + " --est " + (dir / "broken.txt").string(), &out), 2);
  EXPECT_NE(out.find("broken.txt:1"), std::string::npos) << out;
  EXPECT_EQ(test::runCli("eval --gt " + gt.string(), &out), 2);  // --est is required
  EXPECT_EQ(test::runCli("no-such-command", &out), 2);
}
