// Mask propagation by DIS flow: a textured image shifted by known pixels moves its labels.
#include <gtest/gtest.h>

#include "perception/propagation.hpp"
#include "synthetic_scene.hpp"

using namespace dynanav;

namespace {

using test::shifted;
using test::texture;

TEST(Propagation, LabelsFollowAKnownShift) {
  const cv::Size size(320, 240);
  RgbdFrame a, b;
  a.bgr = texture(size, 3);
  const int dx = 6, dy = -4;
  b.bgr = shifted(a.bgr, dx, dy);
  a.depth_m = cv::Mat(size, CV_32F, cv::Scalar(3.0f));
  b.depth_m = a.depth_m.clone();
  const cv::Rect square(100, 80, 60, 60);
  a.depth_m(square).setTo(1.5f);
  b.depth_m(square + cv::Point(dx, dy)).setTo(1.5f);
  Instances inst = Instances::none(size);
  inst.labels(square).setTo(1);
  inst.items = {{1, "person", 0.9f, square, "selfie", {}}};

  PerceptionConfig config;
  MaskPropagator propagator(config);
  propagator.setReference(a, inst);
  const Instances out = propagator.propagate(b);
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].mask_source, "flow");
  const cv::Rect expected = square + cv::Point(dx, dy);
  const cv::Rect got = out.items[0].box;
  EXPECT_NEAR(got.x, expected.x, 1);
  EXPECT_NEAR(got.y, expected.y, 1);
  EXPECT_NEAR(got.width, expected.width, 2);
  EXPECT_NEAR(got.height, expected.height, 2);
  // Almost every label sits on the shifted square.
  const int overlap = cv::countNonZero(out.mask(1)(expected));
  EXPECT_GT(overlap, 0.95 * expected.area());
  EXPECT_LT(out.area(1), 1.05 * expected.area());
}

TEST(Propagation, DepthDropsPixelsThatLeftTheObject) {
  // Flow carries the labels onto the background when the object's depth says otherwise:
  // here the image is static but the depth of the labelled area's right half jumps far away.
  const cv::Size size(320, 240);
  RgbdFrame a;
  a.bgr = texture(size, 5);
  a.depth_m = cv::Mat(size, CV_32F, cv::Scalar(1.5f));
  RgbdFrame b = a;
  b.depth_m = a.depth_m.clone();
  const cv::Rect square(100, 80, 60, 60);
  b.depth_m(cv::Rect(140, 80, 20, 60)).setTo(4.0f);
  Instances inst = Instances::none(size);
  inst.labels(square).setTo(1);
  inst.items = {{1, "person", 0.9f, square, "selfie", {}}};
  PerceptionConfig config;
  MaskPropagator propagator(config);
  propagator.setReference(a, inst);
  const Instances out = propagator.propagate(b);
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(cv::countNonZero(out.mask(1)(cv::Rect(140, 80, 20, 60))), 0);
  EXPECT_GT(out.area(1), 0.9 * 40 * 60);
}

TEST(Propagation, SegmenterRunsEveryKthFrame) {
  // An inner segmenter that counts its calls.
  struct Counting final : Segmenter {
    int* calls;
    explicit Counting(int* c) : calls(c) {}
    Instances segment(const RgbdFrame& f) override {
      ++*calls;
      Instances out = Instances::none(f.bgr.size());
      out.labels(cv::Rect(10, 10, 20, 20)).setTo(1);
      out.items = {{1, "person", 1.f, cv::Rect(10, 10, 20, 20), "file", {}}};
      return out;
    }
    std::string name() const override { return "count"; }
  };
  int calls = 0;
  PropagatingSegmenter segmenter(std::make_unique<Counting>(&calls), 3, PerceptionConfig{});
  EXPECT_EQ(segmenter.name(), "count/every3");
  RgbdFrame f;
  f.bgr = texture({160, 120}, 1);
  for (int i = 0; i < 7; ++i) {
    const Instances out = segmenter.segment(f);
    EXPECT_EQ(out.items.size(), 1u) << "frame " << i;
  }
  EXPECT_EQ(calls, 3);  // frames 0, 3, 6
}

}  // namespace
