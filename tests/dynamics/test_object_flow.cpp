// One object's own flow (dynamics/object_flow.hpp): the background set to a flat grey so DIS's
// patches read the object's motion, not an average with what lies around it.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "dynamics/object_flow.hpp"
#include "dynamics/object_tracker.hpp"
#include "perception/frame_prep.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

/// A strongly textured background moved `background_dx` px and a faintly textured object as
/// bright on average (label 1, 40 x 200 px: a walker seen side on, 4 m away in front of a wall
/// at 6 m) at column `object_x`, both full size.
struct Frame {
  cv::Mat grey_half, labels, depth_m;
};

Frame frame(int background_dx, int object_x) {
  cv::Mat wall(kH, kW + 64, CV_8U);
  cv::RNG rng(7);
  rng.fill(wall, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(wall, wall, cv::Size(5, 5), 1.5);
  cv::Mat shirt(200, 40, CV_8U);
  cv::RNG rng_shirt(11);
  rng_shirt.fill(shirt, cv::RNG::UNIFORM, 112, 145);  // as bright as the wall, faint texture
  cv::GaussianBlur(shirt, shirt, cv::Size(5, 5), 1.5);
  Frame f;
  cv::Mat grey = wall(cv::Rect(32 - background_dx, 0, kW, kH)).clone();
  const cv::Rect box(object_x, 140, 40, 200);
  shirt.copyTo(grey(box));
  cv::resize(grey, f.grey_half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  f.labels = cv::Mat(kH, kW, CV_16U, cv::Scalar(0));
  f.labels(box).setTo(1);
  f.depth_m = cv::Mat(kH, kW, CV_32F, cv::Scalar(6.0f));
  for (int y = box.y; y < box.br().y; ++y)  // 4 m, a relief of 5 cm that moves with it
    for (int x = box.x; x < box.br().x; ++x)
      f.depth_m.at<float>(y, x) = 4.0f + 0.05f * float((x - object_x) % 9) / 9.f;
  return f;
}

cv::Ptr<cv::DISOpticalFlow> sharedFlowDis() {  // FramePrep's settings
  auto dis = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
  dis->setPatchSize(kSharedFlowPatchPx);
  dis->setFinestScale(1);
  return dis;
}

/// Mean horizontal motion (full-size px) of the object's inner pixels in the previous frame.
template <class Carry>
double meanObjectMotion(Carry carry) {
  double sum = 0.0;
  int n = 0;
  for (int y = 160; y < 320; y += 5)
    for (int x = 305; x < 335; x += 5) {
      cv::Point2f px{float(x), float(y)};
      if (!carry(px)) continue;
      sum += px.x - float(x);
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

}  // namespace

TEST(ObjectFlow, ReadsTheObjectsOwnMotionWhereTheSharedFlowAveragesInTheBackground) {
  // The camera turns (the background moves 2 px left), the walker moves 8 px right.
  const Frame a = frame(0, 300), b = frame(-2, 308);
  cv::Mat shared;
  sharedFlowDis()->calc(a.grey_half, b.grey_half, shared);
  const double shared_dx = meanObjectMotion([&](cv::Point2f& px) {
    const cv::Point2f d = shared.at<cv::Point2f>(int(px.y) / 2, int(px.x) / 2);
    px += 2.0f * d;
    return true;
  });
  auto dis = sharedFlowDis();
  const CroppedFlow own = objectFlow({a.grey_half, a.labels, 1, a.depth_m, 3.5},
                                     {b.grey_half, b.labels, 1, b.depth_m, 3.5},
                                     cv::Rect(300, 140, 48, 200), {0, 0}, 16, 64, *dis);
  ASSERT_FALSE(own.flow_half.empty());
  const double own_dx = meanObjectMotion(
      [&](cv::Point2f& px) { return carryByCroppedFlow(own, cv::Size(kW, kH), px); });
  EXPECT_LT(shared_dx, 7.0);      // the background's motion averaged in
  EXPECT_NEAR(own_dx, 8.0, 0.5);  // the object's own
}

TEST(ObjectFlow, TheBackgroundIsFlatGreyANearerSurfaceKeepsItsImage) {
  Frame f = frame(0, 300);
  f.depth_m(cv::Rect(260, 100, 40, 300)).setTo(2.0f);  // a pillar in front, left of the object
  const cv::Rect crop_half(120, 60, 60, 120);          // full size: x 240-360, y 120-360
  const cv::Mat crop = objectCrop({f.grey_half, f.labels, 1, f.depth_m, 3.5}, crop_half, 200);
  const auto at = [&](int x_full, int y_full) {
    return crop.at<uint8_t>(y_full / 2 - crop_half.y, x_full / 2 - crop_half.x);
  };
  const auto original = [&](int x_full, int y_full) {
    return f.grey_half.at<uint8_t>(y_full / 2, x_full / 2);
  };
  EXPECT_EQ(at(244, 200), 200);                 // background (6 m): flat grey
  EXPECT_EQ(at(320, 200), original(320, 200));  // the object
  EXPECT_EQ(at(270, 200), original(270, 200));  // the pillar (2 m, nearer than 3.5): kept
  // Without a depth limit, the pillar is background too.
  const cv::Mat flat = objectCrop({f.grey_half, f.labels, 1, f.depth_m, 0.0}, crop_half, 200);
  EXPECT_EQ(flat.at<uint8_t>(200 / 2 - crop_half.y, 270 / 2 - crop_half.x), 200);
}

TEST(ObjectFlow, NoFlowWithoutTheObjectInBothFramesOrOnATinyCrop) {
  const Frame a = frame(0, 300), b = frame(0, 304);
  auto dis = sharedFlowDis();
  const cv::Rect box(300, 140, 44, 200);
  EXPECT_TRUE(objectFlow({a.grey_half, a.labels, 2, a.depth_m, 0.0},
                         {b.grey_half, b.labels, 1, b.depth_m, 0.0}, box, {0, 0}, 16, 64, *dis)
                  .flow_half.empty());  // label 2 is nowhere
  EXPECT_TRUE(objectFlow({a.grey_half, a.labels, 1, a.depth_m, 0.0},
                         {b.grey_half, b.labels, 1, b.depth_m, 0.0}, cv::Rect(0, 0, 4, 4), {0, 0},
                         0, 64,
                         *dis)
                  .flow_half.empty());  // smaller than DIS's patches at its finest level
  const CroppedFlow own =
      objectFlow({a.grey_half, a.labels, 1, a.depth_m, 0.0},
                 {b.grey_half, b.labels, 1, b.depth_m, 0.0}, box, {0, 0}, 16, 64, *dis);
  ASSERT_FALSE(own.flow_half.empty());
  cv::Point2f outside(10.f, 10.f);  // beyond the crop: not carried
  EXPECT_FALSE(carryByCroppedFlow(own, cv::Size(kW, kH), outside));
}

TEST(ObjectTracker, ABoxIsCarriedByItsOwnFlowWhereTheSharedFlowAveragesInTheBackground) {
  // The scene above as a tracked box (an object that does not move by itself: its rigid motion
  // always enters the filter) moving 8 px per frame at 4 m, 1.83 m/s, while the background
  // moves 2 px the other way; the shared flow is DIS between the frames, as FramePrep makes it.
  const double truth_mps = 8.0 * 4.0 / 525.0 * 30.0;
  const auto speedAfterSixFrames = [&](bool own_flow) {
    ObjectTrackingConfig config;
    config.own_flow = own_flow;
    ObjectTracker tracker(config, 5, {"person"});
    const PinholeCamera camera;  // fx = fy = 525, no distortion
    const SE3 T_world_camera = SE3::Identity();
    FrameDynamics dynamics;
    dynamics.moving_ids = {1};
    cv::Mat previous_half;
    double speed = 0.0;
    for (int i = 0; i < 7; ++i) {
      Frame f = frame(-2 * i, 200 + 8 * i);
      Instances instances = Instances::none(cv::Size(kW, kH));
      Instance box;
      box.id = 1;
      box.class_name = "box";
      box.box = cv::Rect(200 + 8 * i, 140, 40, 200);
      instances.labels = f.labels;
      instances.items.push_back(box);
      cv::Mat shared;
      if (!previous_half.empty()) sharedFlowDis()->calc(previous_half, f.grey_half, shared);
      const auto out = tracker.track({i, i / 30.0, instances, dynamics, shared, f.depth_m,
                                      T_world_camera, true, camera, f.grey_half});
      if (out.size() == 1) speed = out[0].speed_mps;
      previous_half = f.grey_half;
    }
    return speed;
  };
  EXPECT_NEAR(speedAfterSixFrames(true), truth_mps, 0.15 * truth_mps);
  EXPECT_LT(speedAfterSixFrames(false), 0.8 * truth_mps);  // the background's motion averaged in
}

TEST(ObjectFlow, TheShiftIsTheMedianFlowAndTheObjectsDepthTheMedianOfItsMask) {
  // Half-size flow: 3 px right everywhere but a 5 px jump at one of the three pixels.
  cv::Mat flow(kH / 2, kW / 2, CV_32FC2, cv::Scalar(3.f, -1.f));
  flow.at<cv::Point2f>(50, 50) = {5.f, 0.f};
  const std::vector<cv::Point2f> pixels = {{100.f, 100.f}, {200.f, 120.f}, {300.f, 140.f}};
  EXPECT_EQ(medianShiftHalf(flow, cv::Size(kW, kH), pixels), cv::Point(3, -1));
  EXPECT_EQ(medianShiftHalf(cv::Mat(), cv::Size(kW, kH), pixels), cv::Point(0, 0));
  const Frame f = frame(0, 300);  // the object at 4.00-4.05 m in front of a 6 m wall
  EXPECT_NEAR(medianLabelDepthM(f.labels, 1, cv::Rect(280, 120, 80, 240), f.depth_m, 4), 4.0, 0.05);
  EXPECT_EQ(medianLabelDepthM(f.labels, 2, cv::Rect(280, 120, 80, 240), f.depth_m, 4), 0.0);
}
