// `dynanav segment` end to end on a small synthetic TUM-layout sequence with ground-truth masks.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/camera_yaml.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using namespace dynanav;

namespace {

/// 6 frames 160x120: a textured background at 3 m and a square "person" at 1.5 m moving right
/// by 3 px per frame; masks/ + masks.json hold its ground truth (id 1).
fs::path makeSequence() {
  const fs::path dir = test::scratchDir("segseq");
  for (const char* sub : {"rgb", "depth", "masks"}) fs::create_directories(dir / sub);
  PinholeCamera camera;
  camera.width = 160;
  camera.height = 120;
  camera.cx = 79.5;  // inside the image (camera.yaml's range check)
  camera.cy = 59.5;
  saveCameraYaml(dir / "camera.yaml", camera);
  std::ofstream rgb_list(dir / "rgb.txt"), depth_list(dir / "depth.txt");
  cv::Mat background(120, 160, CV_8UC3);
  cv::RNG rng(7);
  rng.fill(background, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(background, background, cv::Size(0, 0), 1.5);
  for (int f = 0; f < 6; ++f) {
    const std::string stamp = cv::format("100.%02d", 10 + 3 * f);
    const cv::Rect person(30 + 3 * f, 30, 30, 60);
    cv::Mat bgr = background.clone();
    cv::Mat patch(person.size(), CV_8UC3);
    rng.fill(patch, cv::RNG::UNIFORM, 0, 255);
    patch.copyTo(bgr(person));
    cv::Mat depth(120, 160, CV_32F, cv::Scalar(3.0f));
    depth(person).setTo(1.5f);
    cv::Mat labels = cv::Mat::zeros(120, 160, CV_16U);
    labels(person).setTo(1);
    cv::imwrite((dir / "rgb" / (stamp + ".png")).string(), bgr);
    writeDepthPng(dir / "depth" / (stamp + ".png"), depth, camera.depth_factor);
    cv::imwrite((dir / "masks" / (stamp + ".png")).string(), labels);
    rgb_list << stamp << " rgb/" << stamp << ".png\n";
    depth_list << stamp << " depth/" << stamp << ".png\n";
  }
  std::ofstream(dir / "masks.json") << R"({"instances": {"1": {"class": "person"}}})";
  return dir;
}

TEST(SegmentCli, MasksSegmenterRoundTripsLabelsVideoAndStats) {
  const fs::path seq = makeSequence();
  const fs::path out = test::scratchDir("segout");
  std::string log;
  ASSERT_EQ(test::runCli("segment " + seq.string() + " --out " + out.string() +
                             " --segmenter masks --contact-sheets",
                         &log),
            0)
      << log;
  ASSERT_TRUE(fs::is_regular_file(out / "masks.json")) << log;
  EXPECT_TRUE(fs::is_regular_file(out / "overlay.mp4") || fs::is_regular_file(out / "overlay.avi"))
      << log;
  EXPECT_TRUE(fs::is_regular_file(out / "contact" / "sheet_0000.png"));
  for (const auto& entry : fs::directory_iterator(seq / "masks")) {
    const cv::Mat expected = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
    const cv::Mat got =
        cv::imread((out / "masks" / entry.path().filename()).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(got.empty()) << entry.path().filename();
    EXPECT_EQ(got.type(), CV_16U);
    EXPECT_EQ(cv::countNonZero(got != expected), 0) << entry.path().filename();
  }
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["frames"], 6);
  EXPECT_EQ(stats["frames_with_person"], 6);
  EXPECT_EQ(stats["per_frame"].size(), 6u);
  EXPECT_EQ(readJsonFile(out / "masks.json")["instances"]["1"]["class"], "person");
}

TEST(SegmentCli, PropagationBetweenSegmentedFramesKeepsThePerson) {
  const fs::path seq = makeSequence();
  const fs::path out = test::scratchDir("segprop");
  std::string log;
  ASSERT_EQ(test::runCli("segment " + seq.string() + " --out " + out.string() +
                             " --segmenter masks --segment-every 3 --no-video --max-frames 5",
                         &log),
            0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["segmenter"], "masks/every3");
  EXPECT_EQ(stats["frames"], 5);
  EXPECT_EQ(stats["frames_with_person"], 5);
  EXPECT_TRUE(stats["per_frame"][1]["steps"].contains("flow"));  // frame 1 was propagated
  EXPECT_FALSE(fs::exists(out / "overlay.mp4") || fs::exists(out / "overlay.avi"));
  // The propagated person overlaps its ground truth well (moved 3 px right per frame).
  const std::string stem = "100.13";
  const cv::Mat gt =
      cv::imread((seq / "masks" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED) > 0;
  const cv::Mat got =
      cv::imread((out / "masks" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED) > 0;
  const double iou = double(cv::countNonZero(gt & got)) / double(cv::countNonZero(gt | got));
  EXPECT_GT(iou, 0.8);
}

TEST(SegmentCli, BadInputGivesExitCode2AndNamesTheProblem) {
  const fs::path seq = makeSequence();
  const fs::path out = test::scratchDir("segbad");
  std::string log;
  EXPECT_EQ(test::runCli("segment " + seq.string() + " --out " + out.string() +
                             " --segmenter dnn --models " + out.string(),
                         &log),
            2);
  EXPECT_NE(log.find("yolo-fastest-1.1-xl.cfg"), std::string::npos) << log;
  fs::remove_all(seq / "masks");
  EXPECT_EQ(test::runCli(
                "segment " + seq.string() + " --out " + out.string() + " --segmenter masks", &log),
            2);
  EXPECT_NE(log.find("masks"), std::string::npos) << log;
  EXPECT_EQ(test::runCli(
                "segment " + seq.string() + " --out " + out.string() + " --segmenter magic", &log),
            2);
  EXPECT_EQ(test::runCli("segment " + (seq / "nope").string() + " --out " + out.string(), &log), 2);
}

}  // namespace
