// The tracker's motion along the floor (dynamics/object_tracker.hpp,
// objects.vertical_speed_sigma_mps): a walker's centre that bobs is not a walker that climbs;
// and its heading in the floor's plane (objects.heading_sigma_mps) comes from its points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "box_instance.hpp"
#include "dynamics/object_tracker.hpp"
#include "level_floor.hpp"

using namespace dynanav;

namespace {

constexpr double kFps = 30.0;
constexpr double kCameraAboveFloorM = 1.5;

struct Frame {
  cv::Mat depth_m;
  Instances instances;
};

/// A level camera 1.5 m above a floor (depth up to 4.5 m when `floor_in_view`, else none) and a
/// 0.4 m wide, 1.7 m tall body standing at (x_m, z_m) whose whole silhouette is raised by bob_m
/// (its front 0.15 m nearer than its centre); labels: the body's mask, id 1.
Frame walkerOnAFloor(double x_m, double z_m, double bob_m, bool floor_in_view,
                     const PinholeCamera& c) {
  Frame f;
  f.depth_m = floor_in_view ? test::levelFloorDepth(c, kCameraAboveFloorM, 4.5)
                            : cv::Mat(c.height, c.width, CV_32F, cv::Scalar(0.f));
  const double soles_y = kCameraAboveFloorM - bob_m, crown_y = soles_y - 1.7;
  const int top = int(std::lround(c.cy + c.fy * crown_y / z_m));
  const int bottom = std::min(c.height - 1, int(std::lround(c.cy + c.fy * soles_y / z_m)));
  const int left = int(std::lround(c.cx + c.fx * (x_m - 0.2) / z_m));
  const int right = int(std::lround(c.cx + c.fx * (x_m + 0.2) / z_m));
  f.instances = Instances::none(cv::Size(c.width, c.height));
  const cv::Rect box =
      cv::Rect(left, top, right - left + 1, bottom - top + 1) & cv::Rect(0, 0, c.width, c.height);
  f.depth_m(box).setTo(float(z_m - 0.15));
  test::addBoxInstance(f.instances, 1, "person", box);
  return f;
}

/// The largest vertical speed (m/s) the tracker reports over the last two of three seconds of a
/// walker crossing 3 m ahead at 1 m/s while its silhouette bobs 3 cm at 2 Hz (a gait's bob),
/// and its mean horizontal speed then.
struct Reported {
  double max_vertical_mps = 0.0;
  double mean_horizontal_mps = 0.0;
};

/// `empty_floor_frames` frames of the floor in view with nobody on it come first (stamps before
/// the walk's).
Reported walkAcross(double vertical_speed_sigma_mps, bool floor_in_view,
                    int empty_floor_frames = 0) {
  const PinholeCamera c;
  ObjectTrackingConfig config;
  config.vertical_speed_sigma_mps = vertical_speed_sigma_mps;
  ObjectTracker tracker(config, 5);
  const cv::Mat floor_depth_m = test::levelFloorDepth(c, kCameraAboveFloorM, 4.5);
  for (int i = 0; i < empty_floor_frames; ++i)
    tracker.track({i - empty_floor_frames, (i - empty_floor_frames) / kFps,
                   Instances::none(cv::Size(c.width, c.height)), FrameDynamics{}, cv::Mat(),
                   floor_depth_m, SE3::Identity(), true, c});
  Reported r;
  int counted = 0;
  for (int i = 0; i < 90; ++i) {
    const double t = i / kFps;
    const Frame f =
        walkerOnAFloor(-1.0 + t, 3.0, 0.03 * std::sin(2.0 * M_PI * 2.0 * t), floor_in_view, c);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    const auto out = tracker.track(
        {i, t, f.instances, dynamics, cv::Mat(), f.depth_m, SE3::Identity(), true, c});
    if (i < 30 || out.size() != 1) continue;
    const Vec3& v = out[0].v_world_mps;
    r.max_vertical_mps = std::max(r.max_vertical_mps, std::abs(v.y()));
    r.mean_horizontal_mps += std::hypot(v.x(), v.z());
    ++counted;
  }
  if (counted > 0) r.mean_horizontal_mps /= counted;
  return r;
}

}  // namespace

