// Issue 18: fast head turns and nods (head-turns, head-turns-walkers) and motion blur over the
// colour camera's exposure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

SimOptions options(const std::string& scenario, float texels_per_m = 40.0f) {
  SimOptions o;
  o.scenario = scenario;
  o.photos = false;
  o.texels_per_m = texels_per_m;
  return o;
}

/// Heading (about room y) and elevation of the camera's viewing direction, in radians.
std::pair<double, double> headingAndElevation(const SE3& T_room_camera) {
  const Vec3 forward = T_room_camera.linear().col(2);
  return {std::atan2(forward.x(), forward.z()), std::asin(forward.y())};
}

TEST(SimHeadTurns, RaisedCosineTurnReachesItsAngleAndPeakRate) {
  const std::vector<HeadTurn> turns{{1.0, 0.8, 60 * kDeg, -20 * kDeg}};
  EXPECT_EQ(headTurnAngles(turns, 0.5).yaw_rad, 0.0);
  EXPECT_NEAR(headTurnAngles(turns, 1.4).yaw_rad, 30 * kDeg, 1e-12);  // half-way: half the angle
  EXPECT_NEAR(headTurnAngles(turns, 5.0).yaw_rad, 60 * kDeg, 1e-12);  // and keeps it
  EXPECT_NEAR(headTurnAngles(turns, 5.0).pitch_rad, -20 * kDeg, 1e-12);
  const double h = 1e-6;
  const double peak =
      (headTurnAngles(turns, 1.4 + h).yaw_rad - headTurnAngles(turns, 1.4 - h).yaw_rad) / (2 * h);
  EXPECT_NEAR(peak, headTurnPeakRate(60 * kDeg, 0.8), 1e-6);
  EXPECT_NEAR(peak / kDeg, 150.0, 1e-4);
  // No jerk into the turn: the rate starts at zero.
  EXPECT_NEAR(headTurnAngles(turns, 1.0 + 1e-3).yaw_rad, 0.0, 1e-6);
}

TEST(SimHeadTurns, ScenariosReachThePeakYawAndPitchRates) {
  for (const std::string name : {"head-turns", "head-turns-walkers"}) {
    Simulator sim(options(name));
    const Scene& scene = sim.scene();
    const double dt = 1e-3;
    double max_yaw = 0, max_pitch = 0;
    for (double t = dt; t < scene.duration_s; t += dt) {
      const auto [h0, e0] = headingAndElevation(scene.T_room_camera(t - dt));
      const auto [h1, e1] = headingAndElevation(scene.T_room_camera(t));
      max_yaw = std::max(max_yaw, std::abs(std::remainder(h1 - h0, 2 * M_PI)) / dt / kDeg);
      max_pitch = std::max(max_pitch, std::abs(e1 - e0) / dt / kDeg);
    }
    // The scripted peaks plus a little walking sway and look-around (the path is straight).
    EXPECT_GT(max_yaw, 0.98 * script::kHeadTurnPeakYawDegPs) << name;
    EXPECT_LT(max_yaw, 1.15 * script::kHeadTurnPeakYawDegPs) << name;
    EXPECT_GT(max_pitch, 0.95 * script::kHeadNodPeakDegPs) << name;
    EXPECT_LT(max_pitch, 1.15 * script::kHeadNodPeakDegPs) << name;
    // The head ends facing the walking direction again.
    const HeadTurnAngles end = headTurnAngles(scene.head.turns, scene.duration_s);
    EXPECT_NEAR(end.yaw_rad, 0.0, 1e-12) << name;
    EXPECT_NEAR(end.pitch_rad, 0.0, 1e-12) << name;
  }
  Simulator walkers(options("head-turns-walkers"));
  EXPECT_EQ(walkers.scene().movers.size(), 2u);
  Simulator alone(options("head-turns"));
  EXPECT_TRUE(alone.scene().movers.empty());
}

/// Mean absolute difference of neighbouring pixels along x (dx = 1) or y, over the grey image.
double meanGradient(const cv::Mat& bgr, bool along_x) {
  cv::Mat grey, d;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_32F);
  const cv::Mat a = along_x ? grey.colRange(1, grey.cols) : grey.rowRange(1, grey.rows);
  const cv::Mat b = along_x ? grey.colRange(0, grey.cols - 1) : grey.rowRange(0, grey.rows - 1);
  cv::absdiff(a, b, d);
  return cv::mean(d)[0];
}

TEST(SimMotionBlur, ExposureSmearsAlongTheImageMotionOnly) {
  // Frame 57 (t = 1.9 s) is the middle of the first 60-degree turn: 150 deg/s about the vertical,
  // so the image moves sideways by 2.62 rad/s x 525 px x 10 ms = 13.7 px during the exposure.
  SimOptions sharp_options = options("head-turns", 200.0f);
  sharp_options.noiseless = true;
  SimOptions blurred_options = sharp_options;
  blurred_options.exposure_s = 0.010;
  Simulator sharp_sim(sharp_options), blurred_sim(blurred_options);
  const int i = 57;
  const double t = sharp_sim.stamp(i);
  EXPECT_EQ(exposureSamples(sharp_sim.scene(), sharp_sim.camera(), t, 0.0), 1);
  const int n = exposureSamples(sharp_sim.scene(), sharp_sim.camera(), t, 0.010);
  EXPECT_GE(n, 10);  // 13.7 px / 1.5 px steps
  EXPECT_LE(n, kMaxExposureSamples);
  const SimFrame sharp = sharp_sim.render(i), blurred = blurred_sim.render(i);
  const double gx_sharp = meanGradient(sharp.bgr, true), gx_blur = meanGradient(blurred.bgr, true);
  const double gy_sharp = meanGradient(sharp.bgr, false),
               gy_blur = meanGradient(blurred.bgr, false);
  // Diagonal texture loses some vertical contrast to a sideways smear too, but far less.
  const double kept_x = gx_blur / gx_sharp, kept_y = gy_blur / gy_sharp;
  EXPECT_LT(kept_x, 0.6) << "horizontal detail smeared by the turn";
  EXPECT_LT(kept_x, 0.75 * kept_y)
      << "the smear is along the motion (sideways): x " << kept_x << ", y " << kept_y;
  // Averaging keeps the brightness; depth and masks stay those of the frame's instant.
  EXPECT_NEAR(cv::mean(blurred.bgr)[0], cv::mean(sharp.bgr)[0], 1.5);
  EXPECT_EQ(cv::norm(blurred.depth_true_m, sharp.depth_true_m, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::countNonZero(blurred.instance != sharp.instance), 0);
  // Deterministic: the same frame again gives the same bytes.
  Simulator again_sim(blurred_options);
  const SimFrame again = again_sim.render(i);
  EXPECT_EQ(cv::countNonZero(cv::Mat(again.bgr != blurred.bgr).reshape(1)), 0);
}

TEST(SimMotionBlur, ExposureLongerThanTheFramePeriodIsRejected) {
  SimOptions o = options("head-turns");
  o.exposure_s = 0.05;  // 30 fps: 33 ms
  EXPECT_THROW(Simulator{o}, InputError);
}

}  // namespace
}  // namespace dynanav::sim
