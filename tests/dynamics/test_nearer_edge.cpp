// Points beside a nearer surface (dynamics/object_points.hpp, besideNearerSurface) and the
// tracker's motion fitted without them (objects.motion_skips_nearer_edge): the dense flow's
// patches there carry the nearer surface's motion.
#include <gtest/gtest.h>

#include <map>

#include "box_instance.hpp"
#include "dynamics/object_points.hpp"
#include "dynamics/object_tracker.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

/// A person (label 1) standing 4 m away in columns [left, right), rows [120, 360), with a 5 cm
/// relief; a nearer surface (no label, 2.5 m) in columns [left - 50, left); 6 m of wall elsewhere.
struct Scene {
  Instances instances;
  cv::Mat depth_m;
};

Scene standingBesideNearer(int left, int right) {
  Scene s;
  s.instances = Instances::none(cv::Size(kW, kH));
  s.depth_m = cv::Mat(kH, kW, CV_32F, cv::Scalar(6.0f));
  s.depth_m(cv::Rect(left - 50, 100, 50, 300)).setTo(2.5f);
  const cv::Rect box(left, 120, right - left, 240);
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x)
      s.depth_m.at<float>(y, x) = 4.0f + 0.05f * float(x % 7) / 7.f + 0.02f * float(y % 5);
  test::addBoxInstance(s.instances, 1, "person", box);
  return s;
}

}  // namespace

TEST(ObjectPoints, APointWithinTheFlowsReachOfANearerSurfaceIsBesideIt) {
  const Scene s = standingBesideNearer(300, 400);
  const std::vector<cv::Point2f> pixels = {
      {305, 200}, {314, 200}, {330, 200}, {395, 200}, {350, 200}};
  std::vector<float> z;
  for (const auto& p : pixels) z.push_back(depthAt(s.depth_m, p));
  z[4] = 0.f;  // no depth: never flagged
  const auto found = [](const std::vector<NearerSurface>& beside) {
    std::vector<uint8_t> flags;
    for (const NearerSurface& b : beside) flags.push_back(b.found ? 1 : 0);
    return flags;
  };
  const std::vector<NearerSurface> beside =
      besideNearerSurface(pixels, z, s.instances.labels, 1, s.depth_m, 16, 0.5);
  // 5 and 14 px from the nearer surface: within reach; 30 px: beyond; beside the farther wall:
  // not nearer.
  EXPECT_EQ(found(beside), (std::vector<uint8_t>{1, 1, 0, 0, 0}));
  EXPECT_EQ(beside[0].label, 0);  // the nearer surface is the static scene (no instance)
  // The object's own nearer parts (an arm in front of the body) do not count: same label.
  cv::Mat own_arm = s.depth_m.clone();
  own_arm(cv::Rect(340, 150, 10, 100)).setTo(3.0f);
  const std::vector<cv::Point2f> beside_arm = {{355, 200}};
  EXPECT_EQ(found(besideNearerSurface(beside_arm, {depthAt(own_arm, beside_arm[0])},
                                      s.instances.labels, 1, own_arm, 16, 0.5)),
            std::vector<uint8_t>{0});
  // Reach 0: nothing is flagged.
  EXPECT_EQ(found(besideNearerSurface(pixels, z, s.instances.labels, 1, s.depth_m, 0, 0.5)),
            std::vector<uint8_t>(pixels.size(), 0));
}

TEST(ObjectPoints, OfTwoNearerSurfacesBesideAPointTheNearerIsGiven) {
  // A person 4 m away with a second instance (label 2, 3 m) on its left and the static scene
  // (2.5 m) on its right, both within reach of a point between them.
  Scene s = standingBesideNearer(300, 330);
  s.depth_m(cv::Rect(330, 100, 40, 300)).setTo(3.0f);
  s.depth_m(cv::Rect(250, 100, 50, 300)).setTo(2.5f);
  test::addBoxInstance(s.instances, 2, "person", cv::Rect(330, 100, 40, 300));
  const std::vector<cv::Point2f> pixel = {{322, 200}};
  const std::vector<NearerSurface> beside = besideNearerSurface(
      pixel, {depthAt(s.depth_m, pixel[0])}, s.instances.labels, 1, s.depth_m, 32, 0.5);
  ASSERT_TRUE(beside[0].found);
  EXPECT_EQ(beside[0].label, 0);  // the static scene at 2.5 m, nearer than the person at 3 m
  // Only the person within reach: it is given.
  const std::vector<NearerSurface> only_person = besideNearerSurface(
      pixel, {depthAt(s.depth_m, pixel[0])}, s.instances.labels, 1, s.depth_m, 16, 0.5);
  ASSERT_TRUE(only_person[0].found);
  EXPECT_EQ(only_person[0].label, 2);
}

