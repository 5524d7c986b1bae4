#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "io/sequence.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
namespace fs = std::filesystem;

namespace {

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A tiny TUM-layout sequence: n frames of 64x48, depth 1 m + 0.1 m per frame.
fs::path makeSequence(const std::string& tag, int n) {
  const fs::path dir = test::scratchDir(tag);
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  std::string rgb = "# color images\r\n# timestamp filename\r\n", depth = "# depth\n\n";
  for (int i = 0; i < n; ++i) {
    const std::string stamp = std::to_string(100.0 + i / 30.0);
    cv::Mat colour(48, 64, CV_8UC3);
    cv::RNG(i + 1).fill(colour, cv::RNG::UNIFORM, 0, 256);  // texture: flat frames are skipped
    cv::imwrite((dir / "rgb" / (stamp + ".png")).string(), colour);
    cv::Mat d(48, 64, CV_16UC1, cv::Scalar(5000 + 500 * i));
    d.at<uint16_t>(0, 0) = 0;
    cv::imwrite((dir / "depth" / (stamp + ".png")).string(), d);
    rgb += stamp + " rgb/" + stamp + ".png\r\n";
    depth += std::to_string(100.0 + i / 30.0 + 0.005) + " depth/" + stamp + ".png\n";
  }
  writeText(dir / "rgb.txt", rgb);
  writeText(dir / "depth.txt", depth);
  PinholeCamera cam;
  cam.width = 64;
  cam.height = 48;
  cam.cx = 31.5;
  cam.cy = 23.5;
  saveCameraYaml(dir / "camera.yaml", cam);
  return dir;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Sequence, ReadsCrlfCommentsAndBlankLines) {
  const fs::path dir = makeSequence("seq", 3);
  const auto seq = TumSequence::open(dir, IoConfig{});
  ASSERT_EQ(seq.size(), 3u);
  EXPECT_EQ(seq.cameraSource(), "camera.yaml");
  const RgbdFrame f = seq.load(2);
  EXPECT_EQ(f.index, 2);
  EXPECT_EQ(f.bgr.type(), CV_8UC3);
  EXPECT_EQ(f.depth_m.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(f.depth_m.at<float>(1, 1), 1.2f);
  EXPECT_FLOAT_EQ(f.depth_m.at<float>(0, 0), 0.0f);  // 0 stays invalid
  EXPECT_NEAR(f.depth_stamp_s - f.stamp_s, 0.005, 1e-9);
}

TEST(Sequence, RejectsUnsortedDuplicateAndMalformedLines) {
  const fs::path dir = test::scratchDir("lists");
  writeText(dir / "a.txt", "1.0 a.png\n0.5 b.png\n");
  EXPECT_NE(errorOf([&] { readStampedFileList(dir / "a.txt"); }).find("a.txt:2"),
            std::string::npos);
  writeText(dir / "b.txt", "1.0 a.png\n1.0 b.png\n");
  EXPECT_NE(errorOf([&] { readStampedFileList(dir / "b.txt"); }).find("duplicate"),
            std::string::npos);
  writeText(dir / "c.txt", "# header\nabc a.png\n");
  EXPECT_NE(errorOf([&] { readStampedFileList(dir / "c.txt"); }).find("c.txt:2"),
            std::string::npos);
  writeText(dir / "d.txt", "1.0 a.png extra\n");
  EXPECT_FALSE(errorOf([&] { readStampedFileList(dir / "d.txt"); }).empty());
  writeText(dir / "e.txt", "# only comments\n\n");
  EXPECT_NE(errorOf([&] { readStampedFileList(dir / "e.txt"); }).find("no images"),
            std::string::npos);
  writeText(dir / "f.txt", "nan a.png\n");
  EXPECT_FALSE(errorOf([&] { readStampedFileList(dir / "f.txt"); }).empty());
}

TEST(Sequence, AssociationIsGreedyBySmallestGap) {
  const std::vector<StampedFile> rgb = {{1.000, "a", 1}, {1.030, "b", 2}, {1.100, "c", 3}};
  const std::vector<StampedFile> depth = {{1.012, "x", 1}, {1.025, "y", 2}, {1.200, "z", 3}};
  const auto pairs = associate(rgb, depth, 0.02);
  // 1.030-1.025 (0.005) is taken first, then 1.000-1.012 (0.012); c has no partner.
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].rgb.relative_path, "a");
  EXPECT_EQ(pairs[0].depth.relative_path, "x");
  EXPECT_EQ(pairs[1].rgb.relative_path, "b");
  EXPECT_EQ(pairs[1].depth.relative_path, "y");
}

TEST(Sequence, MissingDepthListNamesIt) {
  const fs::path dir = makeSequence("nodepth", 2);
  fs::remove(dir / "depth.txt");
  EXPECT_NE(errorOf([&] { TumSequence::open(dir, IoConfig{}); }).find("depth.txt"),
            std::string::npos);
}

