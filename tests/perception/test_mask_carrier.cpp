// Carrying a late segmentation (real-time mode): chained frame-to-frame flows bring a mask of an
// earlier frame onto an object that has moved since, and the deterministic lag replay behaves
// like the real-time worker.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "perception/lagged_segmenter.hpp"
#include "perception/mask_carrier.hpp"
#include "synthetic_scene.hpp"

using namespace dynanav;

namespace {

// A body-sized object (DIS's fast preset works at 1/8 of this size: a small object's flow comes
// out short) moving right by 8 px per frame over a still background.
constexpr int kStepPx = 8;
const cv::Size kSize(640, 480);

cv::Rect objectAt(int index) {
  return {160 + kStepPx * index, 120, 140, 220};
}

/// Frame `index`: a still textured background, a differently textured object pasted where
/// objectAt() says, nearer in depth.
RgbdFrame frameAt(int index) {
  static const cv::Mat background = test::texture(kSize, 3);
  static const cv::Mat object_texture = test::texture(kSize, 11);
  RgbdFrame f;
  f.index = index;
  f.stamp_s = index / 30.0;
  f.bgr = background.clone();
  const cv::Rect box = objectAt(index);
  object_texture(cv::Rect(0, 0, box.width, box.height)).copyTo(f.bgr(box));
  f.depth_m = cv::Mat(kSize, CV_32F, cv::Scalar(3.0f));
  f.depth_m(box).setTo(1.5f);
  return f;
}

Instances truthOf(int index) {
  Instances out = Instances::none(kSize);
  out.labels(objectAt(index)).setTo(1);
  out.items = {{1, "person", 1.f, objectAt(index), "file", {}}};
  return out;
}

/// Share of the true object's pixels the carried label covers, and of the label outside it.
std::pair<double, double> coverage(const Instances& carried, int index) {
  const cv::Rect truth = objectAt(index);
  const cv::Mat label = carried.mask(1);
  const double inside = cv::countNonZero(label(truth));
  const double all = cv::countNonZero(label);
  return {inside / truth.area(), all > 0 ? (all - inside) / all : 1.0};
}

TEST(MaskCarrier, ChainsFrameToFrameFlowsToCarryALateSegmentation) {
  PerceptionConfig config;
  MaskCarrier carrier(config, 12);
  carrier.reset(frameAt(0), truthOf(0));
  const RgbdFrame late = frameAt(1);  // given to the segmenter at frame 1, finished at frame 6
  for (int i = 1; i <= 5; ++i) carrier.carry(frameAt(i));
  const Instances segmented = truthOf(1);
  const Instances carried = carrier.carry(frameAt(6), &segmented, &late);
  EXPECT_EQ(carrier.chainedArrivals(), 1);
  EXPECT_EQ(carrier.directArrivals(), 0);
  ASSERT_EQ(carried.items.size(), 1u);
  const auto [covered, outside] = coverage(carried, 6);
  EXPECT_GT(covered, 0.9);  // 40 px of motion since frame 1, carried onto the object
  EXPECT_LT(outside, 0.1);
}

TEST(MaskCarrier, FallsBackToOneDirectFlowBeyondItsHistory) {
  PerceptionConfig config;
  MaskCarrier carrier(config, 2);
  carrier.reset(frameAt(0), truthOf(0));
  const RgbdFrame late = frameAt(1);
  for (int i = 1; i <= 4; ++i) carrier.carry(frameAt(i));
  const Instances segmented = truthOf(1);
  const Instances carried = carrier.carry(frameAt(5), &segmented, &late);
  EXPECT_EQ(carrier.chainedArrivals(), 0);
  EXPECT_EQ(carrier.directArrivals(), 1);
  EXPECT_EQ(carried.items.size(), 1u);  // carried somewhere, by the direct flow
}

TEST(MaskCarrier, ASegmentationOfTheCurrentFrameIsUsedAsItIs) {
  PerceptionConfig config;
  MaskCarrier carrier(config);
  carrier.reset(frameAt(0), truthOf(0));
  const RgbdFrame now = frameAt(1);
  const Instances segmented = truthOf(1);
  const Instances out = carrier.carry(now, &segmented, &now);
  EXPECT_EQ(out.items[0].box, objectAt(1));
  EXPECT_EQ(cv::countNonZero(out.labels != truthOf(1).labels), 0);
}

TEST(MaskCarrier, FollowsTheObjectFrameToFrameWithoutArrivals) {
  PerceptionConfig config;
  MaskCarrier carrier(config);
  carrier.reset(frameAt(0), truthOf(0));
  Instances out;
  for (int i = 1; i <= 6; ++i) out = carrier.carry(frameAt(i));
  const auto [covered, outside] = coverage(out, 6);
  EXPECT_GT(covered, 0.85);
  EXPECT_LT(outside, 0.15);
}

/// Labels the true object of every frame it is given and remembers which frames those were.
struct RecordingSegmenter final : Segmenter {
  std::vector<int> called;
  Instances segment(const RgbdFrame& f) override {
    called.push_back(f.index);
    return truthOf(f.index);
  }
  std::string name() const override { return "truth"; }
};

TEST(LaggedSegmenter, SegmentsLikeAWorkerThatNeedsLagFramesPerCall) {
  auto inner = std::make_unique<RecordingSegmenter>();
  RecordingSegmenter* recorder = inner.get();
  PerceptionConfig config;
  LaggedSegmenter segmenter(std::move(inner), 3, config);
  EXPECT_EQ(segmenter.name(), "truth/lag3");
  std::vector<Instances> outputs;
  for (int i = 0; i <= 8; ++i) outputs.push_back(segmenter.segment(frameAt(i)));
  // Frame 0 in time (the map starts from it); the worker then takes frames 1, 4, 7.
  EXPECT_EQ(recorder->called, (std::vector<int>{0, 1, 4, 7}));
  // Every output covers the object where it is now, however late its segmentation was.
  for (int i = 0; i <= 8; ++i) {
    const auto [covered, outside] = coverage(outputs[i], i);
    EXPECT_GT(covered, 0.85) << "frame " << i;
    EXPECT_LT(outside, 0.15) << "frame " << i;
  }
}

TEST(LaggedSegmenter, LagZeroIsTheInnerSegmenter) {
  auto inner = std::make_unique<RecordingSegmenter>();
  RecordingSegmenter* recorder = inner.get();
  PerceptionConfig config;
  LaggedSegmenter segmenter(std::move(inner), 0, config);
  for (int i = 0; i <= 3; ++i) {
    const Instances out = segmenter.segment(frameAt(i));
    EXPECT_EQ(cv::countNonZero(out.labels != truthOf(i).labels), 0) << "frame " << i;
  }
  EXPECT_EQ(recorder->called, (std::vector<int>{0, 1, 2, 3}));
}

}  // namespace