TEST(ObjectTracker, AWalkersBobIsNotReadAsVerticalVelocityWhenTheFloorIsInView) {
  const Reported along_floor = walkAcross(0.3, true);
  const Reported free = walkAcross(0.0, true);
  // Without the floor's constraint the filter follows part of the bob (0.38 m/s at its peak):
  // 0.14 m/s here, 0.04 with it.
  EXPECT_GT(free.max_vertical_mps, 0.1);
  EXPECT_LT(along_floor.max_vertical_mps, 0.5 * free.max_vertical_mps);
  // The walk itself is untouched (0.9 m/s on average: the filter, without flow here, takes the
  // first of these seconds to reach the walk's 1 m/s from its prior).
  EXPECT_NEAR(along_floor.mean_horizontal_mps, 1.0, 0.15);
  EXPECT_NEAR(along_floor.mean_horizontal_mps, free.mean_horizontal_mps, 0.02);
}

TEST(ObjectTracker, WithoutAFloorInViewTheVerticalVelocityIsLeftToTheMeasurements) {
  // The same walk with no depth below the walker (a floor out of view or out of range): no
  // floor, so no constraint; both settings report the same.
  const Reported along_floor = walkAcross(0.3, false);
  const Reported free = walkAcross(0.0, false);
  EXPECT_GT(free.max_vertical_mps, 0.1);
  EXPECT_DOUBLE_EQ(along_floor.max_vertical_mps, free.max_vertical_mps);
  EXPECT_DOUBLE_EQ(along_floor.mean_horizontal_mps, free.mean_horizontal_mps);
}

TEST(ObjectTracker, TheFloorSeenBeforeAnyoneEntersHoldsTheWalkerToItWhenItIsOutOfViewLater) {
  // The floor is followed from the run's start, not only while something is tracked: seen for a
  // second before the walker enters, it constrains the walk while no floor shows below him (the
  // simulated office's first walker entered behind a pin board, the floor unknown until then).
  const Reported along_floor = walkAcross(0.3, false, 30);
  const Reported free = walkAcross(0.0, false, 30);
  EXPECT_GT(free.max_vertical_mps, 0.1);
  EXPECT_LT(along_floor.max_vertical_mps, 0.5 * free.max_vertical_mps);
}

namespace {

/// The mean sideways (x) velocity the tracker reports over the last second of two for a walker
/// receding straight down the floor (z from 2.5 m at 1 m/s) whose points' flow says it also
/// drifts sideways at 0.3 m/s; the silhouette's centre says it does not.
double sidewaysReadOfARecedingWalker(double heading_sigma_mps) {
  const PinholeCamera c;
  ObjectTrackingConfig config;
  config.heading_sigma_mps = heading_sigma_mps;
  ObjectTracker tracker(config, 5);
  double sum = 0.0;
  int counted = 0;
  for (int i = 0; i < 60; ++i) {
    const double t = i / kFps, z_m = 2.5 + t;
    const Frame f = walkerOnAFloor(0.0, z_m, 0.0, true, c);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    // Half-resolution flow: 0.3 m/s sideways at the walker's front, per frame.
    const float dx_half = float(0.5 * c.fx * 0.3 / kFps / (z_m - 0.15));
    const cv::Mat flow_half =
        i > 0 ? cv::Mat(c.height / 2, c.width / 2, CV_32FC2, cv::Scalar(dx_half, 0.f)) : cv::Mat();
    const auto out = tracker.track(
        {i, t, f.instances, dynamics, flow_half, f.depth_m, SE3::Identity(), true, c});
    if (i < 30 || out.size() != 1) continue;
    sum += out[0].v_world_mps.x();
    ++counted;
  }
  return counted > 0 ? sum / counted : 0.0;
}

}  // namespace

TEST(ObjectTracker, AWalkersHeadingComesFromItsPointsOnceItsCentresCarryTheVelocity) {
  // After motion_velocity_frames of whole centres the points' velocity no longer enters; their
  // heading (the component across the direction of travel, here sideways) still does.
  const double with_heading = sidewaysReadOfARecedingWalker(0.3);
  const double without = sidewaysReadOfARecedingWalker(0.0);
  EXPECT_GT(with_heading, 0.1);        // 0.185
  EXPECT_LT(std::abs(without), 0.05);  // 0.001
}