TEST(Sequence, BadImagesNameTheFile) {
  const fs::path dir = makeSequence("badimg", 3);
  const auto seq = TumSequence::open(dir, IoConfig{});
  // Corrupt colour image.
  writeText(dir / seq.pairs()[0].rgb.relative_path, "not a png");
  EXPECT_NE(errorOf([&] { (void)seq.load(0); }).find(seq.pairs()[0].rgb.relative_path),
            std::string::npos);
  // Depth of the wrong type.
  cv::imwrite((dir / seq.pairs()[1].depth.relative_path).string(),
              cv::Mat(48, 64, CV_8UC3, cv::Scalar(1)));
  EXPECT_NE(errorOf([&] { (void)seq.load(1); }).find("16-bit"), std::string::npos);
  // Depth of the wrong size.
  cv::imwrite((dir / seq.pairs()[2].depth.relative_path).string(),
              cv::Mat(10, 10, CV_16UC1, cv::Scalar(1)));
  EXPECT_NE(errorOf([&] { (void)seq.load(2); }).find("10x10"), std::string::npos);
  // Missing depth image.
  fs::remove(dir / seq.pairs()[2].depth.relative_path);
  EXPECT_NE(errorOf([&] { (void)seq.load(2); }).find("not found"), std::string::npos);
}

TEST(Sequence, CameraFromFolderNameOrError) {
  const fs::path base = test::scratchDir("names");
  const fs::path dir = base / "rgbd_dataset_freiburg1_tiny";
  fs::create_directories(dir);
  writeText(dir / "rgb.txt", "1.0 rgb/a.png\n");
  writeText(dir / "depth.txt", "1.0 depth/a.png\n");
  EXPECT_EQ(TumSequence::open(dir, IoConfig{}).cameraSource(), "folder name");
  const fs::path other = base / "plain";
  fs::create_directories(other);
  writeText(other / "rgb.txt", "1.0 rgb/a.png\n");
  writeText(other / "depth.txt", "1.0 depth/a.png\n");
  EXPECT_NE(errorOf([&] { TumSequence::open(other, IoConfig{}); }).find("camera"),
            std::string::npos);
  EXPECT_EQ(TumSequence::open(other, IoConfig{}, PinholeCamera{}).cameraSource(), "config");
}

TEST(CameraYaml, RoundTripAndErrors) {
  const fs::path dir = test::scratchDir("camyaml");
  PinholeCamera cam = PinholeCamera::tumFreiburg1();
  saveCameraYaml(dir / "camera.yaml", cam);
  const PinholeCamera back = loadCameraYaml(dir / "camera.yaml");
  EXPECT_DOUBLE_EQ(back.fx, cam.fx);
  EXPECT_DOUBLE_EQ(back.distortion[4], cam.distortion[4]);
  EXPECT_NEAR(back.readout_s, 0.025, 1e-12);  // fr1's rolling shutter survives the round trip
  writeText(dir / "no_readout.yaml", "width: 640\nheight: 480\nfx: 5\nfy: 5\ncx: 1\ncy: 1\n");
  EXPECT_EQ(loadCameraYaml(dir / "no_readout.yaml").readout_s, 0.0);  // global shutter by default
  writeText(
      dir / "neg_readout.yaml",
      "width: 640\nheight: 480\nfx: 5\nfy: 5\ncx: 1\ncy: 1\nrolling_shutter_readout_ms: -3\n");
  EXPECT_NE(errorOf([&] { loadCameraYaml(dir / "neg_readout.yaml"); }).find("readout"),
            std::string::npos);
  writeText(dir / "bad.yaml", "width: 640\nheight: 480\nfx: 500\n");
  EXPECT_NE(errorOf([&] { loadCameraYaml(dir / "bad.yaml"); }).find("'fy'"), std::string::npos);
  writeText(dir / "neg.yaml", "width: 640\nheight: 480\nfx: -5\nfy: 5\ncx: 1\ncy: 1\n");
  EXPECT_FALSE(errorOf([&] { loadCameraYaml(dir / "neg.yaml"); }).empty());
}

TEST(DepthPng, WriteReadRoundTrip) {
  const fs::path dir = test::scratchDir("depthpng");
  cv::Mat depth(4, 4, CV_32F, cv::Scalar(1.2345f));
  depth.at<float>(0, 0) = std::numeric_limits<float>::quiet_NaN();
  depth.at<float>(0, 1) = 20.0f;  // beyond 16-bit range: invalid
  writeDepthPng(dir / "d.png", depth, 5000.0);
  const cv::Mat back = readDepthPng(dir / "d.png", 5000.0, {4, 4});
  EXPECT_FLOAT_EQ(back.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(back.at<float>(0, 1), 0.0f);
  EXPECT_NEAR(back.at<float>(2, 2), 1.2346f, 1e-4);
}
