// The Kinect-like sensor models, and the simulator's determinism.
#include <gtest/gtest.h>

#include "sim/sensor.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {
namespace {

TEST(SimSensor, DepthNoiseGrowsWithDistanceAndIsQuantised) {
  DepthSensorModel model;
  model.holes_per_frame = 0;
  model.dropout_probability = 0.0;
  const double bf = model.focal_px * model.baseline_m;
  for (double z : {1.0, 2.0, 3.5}) {
    const cv::Mat truth(120, 160, CV_32F, cv::Scalar(z));
    const cv::Mat noisy = simulateDepth(truth, model, 7, 0);
    cv::Mat valid = noisy > 0;
    // The border has no 3x3 neighbourhood of equal depth in the dilation: still valid (constant).
    ASSERT_EQ(cv::countNonZero(valid), truth.rows * truth.cols) << z;
    cv::Scalar mean, stddev;
    cv::meanStdDev(noisy, mean, stddev);
    EXPECT_NEAR(mean[0], z, 0.005 + 0.2 * model.sigma(z)) << z;
    // Quantisation adds up to step/sqrt(12) in depth: z^2 / bf * step / sqrt(12).
    const double quant = z * z / bf * model.disparity_step_px / std::sqrt(12.0);
    const double expected = std::hypot(model.sigma(z), quant);
    EXPECT_GT(stddev[0], 0.6 * expected) << z;
    EXPECT_LT(stddev[0], 1.5 * expected) << z;
    // Every value lies on the disparity grid.
    for (int i = 0; i < 50; ++i) {
      const double d = bf / noisy.at<float>(i, i) / model.disparity_step_px;
      EXPECT_NEAR(d, std::round(d), 1e-3);
    }
  }
}

TEST(SimSensor, NoDepthOutOfRangeOrAtDiscontinuities) {
  DepthSensorModel model;
  model.holes_per_frame = 0;
  model.dropout_probability = 0.0;
  cv::Mat truth(100, 100, CV_32F, cv::Scalar(2.0));
  truth(cv::Rect(50, 0, 50, 100)) = 3.0;  // a 1 m step at column 50
  truth(cv::Rect(0, 80, 100, 20)) = 5.0;  // beyond the 4.5 m range
  truth(cv::Rect(0, 0, 100, 5)) = 0.3;    // too close
  const cv::Mat noisy = simulateDepth(truth, model, 1, 0);
  for (int y = 10; y < 70; ++y) {
    EXPECT_EQ(noisy.at<float>(y, 49), 0.0f);
    EXPECT_EQ(noisy.at<float>(y, 50), 0.0f);
    EXPECT_GT(noisy.at<float>(y, 40), 0.0f);
    EXPECT_GT(noisy.at<float>(y, 60), 0.0f);
  }
  EXPECT_EQ(cv::countNonZero(noisy(cv::Rect(0, 82, 100, 18))), 0);
  EXPECT_EQ(cv::countNonZero(noisy(cv::Rect(0, 0, 100, 5))), 0);
}

TEST(SimSensor, HolesAndDropoutsRemoveAFewPixels) {
  DepthSensorModel model;
  const cv::Mat truth(480, 640, CV_32F, cv::Scalar(2.0));
  const cv::Mat noisy = simulateDepth(truth, model, 3, 5);
  const int invalid = int(truth.total()) - cv::countNonZero(noisy);
  EXPECT_GT(invalid, int(0.5 * model.dropout_probability * double(truth.total())));
  EXPECT_LT(invalid, int(0.02 * double(truth.total())));
}

SimOptions small(uint64_t seed) {
  SimOptions o;
  o.scenario = "office";
  o.seed = seed;
  o.photos = false;
  o.texels_per_m = 100.0f;
  return o;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

TEST(SimDeterminism, SameSeedSameImagesOtherSeedOtherImages) {
  Simulator a(small(5)), b(small(5)), c(small(6));
  const SimFrame fa = a.render(40), fb = b.render(40), fc = c.render(40);
  EXPECT_TRUE(same(fa.bgr, fb.bgr));
  EXPECT_TRUE(same(fa.depth_m, fb.depth_m));
  EXPECT_TRUE(same(fa.instance, fb.instance));
  EXPECT_EQ(fa.objects.dump(), fb.objects.dump());
  EXPECT_FALSE(same(fa.bgr, fc.bgr));
  EXPECT_FALSE(same(fa.depth_m, fc.depth_m));
  // The choreography does not depend on the seed: same poses and masks.
  EXPECT_TRUE(fa.T_world_camera.isApprox(fc.T_world_camera, 1e-12));
}

TEST(SimDeterminism, RenderingOrderDoesNotMatter) {
  Simulator a(small(9)), b(small(9));
  (void)a.render(10);
  const SimFrame late = a.render(30);
  const SimFrame direct = b.render(30);
  EXPECT_TRUE(same(late.bgr, direct.bgr));
  EXPECT_TRUE(same(late.depth_m, direct.depth_m));
}

TEST(SimFrames, EveryScenarioRendersPlausibleFrames) {
  for (const auto& info : scenarioList()) {
    SimOptions o;
    o.scenario = info.name;
    o.photos = false;
    o.texels_per_m = 80.0f;
    Simulator sim(o);
    for (int i : {0, sim.frameCount() - 1}) {
      const SimFrame f = sim.render(i);
      ASSERT_EQ(f.bgr.size(), cv::Size(640, 480));
      // The room surrounds the camera: every pixel hits something, and enough depth is valid.
      EXPECT_EQ(cv::countNonZero(f.depth_true_m), 640 * 480) << info.name << " frame " << i;
      EXPECT_GT(cv::countNonZero(f.depth_m), 640 * 480 / 5) << info.name << " frame " << i;
      cv::Scalar mean, stddev;
      cv::meanStdDev(f.bgr, mean, stddev);
      EXPECT_GT(stddev[1], 20.0) << info.name << ": images need contrast";
      EXPECT_EQ(f.objects["objects"].size(), sim.scene().movers.size());
    }
  }
}

}  // namespace
}  // namespace dynanav::sim
