// firstFrameMotion: an object first segmented in this frame gets its motion since the previous
// frame from that frame's points the dense flow carries onto its mask.
#include <gtest/gtest.h>

#include "dynamics/first_motion.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

/// fx = fy = 525, centre (319.5, 239.5), no distortion: PinholeCamera's defaults.
PinholeCamera camera() {
  return PinholeCamera{};
}

/// Depth of a 60 x 120 px block at 2 m (with a relief) whose left edge is at `left`, in front of
/// a wall at 4 m.
cv::Mat depthWithBlock(int left) {
  cv::Mat depth(kH, kW, CV_32F, cv::Scalar(4.0f));
  for (int y = 150; y < 270; ++y)
    for (int x = left; x < left + 60; ++x)
      depth.at<float>(y, x) = 2.0f + 0.05f * float((x - left) % 9) / 9.f + 0.02f * float(y % 5);
  return depth;
}

struct Scene {
  cv::Mat depth_prev, depth_now, labels, flow_half;
  Instance instance;
};

/// The block moves `shift_px` to the right between the frames; the wall stands still.
Scene slidingBlock(int left, int shift_px) {
  Scene s;
  s.depth_prev = depthWithBlock(left);
  s.depth_now = depthWithBlock(left + shift_px);
  s.labels = cv::Mat(kH, kW, CV_16U, cv::Scalar(0));
  const cv::Rect box(left + shift_px, 150, 60, 120);
  s.labels(box).setTo(7);
  s.instance.id = 7;
  s.instance.class_name = "person";
  s.instance.box = box;
  s.flow_half = cv::Mat(kH / 2, kW / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
  s.flow_half(cv::Rect(left / 2, 75, 30, 60)).setTo(cv::Scalar(shift_px / 2.f, 0.f));
  return s;
}

}  // namespace

TEST(FirstMotion, AnObjectFirstSegmentedNowReadsItsMotionSinceThePreviousFrame) {
  const Scene s = slidingBlock(200, 8);
  const PinholeCamera c = camera();
  const SE3 T = SE3::Identity();
  const PreviousDepthFrame previous{s.depth_prev, T, 0.0};
  const auto first = firstFrameMotion(
      {s.instance, s.labels, s.flow_half, s.depth_now, T, 1.0 / 30.0, c, previous}, {});
  ASSERT_TRUE(first.has_value());
  // 8 px per frame at 2.03 m and fx 525, 30 frames/s: 0.93 m/s to the right.
  const double expected = 8.0 * 2.03 / 525.0 * 30.0;
  EXPECT_NEAR(first->v_world_mps.x(), expected, 0.08);
  EXPECT_NEAR(first->v_world_mps.y(), 0.0, 0.05);
  EXPECT_NEAR(first->v_world_mps.z(), 0.0, 0.08);
  EXPECT_GT(first->inliers, 100);
}

TEST(FirstMotion, NothingWithoutAPreviousFrameOrFlow) {
  const Scene s = slidingBlock(200, 8);
  const PinholeCamera c = camera();
  const SE3 T = SE3::Identity();
  const PreviousDepthFrame none{};
  EXPECT_FALSE(
      firstFrameMotion({s.instance, s.labels, s.flow_half, s.depth_now, T, 1.0 / 30.0, c, none}, {})
          .has_value());
  const PreviousDepthFrame previous{s.depth_prev, T, 0.0};
  const cv::Mat no_flow;
  EXPECT_FALSE(
      firstFrameMotion({s.instance, s.labels, no_flow, s.depth_now, T, 1.0 / 30.0, c, previous}, {})
          .has_value());
  // The same stamp twice: no interval to divide by.
  EXPECT_FALSE(
      firstFrameMotion({s.instance, s.labels, s.flow_half, s.depth_now, T, 0.0, c, previous}, {})
          .has_value());
}
