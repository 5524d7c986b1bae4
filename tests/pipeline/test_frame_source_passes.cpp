// SequenceSource's passes (the long-run test's source): passes alternate forward and backward so
// the camera path stays continuous, every frame is delivered once per pass, and stamps keep
// increasing with the recorded intervals (mirrored in backward passes).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "io/camera_yaml.hpp"
#include "pipeline/frame_source.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// A tiny TUM-layout folder of `stamps.size()` textured 64x48 frames at those stamps.
fs::path makeSequence(const std::string& tag, const std::vector<double>& stamps) {
  const fs::path dir = test::scratchDir(tag);
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  std::ofstream rgb(dir / "rgb.txt"), depth(dir / "depth.txt");
  for (size_t i = 0; i < stamps.size(); ++i) {
    const std::string name = std::to_string(i) + ".png";
    cv::Mat colour(48, 64, CV_8UC3);
    cv::RNG(int(i) + 1).fill(colour, cv::RNG::UNIFORM, 0, 256);
    cv::imwrite((dir / "rgb" / name).string(), colour);
    cv::imwrite((dir / "depth" / name).string(), cv::Mat(48, 64, CV_16UC1, cv::Scalar(5000)));
    rgb << cv::format("%.6f rgb/%s\n", stamps[i], name.c_str());
    depth << cv::format("%.6f depth/%s\n", stamps[i] + 0.004, name.c_str());
  }
  PinholeCamera cam;
  cam.width = 64;
  cam.height = 48;
  cam.cx = 31.5;
  cam.cy = 23.5;
  saveCameraYaml(dir / "camera.yaml", cam);
  return dir;
}

int fileIndex(const RgbdFrame& f) {
  return std::stoi(fs::path(f.rgb_path).stem().string());
}

TEST(PassStep, AlternatesDirectionAndStartsEachPassWhereTheLastEnded) {
  std::vector<size_t> order;
  std::vector<int> passes;
  for (size_t k = 0; k < 12; ++k) {
    const PassStep s = passStep(k, 4);
    order.push_back(s.index);
    passes.push_back(s.pass);
    EXPECT_EQ(s.backward, s.pass % 2 == 1);
  }
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 3, 2, 1, 0, 0, 1, 2, 3}));
  EXPECT_EQ(passes, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}));
  // Consecutive deliveries are never more than one recorded frame apart: no jump.
  for (size_t k = 1; k < order.size(); ++k)
    EXPECT_LE(std::abs(int(order[k]) - int(order[k - 1])), 1) << k;
}

TEST(PassStamp, BackwardPassMirrorsTheIntervals) {
  // Recorded: 10.0, 10.1, 10.3 (uneven); span = duration + one mean interval = 0.45 s.
  const double first = 10.0, last = 10.3, span = 0.45;
  const PassStep back{1, 0, true};
  EXPECT_DOUBLE_EQ(passStamp(10.3, {1, 2, true}, first, last, span), 10.45);
  EXPECT_NEAR(passStamp(10.1, {1, 1, true}, first, last, span), 10.65, 1e-12);
  EXPECT_NEAR(passStamp(10.0, back, first, last, span), 10.75, 1e-12);
  EXPECT_NEAR(passStamp(10.0, {2, 0, false}, first, last, span), 10.9, 1e-12);
  EXPECT_NEAR(passStamp(10.1, {2, 1, false}, first, last, span), 11.0, 1e-12);
}

TEST(SequenceSourcePasses, PingPongOrderWithIncreasingStampsAndIndices) {
  const std::vector<double> stamps{100.0, 100.033, 100.07, 100.1, 100.134};
  const fs::path dir = makeSequence("source_passes", stamps);
  SequenceSourceOptions options;
  options.dir = dir;
  options.passes = 3;
  SequenceSource source(options);
  EXPECT_EQ(source.expected(), 15u);
  std::vector<int> files;
  double last_stamp = -1.0;
  int expected_index = 0;
  while (auto f = source.next()) {
    files.push_back(fileIndex(*f));
    EXPECT_GT(f->stamp_s, last_stamp) << "frame " << f->index;
    // Depth keeps its 4 ms offset from colour, mirrored in time in backward passes.
    const bool backward = f->index >= 5 && f->index < 10;
    EXPECT_NEAR(f->depth_stamp_s - f->stamp_s, backward ? -0.004 : 0.004, 1e-6) << f->index;
    if (last_stamp > 0.0) {
      EXPECT_LT(f->stamp_s - last_stamp, 0.05) << "frame " << f->index;
    }
    last_stamp = f->stamp_s;
    EXPECT_EQ(f->index, expected_index++);
  }
  EXPECT_EQ(files, (std::vector<int>{0, 1, 2, 3, 4, 4, 3, 2, 1, 0, 0, 1, 2, 3, 4}));
  EXPECT_EQ(source.skipped(), 0);
}

TEST(SequenceSourcePasses, MaxFramesIsPerPassAndABadFrameIsSkippedEachPass) {
  const fs::path dir = makeSequence("source_passes_bad", {5.0, 5.1, 5.2, 5.3});
  std::ofstream(dir / "rgb" / "1.png", std::ios::trunc) << "not an image";
  SequenceSourceOptions options;
  options.dir = dir;
  options.passes = 2;
  options.max_frames = 3;
  SequenceSource source(options);
  std::vector<int> files;
  while (auto f = source.next()) files.push_back(fileIndex(*f));
  EXPECT_EQ(files, (std::vector<int>{0, 2, 2, 0}));
  EXPECT_EQ(source.skipped(), 2);
}

}  // namespace
}  // namespace dynanav
