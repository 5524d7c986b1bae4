#include <gtest/gtest.h>

#include "core/camera.hpp"
#include "core/se3.hpp"
#include "core/timer.hpp"

using namespace dynanav;

TEST(Camera, ProjectBackprojectRoundTrip) {
  const PinholeCamera cam = PinholeCamera::tumFreiburg3();
  const Vec3 p(0.3, -0.2, 2.5);
  const Eigen::Vector2d uv = cam.project(p);
  const Vec3 back = cam.backproject(uv.x(), uv.y(), p.z());
  EXPECT_LT((back - p).norm(), 1e-12);
}

TEST(Camera, UndistortInvertsDistort) {
  const PinholeCamera cam = PinholeCamera::tumFreiburg1();
  ASSERT_TRUE(cam.isDistorted());
  std::vector<cv::Point2f> distorted;
  const std::vector<cv::Point2d> truth = {{100, 80}, {320, 240}, {600, 450}, {20, 400}};
  for (const auto& p : truth) distorted.push_back(cam.distortPixel(p));
  const auto undistorted = cam.undistortPixels(distorted);
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_NEAR(undistorted[i].x, truth[i].x, 0.05);
    EXPECT_NEAR(undistorted[i].y, truth[i].y, 0.05);
  }
}

TEST(Camera, FromSequenceName) {
  PinholeCamera cam;
  ASSERT_TRUE(PinholeCamera::fromSequenceName("rgbd_dataset_freiburg1_xyz", cam));
  EXPECT_NEAR(cam.fx, 517.306408, 1e-9);
  ASSERT_TRUE(PinholeCamera::fromSequenceName("rgbd_bonn_crowd", cam));
  EXPECT_NEAR(cam.fx, 542.822841, 1e-9);
  ASSERT_TRUE(PinholeCamera::fromSequenceName("rgbd_dataset_freiburg3_walking_xyz", cam));
  EXPECT_FALSE(cam.isDistorted());
  EXPECT_FALSE(PinholeCamera::fromSequenceName("my_office", cam));
}

TEST(SE3, ExpLogAndAngle) {
  const Vec3 omega(0.1, -0.2, 0.3);
  const Mat3 R = expSO3(omega);
  EXPECT_LT((logSO3(R) - omega).norm(), 1e-12);
  EXPECT_NEAR(rotationAngle(R), omega.norm(), 1e-12);
  EXPECT_NEAR(rotationAngle(expSO3(Vec3(0, 0, M_PI - 1e-9))), M_PI, 1e-6);
}

TEST(Timer, SummaryPercentiles) {
  const TimingSummary s = summarize({5, 1, 2, 3, 4, 6, 7, 8, 9, 10});
  EXPECT_DOUBLE_EQ(s.mean_ms, 5.5);
  EXPECT_DOUBLE_EQ(s.p95_ms, 10);
  EXPECT_DOUBLE_EQ(s.max_ms, 10);
  StageTimers timers;
  { ScopedTimer t(timers, "stage"); }
  EXPECT_EQ(timers.summary().at("stage").count, 1u);
  EXPECT_GT(peakRssMb(), 0.0);
}