namespace {

TEST(GrowWithinDepth, TakesTheBodyPartTheFlowLeftBehindButNotTheBackground) {
  // The carried label sits 6 px left of the object (its flow came out short); growing by 8 px
  // reaches the object's right edge, and the depth band keeps it off the wall behind.
  const cv::Size size(200, 150);
  cv::Mat depth(size, CV_32F, cv::Scalar(3.0f));
  const cv::Rect object(60, 40, 50, 70);
  depth(object).setTo(1.5f);
  cv::Mat labels(size, CV_16U, cv::Scalar(0));
  labels(object - cv::Point(6, 0)).setTo(1);
  growWithinDepth(labels, depth, 1, 8, 0.05, 0.6);
  const cv::Mat label = labels == 1;
  EXPECT_EQ(cv::countNonZero(label(object)), object.area());  // all of the object
  EXPECT_EQ(cv::countNonZero(label), object.area());          // nothing else
}

TEST(GrowWithinDepth, LeavesOtherInstancesAlone) {
  const cv::Size size(200, 150);
  cv::Mat depth(size, CV_32F, cv::Scalar(1.5f));
  cv::Mat labels(size, CV_16U, cv::Scalar(0));
  labels(cv::Rect(40, 40, 30, 30)).setTo(1);
  labels(cv::Rect(72, 40, 30, 30)).setTo(2);  // a neighbour at the same depth, 2 px away
  growWithinDepth(labels, depth, 1, 8, 0.05, 0.6);
  EXPECT_EQ(cv::countNonZero(labels == 2), 30 * 30);
}

}  // namespace
