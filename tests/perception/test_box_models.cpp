// Geometry of the per-box crops and MoveNet's decoding, on synthetic inputs with known answers.
#include <gtest/gtest.h>

#include "perception/box_models.hpp"

using namespace dynanav;

namespace {

TEST(BoxCrops, SquareIsCentredAndScaled) {
  const cv::Rect2f sq = squareAround(cv::Rect(100, 50, 40, 100), 1.25);
  EXPECT_FLOAT_EQ(sq.width, 125.f);
  EXPECT_FLOAT_EQ(sq.height, 125.f);
  EXPECT_FLOAT_EQ(sq.x + sq.width / 2, 120.f);
  EXPECT_FLOAT_EQ(sq.y + sq.height / 2, 100.f);
}

TEST(BoxCrops, WarpSquareMapsPixelsAndPadsWithZero) {
  // A white pixel block at (60..63, 20..23) in a 100x80 image; square (40, 0, 80, 80) → 160 px.
  cv::Mat image = cv::Mat::zeros(80, 100, CV_8UC3);
  image(cv::Rect(60, 20, 4, 4)).setTo(cv::Scalar::all(255));
  const cv::Mat crop = warpSquare(image, cv::Rect2f(40, 0, 80, 80), 160);
  ASSERT_EQ(crop.size(), cv::Size(160, 160));
  // Image x = 61.5 → crop (61.5 - 40) * 2 = 43; y = 21.5 → 43.
  EXPECT_EQ(crop.at<cv::Vec3b>(43, 43), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(crop.at<cv::Vec3b>(43, 150), cv::Vec3b(0, 0, 0));  // beyond the image's right edge
}

cv::Mat blob(int channels, int h, int w, float value = 0.f) {
  const int size[] = {1, channels, h, w};
  return cv::Mat(4, size, CV_32F, cv::Scalar(value));
}

float& at(cv::Mat& b, int c, int y, int x) { return b.ptr<float>(0, c)[y * b.size[3] + x]; }

TEST(MoveNetDecode, FollowsCentreRegressionHeatmapAndOffset) {
  constexpr int kGrid = 48;
  cv::Mat heat = blob(17, kGrid, kGrid, 0.05f), centre = blob(1, kGrid, kGrid, 0.01f);
  cv::Mat regress = blob(34, kGrid, kGrid), offset = blob(34, kGrid, kGrid);
  at(centre, 0, 20, 25) = 0.9f;  // the person's centre
  at(centre, 0, 5, 5) = 0.95f;   // a stronger but far-off centre loses to distance weighting
  for (int k = 0; k < 17; ++k) {
    const int ky = 10 + k, kx = 30 - k;  // where keypoint k is
    at(regress, 2 * k, 20, 25) = float(ky - 20);
    at(regress, 2 * k + 1, 20, 25) = float(kx - 25);
    at(heat, k, ky, kx) = 0.8f;
    at(heat, k, 45, 2) = 0.9f;  // a distractor far from the regressed position
    at(offset, 2 * k, ky, kx) = 0.25f;
    at(offset, 2 * k + 1, ky, kx) = -0.5f;
  }
  const BodyKeypoints k = decodeMoveNet(heat, centre, regress, offset);
  for (int i = 0; i < 17; ++i) {
    EXPECT_NEAR(k.points[size_t(i)].pixel.y, (10 + i + 0.25f) / kGrid, 1e-5) << i;
    EXPECT_NEAR(k.points[size_t(i)].pixel.x, (30 - i - 0.5f) / kGrid, 1e-5) << i;
    EXPECT_FLOAT_EQ(k.points[size_t(i)].score, 0.8f) << i;
  }
}

}  // namespace
