// Clean interruption (issue 16): SIGINT or SIGTERM during `dynanav run` ends it with 130 / 143,
// and every output written so far is well-formed — stats.json says "interrupted", the
// trajectory holds whole lines only, keyframes.txt exists, annotated.mp4 plays (issue 15).
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include <unistd.h>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

void expectWellFormedOutputs(const fs::path& out, int max_frames) {
  const auto stats = nlohmann::json::parse(test::readFile(out / "stats.json"));  // throws if cut
  EXPECT_TRUE(stats["interrupted"].get<bool>());
  EXPECT_GT(stats["frames"].get<int>(), 0);
  EXPECT_LT(stats["frames"].get<int>(), max_frames);
  std::istringstream lines(test::readFile(out / "trajectory.txt"));
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double v = 0;
    int n = 0;
    while (fields >> v) ++n;
    EXPECT_EQ(n, 8) << "cut line: " << line;
    ++rows;
  }
  EXPECT_GT(rows, 0);
  EXPECT_TRUE(fs::exists(out / "keyframes.txt"));
  EXPECT_TRUE(fs::exists(out / "trajectory_online.txt"));
}

class InterruptCli : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { test::removeScratchDir(dir_); }
  static void SetUpTestSuite() {
    dir_ = test::scratchDir("interrupt_cli_" +
                            std::to_string(getpid()));  // one per test process (ctest -j)
    std::string log;
    ASSERT_EQ(test::runCli("simulate --scenario office --out " + (dir_ / "seq").string() +
                               " --frames 240 --seed 3",
                           &log),
              0)
        << log;
  }
  static fs::path dir_;
};
fs::path InterruptCli::dir_;

TEST_F(InterruptCli, SigintDuringARealtimeRunLeavesValidOutputs) {
  const fs::path out = dir_ / "sigint";
  // Paced at 30 Hz the 240 frames take 8 s: the signal comes in the middle.
  const int code = test::runAndSignal({"run", (dir_ / "seq").string(), "--out", out.string(),
                                       "--segmenter", "masks", "--realtime", "--quiet"},
                                      SIGINT, std::chrono::milliseconds(3500));
  EXPECT_EQ(code, 130);
  expectWellFormedOutputs(out, 240);
}

TEST_F(InterruptCli, SigtermDuringADeterministicRunLeavesValidOutputs) {
  const fs::path out = dir_ / "sigterm";
  const int code = test::runAndSignal({"run", (dir_ / "seq").string(), "--out", out.string(),
                                       "--segmenter", "masks", "--deterministic", "--quiet"},
                                      SIGTERM, std::chrono::milliseconds(2500));
  EXPECT_EQ(code, 143);
  expectWellFormedOutputs(out, 240);
}

TEST_F(InterruptCli, SigintWithVideoLeavesAPlayableVideoOfEveryFrameRun) {
  const fs::path out = dir_ / "sigint_video";
  const int code = test::runAndSignal({"run", (dir_ / "seq").string(), "--out", out.string(),
                                       "--segmenter", "masks", "--realtime", "--video", "--quiet"},
                                      SIGINT, std::chrono::milliseconds(3500));
  EXPECT_EQ(code, 130);
  expectWellFormedOutputs(out, 240);
  // The mp4's index is written when the video closes; an interrupted run must still close it.
  cv::VideoCapture read((out / "annotated.mp4").string());
  ASSERT_TRUE(read.isOpened());
  int frames = 0;
  for (cv::Mat f; read.read(f);) ++frames;
  const auto stats = nlohmann::json::parse(test::readFile(out / "stats.json"));
  EXPECT_EQ(frames, stats["frames"].get<int>());
}

}  // namespace
}  // namespace dynanav
