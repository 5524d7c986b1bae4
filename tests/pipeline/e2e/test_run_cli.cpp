// `dynanav run` on bad input: clear messages and the documented exit codes (no data needed).
#include <gtest/gtest.h>

#include <fstream>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

TEST(RunCli, MissingSequenceIsBadInput) {
  const fs::path out = test::scratchDir("run_missing");
  std::string log;
  EXPECT_EQ(
      test::runCli("run /nonexistent/rgbd_dataset_freiburg1_none --out " + out.string(), &log), 2);
  EXPECT_NE(log.find("nonexistent"), std::string::npos) << log;
}

TEST(RunCli, UnknownFlagIsBadInput) {
  std::string log;
  EXPECT_EQ(test::runCli("run . --out /tmp/x --no-such-flag", &log), 2) << log;
}

TEST(RunCli, MalformedBlackoutIsBadInput) {
  const fs::path out = test::scratchDir("run_blackout_bad");
  std::string log;
  EXPECT_EQ(test::runCli("run . --out " + out.string() + " --blackout 9:3", &log), 2);
  EXPECT_NE(log.find("--blackout"), std::string::npos) << log;
}

TEST(RunCli, UnknownConfigKeyIsBadInput) {
  const fs::path dir = test::scratchDir("run_bad_config");
  std::ofstream(dir / "bad.yaml") << "tracking:\n  no_such_key: 3\n";
  std::string log;
  EXPECT_EQ(test::runCli("run . --out " + (dir / "out").string() + " --config " +
                             (dir / "bad.yaml").string(),
                         &log),
            2);
  EXPECT_NE(log.find("no_such_key"), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
