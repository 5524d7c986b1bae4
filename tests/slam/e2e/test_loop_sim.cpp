// Issue 4's loop test on the simulator: the wearer walks the ~21 m `loop` scenario (10 frames/s to
// keep the test short) and comes back to the start. With loop closing the loop must be found and
// the end-point drift (last pose vs ground truth, no alignment: the simulator's first pose is the
// identity, as ours) must be at least 5x smaller than without it. Skipped without a vocabulary.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "io/trajectory.hpp"
#include "keyframe_gap.hpp"
#include "slam/vocabulary/vocabulary_path.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

double endDrift(const fs::path& gt_path, const fs::path& est_path) {
  const auto gt = readTrajectory(gt_path);
  const auto est = readTrajectory(est_path);
  if (gt.empty() || est.empty()) return 1e9;
  const StampedPose& last = est.back();
  const auto nearest = std::min_element(gt.begin(), gt.end(), [&](const auto& a, const auto& b) {
    return std::abs(a.stamp_s - last.stamp_s) < std::abs(b.stamp_s - last.stamp_s);
  });
  return (nearest->T_world_camera.translation() - last.T_world_camera.translation()).norm();
}

TEST(LoopSim, LoopIsClosedAndEndDriftShrinksFiveTimes) {
  try {
    findVocabulary();
  } catch (const std::exception& e) {
    GTEST_SKIP() << e.what();
  }
  const fs::path seq = test::scratchDir("loop_sim_seq");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario loop --fps 10 --out " + seq.string(), &log), 0)
      << log;
  const fs::path config = test::scratchDir("loop_sim_cfg") / "loop_off.yaml";
  std::ofstream(config) << "loop:\n  loop_closing: false\n";
  const fs::path on = test::scratchDir("loop_sim_on"), off = test::scratchDir("loop_sim_off");
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + on.string() + " --quiet", &log), 0)
      << log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + off.string() + " --config " +
                             config.string() + " --quiet",
                         &log),
            0)
      << log;
  const auto stats_on = readJsonFile(on / "stats.json");
  const auto stats_off = readJsonFile(off / "stats.json");
  EXPECT_EQ(stats_off["loops"], 0);
  EXPECT_EQ(stats_on["place_recognition"]["on"], true);
  EXPECT_EQ(stats_on["place_recognition"]["off_reason"], "");
  ASSERT_GE(stats_on["loops"].get<int>(), 1) << "the loop is detected";
  // The loop closes when the wearer is back near the start (the last ~15 % of the walk).
  const int frames = stats_on["frames"].get<int>();
  EXPECT_GT(stats_on["loop_frames"][0].get<int>(), frames * 3 / 4)
      << stats_on["loop_details"].dump();
  EXPECT_LT(stats_on["loop_details"][0]["loop_frame"].get<int>(), frames / 4);
  const double drift_on = endDrift(seq / "groundtruth.txt", on / "trajectory.txt");
  const double drift_off = endDrift(seq / "groundtruth.txt", off / "trajectory.txt");
  std::printf("loop sim: end drift %.4f m without loop closing, %.4f m with (%.1fx)\n", drift_off,
              drift_on, drift_off / drift_on);
  EXPECT_LE(drift_on * 5.0, drift_off);
  // Written with 9 decimals: a keyframe's frame is where its keyframe ended, loop or not.
  EXPECT_LT(test::keyframeFrameGap(on), 1e-6);
  EXPECT_LT(test::keyframeFrameGap(off), 1e-6);
}

TEST(LoopSim, MissingVocabularyDisablesPlaceRecognitionWithOneWarningAndInStats) {
  const fs::path seq = test::scratchDir("loop_novoc_seq");
  std::string log;
  ASSERT_EQ(test::runCli(
                "simulate --scenario static-room --frames 12 --fps 10 --out " + seq.string(), &log),
            0)
      << log;
  const fs::path config = test::scratchDir("loop_novoc_cfg") / "novoc.yaml";
  std::ofstream(config) << "loop:\n  vocabulary: " << (seq / "missing.dnvoc").string() << "\n";
  const fs::path out = test::scratchDir("loop_novoc_out");
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() + " --config " +
                             config.string() + " --quiet",
                         &log),
            0)
      << log;
  const std::string warning = "relocalisation and loop closing disabled";
  const auto first = log.find(warning);
  ASSERT_NE(first, std::string::npos) << log;
  EXPECT_EQ(log.find(warning, first + 1), std::string::npos) << "said once";
  EXPECT_NE(log.find("missing.dnvoc"), std::string::npos) << "names the file";
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["loops"], 0);
  EXPECT_EQ(stats["place_recognition"]["on"], false) << "stats.json says so too";
  EXPECT_NE(stats["place_recognition"]["off_reason"].get<std::string>().find("missing.dnvoc"),
            std::string::npos);
}

}  // namespace
}  // namespace dynanav
