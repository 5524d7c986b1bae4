// The safety net of the pipeline restructuring (issue 12): --deterministic with dynamics on gives
// bit-identical trajectories and per-frame dynamics, run after run, on simulated scenes with
// people walking (office) and an object pushed (pushed-box).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/videoio.hpp>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// `extra`: more run flags (a config file); `extra_b`: flags of the second run only (outputs
/// that must not change the trajectory); `dir_out`: where the runs are, OUT/a and OUT/b.
void expectReproducible(const std::string& scenario, const std::string& extra = "",
                        const std::string& tag = "", const std::string& extra_b = "",
                        fs::path* dir_out = nullptr) {
  const fs::path dir = test::scratchDir("determinism_" + scenario + tag);
  if (dir_out) *dir_out = dir;
  const fs::path seq = dir / "seq";
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario " + scenario + " --out " + seq.string() +
                             " --frames 90 --seed 2",
                         &log),
            0)
      << log;
  for (const std::string run : {"a", "b"}) {
    ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + (dir / run).string() +
                               " --segmenter masks --deterministic --quiet" + extra +
                               (run == "b" ? extra_b : ""),
                           &log),
              0)
        << log;
  }
  for (const char* file : {"trajectory.txt", "keyframes.txt", "trajectory_online.txt"}) {
    const std::string a = test::readFile(dir / "a" / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, test::readFile(dir / "b" / file))
        << scenario << ": " << file << " differs between runs";
  }
  const auto a = nlohmann::json::parse(test::readFile(dir / "a" / "stats.json"));
  const auto b = nlohmann::json::parse(test::readFile(dir / "b" / "stats.json"));
  EXPECT_EQ(a["dynamics"], b["dynamics"]) << scenario << ": per-frame dynamics differ between runs";
  // The scene has movers, so the comparison covers the dynamic path, not an empty one.
  EXPECT_GT(a["dynamics"]["mean_prior_instances"].get<double>() +
                a["dynamics"]["mean_dynamic_instances"].get<double>(),
            0.0);
}

TEST(Determinism, OfficeWithWalkersIsBitIdentical) {
  expectReproducible("office");
}
TEST(Determinism, PushedBoxIsBitIdentical) {
  expectReproducible("pushed-box");
}
TEST(Determinism, LateMasksReplayIsBitIdentical) {
  // The deterministic replay of real-time segmentation (masks 3 frames late, carried by flow).
  const fs::path config = test::scratchDir("determinism_lag_config") / "lag.yaml";
  std::ofstream(config) << "perception:\n  emulated_lag_frames: 3\n";
  expectReproducible("office", " --config " + config.string(), "_lag3");
}

TEST(Determinism, TheAnnotatedVideoDoesNotChangeTheTrajectory) {
  // The video's worker thread only reads the frames and results (issue 15).
  fs::path dir;
  expectReproducible("office", "", "_video", " --video", &dir);
  const fs::path video = dir / "b" / "annotated.mp4";
  cv::VideoCapture read(video.string());
  ASSERT_TRUE(read.isOpened()) << video;
  int frames = 0;
  for (cv::Mat f; read.read(f);) ++frames;
  EXPECT_EQ(frames, 90);  // every frame, none dropped
}

}  // namespace
}  // namespace dynanav
