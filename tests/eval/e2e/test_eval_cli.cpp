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
  // --errors: one CSV line per matched pose after the header.
  ASSERT_EQ(test::runCli("eval --gt " + gt.string() + " --est " + est.string() + " --errors " +
                             (dir / "errors.csv").string(),
                         &out),
            0)
      << out;
  std::ifstream csv(dir / "errors.csv");
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "stamp_s,ate_error_m");
  int lines = 0;
  while (std::getline(csv, line)) {
    ++lines;
    EXPECT_NEAR(std::stod(line.substr(line.find(',') + 1)), 0.002, 5e-4) << line;
  }
  EXPECT_EQ(lines, 120);
  // An output path in a folder that does not exist: exit 2 naming it.
  EXPECT_EQ(test::runCli("eval --gt " + gt.string() + " --est " + est.string() + " --errors " +
                             (dir / "missing" / "errors.csv").string(),
                         &out),
            2);
  EXPECT_NE(out.find("missing"), std::string::npos) << out;
}

TEST(EvalCli, BadInputExitsTwoNamingTheFile) {
  const fs::path dir = test::scratchDir("evalbad");
  const auto gt = writeCircle(dir, "gt.txt", 0.0);
  std::string out;
  EXPECT_EQ(
      test::runCli("eval --gt " + gt.string() + " --est " + (dir / "missing.txt").string(), &out),
      2);
  EXPECT_NE(out.find("missing.txt"), std::string::npos) << out;
  std::ofstream(dir / "broken.txt") << "1 2 3\n";
  EXPECT_EQ(
      test::runCli("eval --gt " + gt.string() + " --est " + (dir / "broken.txt").string(), &out),
      2);
  EXPECT_NE(out.find("broken.txt:1"), std::string::npos) << out;
  EXPECT_EQ(test::runCli("eval --gt " + gt.string(), &out), 2);  // --est is required
  EXPECT_EQ(test::runCli("no-such-command", &out), 2);
}

TEST(EvalCli, StatsScoresMovingFlagsOrSaysWhyNot) {
  // A short simulated push: the masks run has moving flags to score, the --dynamic off run has
  // none, and a run over fewer frames than the sequence does not line up with its ground truth.
  const fs::path seq = test::scratchDir("evalstats_seq");
  const fs::path on = test::scratchDir("evalstats_on");
  const fs::path off = test::scratchDir("evalstats_off");
  const fs::path part = test::scratchDir("evalstats_part");
  std::string out;
  ASSERT_EQ(test::runCli("simulate --scenario pushed-box --frames 20 --out " + seq.string(), &out),
            0)
      << out;
  ASSERT_EQ(
      test::runCli("run " + seq.string() + " --out " + on.string() + " --segmenter masks --quiet",
                   &out),
      0)
      << out;
  ASSERT_EQ(test::runCli(
                "run " + seq.string() + " --out " + off.string() + " --dynamic off --quiet", &out),
            0)
      << out;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + part.string() +
                             " --segmenter masks --max-frames 10 --quiet",
                         &out),
            0)
      << out;
  const std::string base =
      "eval --gt " + (seq / "groundtruth.txt").string() + " --sequence " + seq.string();
  auto evalRun = [&](const fs::path& run, const std::string& extra) {
    return test::runCli(base + " --est " + (run / "trajectory.txt").string() + " --stats " +
                            (run / "stats.json").string() + extra,
                        &out);
  };
  ASSERT_EQ(evalRun(on, " --json"), 0) << out;
  const auto json = nlohmann::json::parse(out.substr(out.find('{')));
  ASSERT_EQ(json["moving_flags"].size(), 2u);  // the person and the box
  for (const auto& f : json["moving_flags"]) {
    const int scored = f["true_positive"].get<int>() + f["false_positive"].get<int>() +
                       f["false_negative"].get<int>() + f["true_negative"].get<int>();
    EXPECT_EQ(scored + f["out_of_view"].get<int>(), 20) << f.dump();
  }
  ASSERT_EQ(evalRun(on, ""), 0) << out;
  EXPECT_NE(out.find("moving flag  box 2:"), std::string::npos) << out;
  EXPECT_EQ(evalRun(off, ""), 2);
  EXPECT_NE(out.find("--dynamic off"), std::string::npos) << out;
  EXPECT_EQ(evalRun(part, ""), 2);
  EXPECT_NE(out.find("10 frames of moving flags but 20"), std::string::npos) << out;
  EXPECT_EQ(test::runCli("eval --gt " + (seq / "groundtruth.txt").string() + " --est " +
                             (on / "trajectory.txt").string() + " --stats " +
                             (on / "stats.json").string(),
                         &out),
            2);  // needs --sequence
  EXPECT_NE(out.find("--sequence"), std::string::npos) << out;
}
