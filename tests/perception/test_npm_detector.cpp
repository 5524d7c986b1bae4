// MoveNet MultiPose decoding (npm_detector.hpp) on hand-made network outputs with known answers.
#include <gtest/gtest.h>

#include "perception/npm_detector.hpp"

using namespace dynanav;

namespace {

constexpr int kGh = 48, kGw = 64;  // grid of a 256x192 input; the image is 640x480 (10 px per cell)

cv::Mat blob(int channels) {
  const int sizes[] = {1, channels, kGh, kGw};
  return cv::Mat(4, sizes, CV_32F, cv::Scalar(0));
}
float& at(cv::Mat& b, int c, int y, int x) {
  return b.ptr<float>(0, c)[y * kGw + x];
}

MultiPoseHeads emptyHeads() {
  return {blob(1),
          blob(2),
          blob(2),
          blob(kBodyKeypointCount),
          blob(2 * kBodyKeypointCount),
          blob(2 * kBodyKeypointCount)};
}

/// One person centred in cell (x 20, y 24): box 12 x 30 cells, keypoint k at cell (18 + k % 5, 12 +
/// k).
void addPerson(MultiPoseHeads& h, float score) {
  at(h.centre, 0, 24, 20) = score;
  at(h.box_offset, 0, 24, 20) = 0.5f;   // dy
  at(h.box_offset, 1, 24, 20) = 0.25f;  // dx
  at(h.box_scale, 0, 24, 20) = 30.f;    // height
  at(h.box_scale, 1, 24, 20) = 12.f;    // width
  for (int k = 0; k < kBodyKeypointCount; ++k) {
    const int ky = 12 + k, kx = 18 + k % 5;
    at(h.regress, 2 * k, 24, 20) = float(ky - 24) + 0.4f;  // near, not exactly on, the peak
    at(h.regress, 2 * k + 1, 24, 20) = float(kx - 20) - 0.3f;
    at(h.heat, k, ky, kx) = 0.8f;
    at(h.offset, 2 * k, ky, kx) = 0.5f;
    at(h.offset, 2 * k + 1, ky, kx) = -0.5f;
  }
}

}  // namespace

TEST(MultiPoseDecode, BoxAndKeypointsOfOnePerson) {
  MultiPoseHeads heads = emptyHeads();
  addPerson(heads, 0.9f);
  at(heads.centre, 0, 5, 50) = 0.2f;  // below the threshold
  const auto found = decodeMultiPose(heads, {640, 480}, 0.3f);
  ASSERT_EQ(found.size(), 1u);
  const Detection& d = found[0];
  EXPECT_EQ(d.class_id, 0);
  EXPECT_EQ(d.class_name, "person");
  EXPECT_FLOAT_EQ(d.score, 0.9f);
  // Centre (20.25, 24.5) cells = (202.5, 245) px; 120 x 300 px.
  EXPECT_NEAR(d.box.x, 142.5, 1.0);
  EXPECT_NEAR(d.box.y, 95, 1.0);
  EXPECT_NEAR(d.box.width, 120, 1.0);
  EXPECT_NEAR(d.box.height, 300, 1.0);
  ASSERT_TRUE(d.keypoints.has_value());
  for (int k = 0; k < kBodyKeypointCount; ++k) {
    const Keypoint& p = d.keypoints->points[size_t(k)];
    EXPECT_NEAR(p.pixel.x, (18 + k % 5 - 0.5f) * 10.f, 1e-3) << k;
    EXPECT_NEAR(p.pixel.y, (12 + k + 0.5f) * 10.f, 1e-3) << k;
    EXPECT_FLOAT_EQ(p.score, 0.8f) << k;
  }
}

TEST(MultiPoseDecode, PeaksBestFirstAtMostMaxPeopleAndClippedBoxes) {
  MultiPoseHeads heads = emptyHeads();
  addPerson(heads, 0.6f);
  for (int i = 0; i < 8; ++i) {  // eight more people in a row at the top, one at the border
    at(heads.centre, 0, 2, 4 + 7 * i) = 0.7f + 0.01f * float(i);
    at(heads.box_scale, 0, 2, 4 + 7 * i) = 10.f;
    at(heads.box_scale, 1, 2, 4 + 7 * i) = 4.f;
  }
  const auto found = decodeMultiPose(heads, {640, 480}, 0.3f, 6);
  ASSERT_EQ(found.size(), 6u);
  for (size_t i = 1; i < found.size(); ++i) EXPECT_GE(found[i - 1].score, found[i].score);
  EXPECT_FLOAT_EQ(found[0].score, 0.77f);
  for (const Detection& d : found) {
    EXPECT_GE(d.box.y, 0);  // the 10-cell box around row 2 starts above the image
    EXPECT_LE(d.box.br().x, 640);
  }
}

TEST(MultiPoseDecode, NothingBelowThreshold) {
  MultiPoseHeads heads = emptyHeads();
  addPerson(heads, 0.25f);
  EXPECT_TRUE(decodeMultiPose(heads, {640, 480}, 0.3f).empty());
}

TEST(MultiPoseInput, KeepsTheAspectRatioInMultiplesOf32) {
  EXPECT_EQ(MultiPoseDetector::inputSize({640, 480}), cv::Size(256, 192));
  EXPECT_EQ(MultiPoseDetector::inputSize({480, 640}), cv::Size(192, 256));
  EXPECT_EQ(MultiPoseDetector::inputSize({256, 256}), cv::Size(256, 256));
  EXPECT_EQ(MultiPoseDetector::inputSize({1000, 20}), cv::Size(256, 32));
}
