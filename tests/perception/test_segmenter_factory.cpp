// The segmenter factory: names, errors naming the missing file, fall-back to hog.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/error.hpp"
#include "perception/depth_masks.hpp"
#include "perception/model_files.hpp"
#include "perception/segmenter.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using namespace dynanav;

namespace {

std::string errorOf(const SegmenterRequest& request, const PerceptionConfig& config) {
  try {
    (void)makeSegmenter(request, config);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SegmenterFactory, UnknownNameIsAnInputError) {
  SegmenterRequest request;
  request.name = "panoptic";
  EXPECT_NE(errorOf(request, {}).find("unknown segmenter 'panoptic'"), std::string::npos);
}

TEST(SegmenterFactory, MissingModelFileIsNamed) {
  const fs::path empty = test::scratchDir("nomodels");
  PerceptionConfig config;
  config.models_dir = empty.string();
  SegmenterRequest request;
  request.name = "dnn";
  const std::string message = errorOf(request, config);
  EXPECT_NE(message.find("yolo-fastest-1.1-xl.cfg"), std::string::npos) << message;
  EXPECT_NE(message.find(empty.string()), std::string::npos) << message;
}

TEST(SegmenterFactory, AutoFallsBackToHogWithoutModels) {
  PerceptionConfig config;
  config.models_dir = test::scratchDir("nomodels_auto").string();
  SegmenterRequest request;
  request.name = "auto";
  EXPECT_EQ(makeSegmenter(request, config)->name(), "hog");
}

TEST(SegmenterFactory, NamesAndPropagation) {
  SegmenterRequest request;
  request.name = "hog";
  EXPECT_EQ(makeSegmenter(request, {})->name(), "hog");
  request.segment_every = 4;
  EXPECT_EQ(makeSegmenter(request, {})->name(), "hog/every4");
  request.segment_every = 0;
  EXPECT_THROW((void)makeSegmenter(request, {}), InputError);
  request = {};
  request.name = "none";
  auto none = makeSegmenter(request, {});
  RgbdFrame frame;
  frame.bgr = cv::Mat::zeros(48, 64, CV_8UC3);
  const Instances out = none->segment(frame);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(out.labels.type(), CV_16U);
  EXPECT_EQ(out.labels.size(), frame.bgr.size());
  request.name = "masks";  // no sequence folder
  EXPECT_THROW((void)makeSegmenter(request, {}), InputError);
}

TEST(ModelFiles, ExplicitFolderIsTheOnlyCandidate) {
  EXPECT_EQ(modelSearchPath("/some/where").size(), 1u);
  EXPECT_TRUE(findModelsDir("/nonexistent/models", dnnModelFiles(true)).empty());
}

TEST(DepthMasks, ModeAndBoxMaskPickTheNearObject) {
  // A box over a person at 1.6 m in front of a wall at 4 m that fills most of the box.
  cv::Mat depth(100, 100, CV_32F, cv::Scalar(4.0f));
  depth(cv::Rect(35, 10, 30, 90)).setTo(1.6f);
  depth(cv::Rect(40, 40, 5, 5)).setTo(0.0f);  // a hole
  EXPECT_NEAR(depthMode(depth, cv::Mat(), 0.05), 4.0, 0.05);
  EXPECT_NEAR(depthMode(depth, cv::Mat(), 0.05, 0.5), 4.0, 0.05);  // wall still much stronger
  const cv::Mat mask = depthMaskInBox(depth, cv::Rect(20, 0, 60, 100), 0.05, 0.5);
  EXPECT_EQ(cv::countNonZero(mask), 30 * 90 - 25);
  cv::Mat person = cv::Mat::zeros(depth.size(), CV_8U);
  person(cv::Rect(30, 10, 40, 90)).setTo(255);  // leaks 5 px onto the wall on each side
  refineMaskByDepth(person, depth, 0.05, 0.5);
  EXPECT_EQ(cv::countNonZero(person), 30 * 90);  // hole kept: no depth, the model's word stands
}

}  // namespace

namespace {

TEST(ModelFiles, SearchPathOrder) {
  setenv("DYNANAV_MODELS", "/env/models", 1);
  const auto dirs = modelSearchPath("");
  unsetenv("DYNANAV_MODELS");
  ASSERT_GE(dirs.size(), 5u);
  EXPECT_EQ(dirs[0], fs::path("/env/models"));
  EXPECT_EQ(dirs[1], fs::current_path() / "models");
  EXPECT_EQ(dirs[2], fs::current_path() / ".." / "shared" / "models");
  EXPECT_EQ(dirs[3].filename(), "models");  // next to the test binary
}

}  // namespace