TEST(ObjectTracker, AStandingPersonBesideANearerSurfaceDoesNotTakeItsMotion) {
  // A person stands 4 m away, 26 px of it in view beside a nearer surface. The dense flow's
  // patches straddle both: the person's pixels within 16 px of the nearer surface (the flow's
  // reach at finest scale 1) carry its image motion, 6 px per frame, as DIS's do there. Those
  // are most of the person's points; fitted with them its rigid motion reads their 1.4 m/s
  // (the filter, 8 frames on from its 0 +- 1 m/s prior, half of that).
  const Scene s = standingBesideNearer(300, 326);
  cv::Mat flow_half(kH / 2, kW / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
  flow_half(cv::Rect(125, 0, 25, kH / 2)).setTo(cv::Scalar(3.f, 0.f));  // full-size x 250-299
  flow_half(cv::Rect(150, 0, 8, kH / 2)).setTo(cv::Scalar(3.f, 0.f));   // the person's 300-315
  const auto speedAfter = [&](bool skip_nearer_edge) {
    ObjectTrackingConfig config;
    config.motion_skips_nearer_edge = skip_nearer_edge;
    ObjectTracker tracker(config, 5);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    std::vector<TrackedObject> out;
    for (int i = 0; i < 8; ++i)
      out = tracker.track({i, i / 30.0, s.instances, dynamics, flow_half, s.depth_m,
                           SE3::Identity(), true, PinholeCamera{}});
    return out.size() == 1 ? out[0].speed_mps : -1.0;
  };
  EXPECT_LT(speedAfter(true), 0.15);
  EXPECT_GT(speedAfter(false), 0.35);  // without the rule it takes that motion
}

TEST(ObjectTracker, APersonAllBesideANearerMoverDoesNotTakeItsMotion) {
  // A person stands 4 m away, 14 px of it in view beside a nearer walker (another instance,
  // 2.5 m away) whom the flow moves 6 px per frame. Every point of the standing person lies
  // within the flow's reach of the walker, so the flow carries the walker's motion onto all of
  // them (1.4 m/s at 4 m): too few clear points to fit without them. Beside a surface tracked
  // moving, no motion is fitted; beside a static one (rule off) the flow would be fitted as the
  // person's own.
  Scene s = standingBesideNearer(300, 314);
  test::addBoxInstance(s.instances, 2, "person", cv::Rect(250, 100, 50, 300));
  cv::Mat flow_half(kH / 2, kW / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
  flow_half(cv::Rect(125, 0, 32, kH / 2)).setTo(cv::Scalar(3.f, 0.f));  // full-size x 250-313
  const auto speedsAfter = [&](bool not_beside_movers) {
    ObjectTrackingConfig config;
    config.motion_not_beside_movers = not_beside_movers;
    ObjectTracker tracker(config, 5);
    FrameDynamics dynamics;
    dynamics.moving_ids = {1, 2};
    std::vector<TrackedObject> out;
    for (int i = 0; i < 8; ++i)
      out = tracker.track({i, i / 30.0, s.instances, dynamics, flow_half, s.depth_m,
                           SE3::Identity(), true, PinholeCamera{}});
    std::map<uint64_t, double> speed;
    for (const TrackedObject& o : out) speed[o.id] = o.speed_mps;
    return speed;
  };
  const std::map<uint64_t, double> with_rule = speedsAfter(true);
  const std::map<uint64_t, double> without = speedsAfter(false);
  ASSERT_EQ(with_rule.size(), 2u);
  ASSERT_EQ(without.size(), 2u);
  // Ids in instance order: 1 the standing person, 2 the walker (tracked moving either way).
  EXPECT_GT(with_rule.at(2), 0.25);
  EXPECT_LT(with_rule.at(1), 0.15);
  EXPECT_GT(without.at(1), 0.35);
}
