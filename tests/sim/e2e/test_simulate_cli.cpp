// `dynanav simulate` end to end: the files, their formats, byte-for-byte reproducibility, bad
// input, and a short simulate -> run -> eval chain.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "io/camera_yaml.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using dynanav::test::readFile;
using dynanav::test::runCli;
using dynanav::test::scratchDir;

namespace dynanav {
namespace {

std::vector<std::string> dataLines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

/// Every file under dir (relative path -> contents).
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = readFile(e.path());
  return files;
}

TEST(SimulateCli, WritesATumSequenceWithGroundTruth) {
  const fs::path out = scratchDir("sim") / "crossing";
  std::string log;
  ASSERT_EQ(
      runCli("simulate --scenario crossing --out " + out.string() + " --frames 40 --seed 3", &log),
      0)
      << log;

  const auto rgb = dataLines(out / "rgb.txt"), depth = dataLines(out / "depth.txt");
  ASSERT_EQ(rgb.size(), 40u);
  ASSERT_EQ(depth.size(), 40u);
  EXPECT_EQ(readFile(out / "rgb.txt").rfind("# color images", 0), 0u);
  EXPECT_EQ(rgb[0], "0.000000 rgb/0.000000.png");
  EXPECT_EQ(depth[1], "0.033333 depth/0.033333.png");

  const auto gt = readTrajectory(out / "groundtruth.txt");
  ASSERT_EQ(gt.size(), 40u);
  EXPECT_TRUE(gt[0].T_world_camera.isApprox(SE3::Identity(), 1e-12))
      << "world = first camera frame";
  EXPECT_GT(gt.back().T_world_camera.translation().z(), 0.2)
      << "the wearer walks forward (camera z)";

  const PinholeCamera cam = loadCameraYaml(out / "camera.yaml");
  EXPECT_EQ(cam.width, 640);
  EXPECT_EQ(cam.height, 480);
  EXPECT_FALSE(cam.isDistorted());
  EXPECT_DOUBLE_EQ(cam.depth_factor, 5000.0);

  const auto masks = readJsonFile(out / "masks.json");
  EXPECT_EQ(masks["instances"]["1"]["class"], "person");

  const auto objects = readJsonLines(out / "objects_gt.jsonl");
  ASSERT_EQ(objects.size(), 40u);
  EXPECT_DOUBLE_EQ(objects[1]["t"].get<double>(), 0.033333);
  const auto& o = objects[39]["objects"][0];
  for (const char* key : {"id", "class", "dynamic", "position_world", "position_camera", "distance",
                          "bearing_deg", "clock", "velocity_world", "speed", "points", "in_view"})
    EXPECT_TRUE(o.contains(key)) << key;

  // Images: 8-bit colour, 16-bit depth and masks, same size; mask ids are the listed instances,
  // and `points` counts the labelled pixels.
  const cv::Mat colour = cv::imread((out / "rgb/1.300000.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat raw_depth = cv::imread((out / "depth/1.300000.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat mask = cv::imread((out / "masks/1.300000.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(colour.type(), CV_8UC3);
  ASSERT_EQ(raw_depth.type(), CV_16UC1);
  ASSERT_EQ(mask.type(), CV_16UC1);
  EXPECT_EQ(mask.size(), colour.size());
  double max_id = 0;
  cv::minMaxLoc(mask, nullptr, &max_id);
  EXPECT_LE(max_id, 1.0);
  EXPECT_EQ(cv::countNonZero(mask == 1), objects[39]["objects"][0]["points"].get<int>());

  // The project's own reader takes it as it is.
  const auto seq = TumSequence::open(out, IoConfig{});
  EXPECT_EQ(seq.size(), 40u);
  EXPECT_EQ(seq.cameraSource(), "camera.yaml");
  const RgbdFrame frame = seq.load(20);
  EXPECT_GT(cv::countNonZero(frame.depth_m > 0), 640 * 480 / 4);
}

TEST(SimulateCli, SameSeedSameBytes) {
  const fs::path dir = scratchDir("sim");
  for (const char* run : {"a", "b"})
    ASSERT_EQ(
        runCli("simulate --scenario office --frames 8 --seed 11 --out " + (dir / run).string()), 0);
  ASSERT_EQ(runCli("simulate --scenario office --frames 8 --seed 12 --out " + (dir / "c").string()),
            0);
  const auto a = snapshot(dir / "a"), b = snapshot(dir / "b"), c = snapshot(dir / "c");
  ASSERT_EQ(a.size(), 8u * 3u + 6u) << "3 images per frame, 4 lists, camera.yaml, masks.json";
  EXPECT_TRUE(a == b) << "a seed must reproduce every file byte for byte";
  EXPECT_NE(a.at("rgb/0.100000.png"), c.at("rgb/0.100000.png"));
  EXPECT_NE(a.at("depth/0.100000.png"), c.at("depth/0.100000.png"));
  EXPECT_EQ(a.at("groundtruth.txt"), c.at("groundtruth.txt"))
      << "the choreography does not depend on the seed";
}

TEST(SimulateCli, ListsScenarios) {
  std::string out;
  ASSERT_EQ(runCli("simulate --list", &out), 0);
  for (const char* name :
       {"static-room", "approach", "crossing", "crossing-near", "parallel", "walking-away",
        "office", "office-ramped", "pushed-box", "loop", "standing"})
    EXPECT_NE(out.find(name), std::string::npos) << name;
  ASSERT_EQ(runCli("simulate --help", &out), 0);
  EXPECT_NE(out.find("pushed-box"), std::string::npos) << "the help names the scenarios";
}

TEST(SimulateCli, BadInputExitsWithCodeTwoAndSaysWhy) {
  const fs::path dir = scratchDir("sim");
  std::string out;
  EXPECT_EQ(runCli("simulate --scenario offfice --out " + (dir / "x").string(), &out), 2);
  EXPECT_NE(out.find("unknown scenario 'offfice'"), std::string::npos) << out;
  EXPECT_NE(out.find("office"), std::string::npos) << out;
  EXPECT_EQ(runCli("simulate --scenario office", &out), 2) << "no --out";
  EXPECT_NE(out.find("--out"), std::string::npos) << out;
  EXPECT_EQ(runCli("simulate --out " + (dir / "y").string(), &out), 2) << "no --scenario";
  EXPECT_EQ(runCli("simulate --scenario office --fps 0 --out " + (dir / "z").string(), &out), 2);
  EXPECT_EQ(runCli("simulate --scenario office --frames -3 --out " + (dir / "z").string(), &out),
            2);
  EXPECT_EQ(runCli("simulate --scenario office --frames ten --out " + (dir / "z").string(), &out),
            2);
  EXPECT_EQ(
      runCli("simulate --scenario office --rolling-shutter-ms 40 --out " + (dir / "r").string(),
             &out),
      2);
  EXPECT_NE(out.find("frame period"), std::string::npos) << out;  // 40 ms > 33 ms at 30 fps
  EXPECT_EQ(
      runCli("simulate --scenario office --rolling-shutter-ms -1 --out " + (dir / "r").string(),
             &out),
      2);
  EXPECT_FALSE(fs::exists(dir / "r")) << "nothing written for a bad readout";
  EXPECT_EQ(
      runCli("simulate --scenario head-turns --exposure-ms 40 --out " + (dir / "e").string(), &out),
      2);
  EXPECT_NE(out.find("frame period"), std::string::npos) << out;  // 40 ms > 33 ms at 30 fps
  EXPECT_FALSE(fs::exists(dir / "e")) << "nothing written for a bad exposure";
  EXPECT_FALSE(fs::exists(dir / "x")) << "nothing written for a bad scenario";
}

/// DESIGN.md §6: simulate + run + eval on a short scene in every CI run. Until `dynanav run`
/// exists this skips with a message; then it checks tracking and accuracy on static-room.
TEST(SimulateCli, ShortStaticRoomThroughRunAndEval) {
  const fs::path dir = scratchDir("sim");
  const fs::path seq = dir / "static-room";
  ASSERT_EQ(runCli("simulate --scenario static-room --frames 150 --out " + seq.string()), 0);
  std::string log;
  const int code =
      runCli("run " + seq.string() + " --out " + (dir / "run").string() + " --deterministic", &log);
  if (log.find("not built yet") != std::string::npos)
    GTEST_SKIP() << "'dynanav run' is not built yet: " << log;
  ASSERT_EQ(code, 0) << log;
  std::string eval;
  ASSERT_EQ(runCli("eval --json --gt " + (seq / "groundtruth.txt").string() + " --est " +
                       (dir / "run" / "trajectory.txt").string() + " --sequence " + seq.string(),
                   &eval),
            0)
      << eval;
  const auto result = nlohmann::json::parse(eval.substr(eval.find('{')));
  EXPECT_EQ(result["coverage"]["tracked_frames"], 150) << "every frame tracked";
  EXPECT_LE(result["ate_m"]["rmse"].get<double>(), 0.005) << "issue 5: ATE <= 5 mm on static-room";
}

/// A rolling-shutter camera, simulated with the truth in camera.yaml: SLAM's re-timing must use
/// it and win back most of what the shear costs (docs/slam.md: 0.0050 m with it, 0.0099 m
/// treated as a global shutter, 0.0038 m for the same walk seen by a global shutter).
TEST(SimulateCli, RollingShutterWalkIsTrackedWithTheReadoutFromCameraYaml) {
  const fs::path dir = scratchDir("sim_rolling");
  const fs::path seq = dir / "static-room";
  ASSERT_EQ(runCli("simulate --scenario static-room --frames 150 --rolling-shutter-ms 25 --out " +
                   seq.string()),
            0);
  EXPECT_NE(readFile(seq / "camera.yaml").find("rolling_shutter_readout_ms: 25"),
            std::string::npos);
  std::ofstream(dir / "global.yaml") << "tracking:\n  rolling_shutter_readout_ms: 0\n";
  double ate[2] = {0.0, 0.0};
  for (int global = 0; global < 2; ++global) {
    const fs::path out = dir / (global ? "run_global" : "run");
    std::string log;
    ASSERT_EQ(runCli("run " + seq.string() + " --out " + out.string() + " --deterministic --quiet" +
                         (global ? " --config " + (dir / "global.yaml").string() : ""),
                     &log),
              0)
        << log;
    ate[global] = test::ateRmse(seq / "groundtruth.txt", out / "trajectory.txt");
  }
  EXPECT_LT(ate[0], 0.007);
  EXPECT_GT(ate[1], 1.5 * ate[0]) << "re-timed " << ate[0] << ", as global shutter " << ate[1];
}

/// Issue 18: the fast head turns (150 deg/s) seen through a 25 ms rolling shutter with a 10 ms
/// exposure (motion blur) in a static room, half the scene (5 s: the first 60-degree turn, two
/// nods and most of the 120-degree sweep). SLAM must track every frame with the readout from
/// camera.yaml, and with geometry-only dynamics flag only a small share of the (all static)
/// keypoints (docs/dynamics.md has the whole scene's figures).
// Measured (2026-12-02): ATE 0.0102 m, 250 of 149988 keypoints flagged (0.17 %); (2026-12-08,
// the motion blur modelled: docs/slam.md): 0.0091 m, 8 of 149989 (0.005 %), readout 25.1 ms.
constexpr double kHeadTurnAteBoundM = 0.015;
constexpr double kHeadTurnFlaggedShareBound = 0.005;  // issue 18's target: < 1 %
constexpr double kReadoutAtTruthToleranceMs = 2.0;    // issue 18's target: within 3 ms

TEST(SimulateCli, FastHeadTurnsWithBlurAndRollingShutterAreTracked) {
  const fs::path dir = scratchDir("sim_head_turns");
  const fs::path seq = dir / "head-turns";
  ASSERT_EQ(runCli("simulate --scenario head-turns --frames 150 --rolling-shutter-ms 25 "
                   "--exposure-ms 10 --out " +
                   seq.string()),
            0);
  std::string log;
  const int code = runCli("run " + seq.string() + " --out " + (dir / "run").string() +
                              " --deterministic --quiet --segmenter none",
                          &log);
  if (log.find("not built yet") != std::string::npos)
    GTEST_SKIP() << "'dynanav run' is not built yet: " << log;
  ASSERT_EQ(code, 0) << log;
  EXPECT_EQ(readTrajectory(dir / "run" / "trajectory.txt").size(), 150u) << "every frame tracked";
  EXPECT_LT(test::ateRmse(seq / "groundtruth.txt", dir / "run" / "trajectory.txt"),
            kHeadTurnAteBoundM);
  const auto stats = nlohmann::json::parse(readFile(dir / "run" / "stats.json"));
  double flagged = 0, kept = 0;
  for (const auto& v : stats["dynamics"]["per_frame"]["dynamic_keypoints"])
    flagged += v.get<double>();
  for (const auto& v : stats["dynamics"]["per_frame"]["static_keypoints"]) kept += v.get<double>();
  EXPECT_GT(kept, 0.0);
  EXPECT_LT(flagged / (flagged + kept), kHeadTurnFlaggedShareBound) << "nothing moves here";
  // The online readout estimate, gathered while re-timing with the true 25 ms, stays there (it
  // is unbiased at the truth: slam/readout_estimate.hpp).
  const auto& readout = stats["rolling_shutter"];
  ASSERT_TRUE(readout["estimate_ms"].is_number()) << readout.dump();
  EXPECT_NEAR(readout["estimate_ms"].get<double>(), 25.0, kReadoutAtTruthToleranceMs)
      << readout.dump();
  EXPECT_EQ(readout["configured_ms"].get<double>(), 25.0);
}

}  // namespace
}  // namespace dynanav