TEST(ObjectTracker, AWalkerWhoStopsIsHeldThoughItsBodyRisesIntoAStandingPose) {
  // A walker crossing 3 m ahead at 1 m/s stops; in the two frames after the stop its points rise
  // at 0.3 m/s (a stride closing into a standing pose) with no motion along the floor. Its speed
  // is judged along the floor: two slow frames, and it is held still (stop_after_slow_frames);
  // judged in 3D, 0.3 m/s is no stop.
  const PinholeCamera c;
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  constexpr int kStopFrame = 40;  // the last frame it moved into
  double x_m = -1.0;
  std::vector<TrackedObject> out;
  for (int i = 0; i <= kStopFrame + 2; ++i) {
    const double t = i / kFps, z_m = 3.0;
    const Frame f = walkerOnAFloor(x_m, z_m, 0.0, true, c);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);  // the scene flow's verdict lags the stop
    const double front_m = z_m - 0.15;
    const bool rising = i > kStopFrame;
    const float dx_half = rising ? 0.f : float(0.5 * c.fx * 1.0 / kFps / front_m);
    const float dy_half = rising ? float(-0.5 * c.fy * 0.3 / kFps / front_m) : 0.f;
    const cv::Mat flow_half =
        i > 0 ? cv::Mat(c.height / 2, c.width / 2, CV_32FC2, cv::Scalar(dx_half, dy_half))
              : cv::Mat();
    out = tracker.track(
        {i, t, f.instances, dynamics, flow_half, f.depth_m, SE3::Identity(), true, c});
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    if (i == kStopFrame) {
      EXPECT_TRUE(out[0].dynamic);
    }
    if (i < kStopFrame) x_m += 1.0 / kFps;
  }
  EXPECT_FALSE(out[0].dynamic);
  EXPECT_EQ(out[0].speed_mps, 0.0);
}

namespace {

/// The speeds the tracker reports in the first `frames` frames of a walker crossing 3 m ahead at
/// `speed_mps`, its points' flow exact (the whole body in view from the first frame).
std::vector<double> firstSpeedsOfACrossingWalker(double speed_mps, double walking_speed_sigma_mps,
                                                 int frames) {
  const PinholeCamera c;
  ObjectTrackingConfig config;
  config.walking_speed_sigma_mps = walking_speed_sigma_mps;
  ObjectTracker tracker(config, 5);
  std::vector<double> speeds;
  for (int i = 0; i < frames; ++i) {
    const double t = i / kFps, z_m = 3.0, x_m = -1.0 + speed_mps * t;
    const Frame f = walkerOnAFloor(x_m, z_m, 0.0, true, c);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    const float dx_half = float(0.5 * c.fx * speed_mps / kFps / (z_m - 0.15));
    const cv::Mat flow_half =
        i > 0 ? cv::Mat(c.height / 2, c.width / 2, CV_32FC2, cv::Scalar(dx_half, 0.f)) : cv::Mat();
    const auto out = tracker.track(
        {i, t, f.instances, dynamics, flow_half, f.depth_m, SE3::Identity(), true, c});
    speeds.push_back(out.size() == 1 ? out[0].speed_mps : -1.0);
  }
  return speeds;
}

}  // namespace

TEST(ObjectTracker, AMovingPersonsFirstSpeedsStartFromAWalkersNotFromAStandstill) {
  // objects.walking_speed_mps (1.2 +- 0.4): once the points' motion gives a clear direction, the
  // speed along it is told a walker's, once, instead of the zero-mean prior's pull to a standstill.
  const auto walker = firstSpeedsOfACrossingWalker(1.2, 0.4, 12);
  const auto walker_zero_prior = firstSpeedsOfACrossingWalker(1.2, 0.0, 12);
  EXPECT_NEAR(walker[2], 1.2, 0.1);             // 1.120
  EXPECT_LT(walker_zero_prior[2], 1.2 - 0.12);  // 1.051
  EXPECT_LT(std::abs(walker[3] - 1.2), std::abs(walker_zero_prior[3] - 1.2));
  // A slow walker's direction is not clear before its velocity is known: no prior, the same
  // speeds (0.40, 0.43, 0.46, 0.50 m/s...).
  EXPECT_EQ(firstSpeedsOfACrossingWalker(0.5, 0.4, 12), firstSpeedsOfACrossingWalker(0.5, 0.0, 12));
  // Its cost: a hurrying walker (1.8 m/s) reads slower in its first frames, as a prior does.
  const auto hurrying = firstSpeedsOfACrossingWalker(1.8, 0.4, 12);
  const auto hurrying_zero_prior = firstSpeedsOfACrossingWalker(1.8, 0.0, 12);
  for (size_t i = 1; i < hurrying.size(); ++i) {
    EXPECT_LE(hurrying[i], hurrying_zero_prior[i] + 1e-9) << "frame " << i;
    EXPECT_GT(hurrying[i], hurrying_zero_prior[i] - 0.2) << "frame " << i;  // 0.18 at most
  }
}
