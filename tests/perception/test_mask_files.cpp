// The `masks` segmenter's file format, the writer that renumbers ids, and noise injection.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "perception/mask_files.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using namespace dynanav;

namespace {

/// A sequence folder with masks/<stem>.png for two frames: a person (id 1) and a chair (id 2).
fs::path makeMaskFolder() {
  const fs::path dir = test::scratchDir("masks");
  fs::create_directories(dir / "masks");
  for (int f = 0; f < 2; ++f) {
    cv::Mat labels = cv::Mat::zeros(120, 160, CV_16U);
    cv::rectangle(labels, cv::Rect(20 + 5 * f, 10, 30, 80), cv::Scalar(1), cv::FILLED);
    cv::rectangle(labels, cv::Rect(100, 60, 40, 40), cv::Scalar(2), cv::FILLED);
    cv::imwrite((dir / "masks" / ("frame" + std::to_string(f) + ".png")).string(), labels);
  }
  std::ofstream(dir / "masks.json") << R"({"instances": {"1": {"class": "person"}, "2": {"class": "chair"}}})";
  return dir;
}

RgbdFrame frameFor(const fs::path& dir, int f) {
  RgbdFrame frame;
  frame.index = f;
  frame.bgr = cv::Mat::zeros(120, 160, CV_8UC3);
  frame.rgb_path = (dir / "rgb" / ("frame" + std::to_string(f) + ".jpg")).string();
  return frame;
}

TEST(MaskFiles, ReadsInstancesWithClassesAndBoxes) {
  const fs::path dir = makeMaskFolder();
  MaskFileSegmenter segmenter(dir, MaskNoise{});
  const Instances inst = segmenter.segment(frameFor(dir, 1));
  ASSERT_EQ(inst.items.size(), 2u);
  EXPECT_EQ(inst.items[0].id, 1);
  EXPECT_EQ(inst.items[0].class_name, "person");
  EXPECT_EQ(inst.items[0].box, cv::Rect(25, 10, 30, 80));
  EXPECT_EQ(inst.items[1].class_name, "chair");
  EXPECT_EQ(inst.area(2), 40 * 40);
}

TEST(MaskFiles, ErrorsNameTheFile) {
  const fs::path dir = makeMaskFolder();
  MaskFileSegmenter segmenter(dir, MaskNoise{});
  try {
    (void)segmenter.segment(frameFor(dir, 7));
    FAIL() << "no error for a missing mask";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame7.png"), std::string::npos) << e.what();
  }
  // An 8-bit PNG is not an instance mask.
  cv::imwrite((dir / "masks" / "frame0.png").string(), cv::Mat::zeros(120, 160, CV_8U));
  EXPECT_THROW((void)segmenter.segment(frameFor(dir, 0)), InputError);
  // Malformed masks.json.
  std::ofstream(dir / "masks.json") << R"({"instances": {"x": {"class": "person"}}})";
  EXPECT_THROW(MaskFileSegmenter(dir, MaskNoise{}), InputError);
  fs::remove_all(dir / "masks");
  EXPECT_THROW(MaskFileSegmenter(dir, MaskNoise{}), InputError);
}

TEST(MaskFiles, WriterKeepsOneClassPerIdAndRoundTrips) {
  const fs::path out = test::scratchDir("writer");
  std::map<uint16_t, std::string> classes;
  {
    MaskFolderWriter writer(out);
    // Frame a: person id 1, chair id 2. Frame b: chair id 1, person id 2, person id 3.
    Instances a = Instances::none({50, 40});
    a.labels(cv::Rect(0, 0, 10, 10)).setTo(1);
    a.labels(cv::Rect(20, 0, 10, 10)).setTo(2);
    a.items = {{1, "person", 0.9f, {}, "selfie", {}}, {2, "chair", 0.8f, {}, "depth", {}}};
    Instances b = Instances::none({50, 40});
    b.labels(cv::Rect(0, 20, 10, 10)).setTo(1);
    b.labels(cv::Rect(20, 20, 10, 10)).setTo(2);
    b.labels(cv::Rect(35, 20, 10, 10)).setTo(3);
    b.items = {{1, "chair", 0.8f, {}, "depth", {}}, {2, "person", 0.9f, {}, "selfie", {}},
               {3, "person", 0.7f, {}, "selfie", {}}};
    writer.write("a", a);
    const Instances wb = writer.write("b", b);
    EXPECT_EQ(wb.items.size(), 3u);
  }
  classes = readMaskClasses(out / "masks.json");
  ASSERT_EQ(classes.size(), 3u);
  EXPECT_EQ(classes[1], "person");
  EXPECT_EQ(classes[2], "chair");
  EXPECT_EQ(classes[3], "person");
  const Instances back = readMaskPng(out / "masks" / "b.png", classes);
  EXPECT_EQ(back.count("person"), 2);
  EXPECT_EQ(back.count("chair"), 1);
  EXPECT_EQ(back.labels.at<uint16_t>(25, 5), 2);   // (row, col): the chair took the chair's id
  EXPECT_EQ(back.labels.at<uint16_t>(25, 25), 1);  // the first person took person id 1
  EXPECT_EQ(back.labels.at<uint16_t>(25, 40), 3);
}

Instances twoSquares() {
  Instances clean = Instances::none({200, 100});
  clean.labels(cv::Rect(20, 20, 40, 40)).setTo(1);
  clean.labels(cv::Rect(120, 30, 40, 40)).setTo(2);
  clean.items = {{1, "person", 1.f, cv::Rect(20, 20, 40, 40), "file", {}},
                 {2, "person", 1.f, cv::Rect(120, 30, 40, 40), "file", {}}};
  return clean;
}

TEST(MaskNoise, GrowAndShrinkChangeAreaAsExpected) {
  const Instances clean = twoSquares();
  MaskNoise grow;
  grow.grow_px = 3;
  const Instances grown = addMaskNoise(clean, grow, 0);
  EXPECT_GT(grown.area(1), 40 * 40);
  EXPECT_LE(grown.area(1), 46 * 46);
  EXPECT_EQ(grown.items[0].box, cv::Rect(17, 17, 46, 46));
  MaskNoise shrink;
  shrink.grow_px = -3;
  const Instances shrunk = addMaskNoise(clean, shrink, 0);
  EXPECT_EQ(shrunk.area(1), 34 * 34);
}

TEST(MaskNoise, DropShareIsHonouredAndDeterministic) {
  const Instances clean = twoSquares();
  MaskNoise noise;
  noise.drop_share = 0.3;
  noise.seed = 42;
  int kept = 0;
  for (int f = 0; f < 500; ++f) kept += int(addMaskNoise(clean, noise, f).items.size());
  EXPECT_NEAR(kept / 1000.0, 0.7, 0.06);
  // Same seed and frame → same result, whatever was computed before.
  EXPECT_EQ(addMaskNoise(clean, noise, 17).items.size(), addMaskNoise(clean, noise, 17).items.size());
  noise.drop_share = 1.0;
  EXPECT_TRUE(addMaskNoise(clean, noise, 3).empty());
}

TEST(MaskNoise, ShiftMovesMasksWithinBounds) {
  const Instances clean = twoSquares();
  MaskNoise noise;
  noise.shift_px = 5;
  bool moved = false;
  for (int f = 0; f < 20; ++f) {
    const Instances shifted = addMaskNoise(clean, noise, f);
    ASSERT_EQ(shifted.items.size(), 2u);
    const cv::Rect b = shifted.items[0].box;
    EXPECT_EQ(b.size(), cv::Size(40, 40));
    EXPECT_LE(std::abs(b.x - 20), 5);
    EXPECT_LE(std::abs(b.y - 20), 5);
    moved = moved || b.tl() != cv::Point(20, 20);
  }
  EXPECT_TRUE(moved);
}

}  // namespace
