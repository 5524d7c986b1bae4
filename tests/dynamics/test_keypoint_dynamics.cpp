#include <gtest/gtest.h>

#include "dynamics/keypoint_dynamics.hpp"
#include "slam/keyframe.hpp"

using namespace dynanav;

namespace {
Instances twoObjects() {
  Instances instances;
  instances.labels = cv::Mat::zeros(120, 160, CV_16U);
  instances.labels(cv::Rect(10, 10, 30, 60)).setTo(1);   // a person
  instances.labels(cv::Rect(100, 40, 40, 40)).setTo(2);  // a box
  instances.items = {{1, "person", 0.9f, cv::Rect(10, 10, 30, 60), "selfie", {}},
                     {2, "box", 1.f, cv::Rect(100, 40, 40, 40), "file", {}}};
  return instances;
}

/// A frame at the identity with keypoints at `pixels`, each matched to a map point straight
/// ahead at `map_depth_m` and measured at `measured_depth_m`.
Frame frameWith(const std::vector<cv::Point2f>& pixels, const std::vector<float>& map_depth_m,
                const std::vector<float>& measured_depth_m) {
  Features f;
  for (const auto& p : pixels) f.keypoints.emplace_back(p, 31.f);
  f.points = pixels;
  f.depth_m = measured_depth_m;
  f.usable.assign(pixels.size(), 1);
  f.instance_id.assign(pixels.size(), 0);
  Frame frame(7, 0.0, f);
  for (size_t i = 0; i < pixels.size(); ++i)
    if (map_depth_m[i] > 0)
      frame.map_points[i] = std::make_shared<MapPoint>(i, Vec3(0, 0, map_depth_m[i]), nullptr);
  return frame;
}
}  // namespace

TEST(KeypointDynamics, PriorClassesOnly) {
  DynamicsConfig c;
  const Instances instances = twoObjects();
  EXPECT_TRUE(isPriorDynamic(instances.items[0], c));
  EXPECT_FALSE(isPriorDynamic(instances.items[1], c));
}

TEST(KeypointDynamics, ExtractionMaskCutsOutDilatedPersonOnly) {
  DynamicsConfig c;
  c.prior_mask_dilate_px = 5;
  const cv::Mat allowed = staticExtractionMask(twoObjects(), c);
  ASSERT_EQ(allowed.type(), CV_8U);
  EXPECT_EQ(allowed.at<uint8_t>(40, 25), 0);     // inside the person
  EXPECT_EQ(allowed.at<uint8_t>(40, 43), 0);     // 4 px right of the person: dilated away
  EXPECT_EQ(allowed.at<uint8_t>(40, 50), 255);   // 11 px right: allowed
  EXPECT_EQ(allowed.at<uint8_t>(60, 120), 255);  // the box is not a prior mover
}

TEST(KeypointDynamics, NoPriorObjectsGivesEmptyMask) {
  DynamicsConfig c;
  Instances instances = twoObjects();
  instances.items.erase(instances.items.begin());
  EXPECT_TRUE(staticExtractionMask(instances, c).empty());
  EXPECT_TRUE(staticExtractionMask(Instances::none({160, 120}), c).empty());
}

/// Step 5 as the pipeline runs it: mover rejection decides on the frame, slam applies it.
struct Rejection {
  int checked = 0;
  int rejected = 0;
  int culled = 0;
  std::vector<uint16_t> moving_instances;
};
Rejection rejectDepthMovers(Frame& frame, const DynamicsConfig& c) {
  const MoverVerdict verdict = findDepthMovers(frame, predictedMapPointDepths(frame), c);
  Rejection r;
  r.checked = verdict.checked;
  r.rejected = static_cast<int>(verdict.drop.drop.size());
  r.moving_instances = verdict.moving_instances;
  r.culled = applyKeypointDrop(frame, verdict.drop);
  return r;
}

TEST(KeypointDynamics, LabelsFollowKeypointPixels) {
  Frame frame = frameWith({{20, 20}, {120, 60}, {70, 100}}, {2, 2, 2}, {2, 2, 2});
  labelKeypoints(frame.features, twoObjects().labels);
  EXPECT_EQ(frame.features.instance_id, (std::vector<uint16_t>{1, 2, 0}));
}

TEST(KeypointDynamics, MovingBoxIsRejectedWholeStaticPointsKept) {
  DynamicsConfig c;
  // Six box keypoints: four moved 0.4 m closer, one agrees, one has no map point yet.
  // Two background points: one agrees, one is a lone mover outside any mask.
  std::vector<cv::Point2f> px = {{105, 45}, {110, 50}, {115, 55}, {120, 60},
                                 {125, 65}, {130, 70}, {70, 100}, {80, 100}};
  std::vector<float> map_z = {2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 0.f, 3.0f, 3.0f};
  std::vector<float> meas_z = {1.6f, 1.6f, 1.6f, 1.6f, 2.0f, 1.6f, 3.01f, 2.2f};
  Frame frame = frameWith(px, map_z, meas_z);
  labelKeypoints(frame.features, twoObjects().labels);
  c.instance_min_points = 5;
  const Rejection r = rejectDepthMovers(frame, c);
  EXPECT_EQ(r.checked, 7);
  EXPECT_EQ(r.moving_instances, (std::vector<uint16_t>{2}));
  for (int i = 0; i < 6; ++i) {
    EXPECT_FALSE(frame.features.usable[i]) << i;
    EXPECT_FALSE(frame.map_points[i]) << i;
  }
  EXPECT_TRUE(frame.features.usable[6]);
  EXPECT_TRUE(frame.map_points[6]);
  EXPECT_FALSE(frame.features.usable[7]);  // judged on its own
  EXPECT_EQ(r.rejected, 7);
}

TEST(KeypointDynamics, MapPointsOnAMovingObjectAreCulled) {
  // The box's four moved keypoints and one that agrees are matched to mapped points (seen by a
  // keyframe); the box is voted moving, so all five points leave the map. The background point
  // that agrees stays.
  std::vector<cv::Point2f> px = {{105, 45}, {110, 50}, {115, 55}, {120, 60}, {125, 65}, {70, 100}};
  std::vector<float> map_z = {2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 3.0f};
  std::vector<float> meas_z = {1.6f, 1.6f, 1.6f, 1.6f, 2.0f, 3.01f};
  for (const bool cull : {true, false}) {
    Frame frame = frameWith(px, map_z, meas_z);
    labelKeypoints(frame.features, twoObjects().labels);
    auto kf =
        std::make_shared<KeyFrame>(0, 0, 0.0, frame.features, SE3::Identity(), frame.map_points);
    std::vector<MapPointPtr> points = frame.map_points;
    for (int i = 0; i < frame.size(); ++i) points[i]->addObservation(kf.get(), i);
    DynamicsConfig c;
    c.instance_min_points = 5;
    c.cull_moving_object_points = cull;
    const Rejection r = rejectDepthMovers(frame, c);
    ASSERT_EQ(r.moving_instances, (std::vector<uint16_t>{2}));
    EXPECT_EQ(r.culled, cull ? 5 : 0);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(points[i]->bad, cull) << i;
    EXPECT_FALSE(points[5]->bad);
    EXPECT_EQ(kf->map_points[0] == nullptr, cull);  // gone from the keyframe too
  }
}

TEST(KeypointDynamics, StaticSceneLosesNothing) {
  DynamicsConfig c;
  std::vector<cv::Point2f> px;
  std::vector<float> map_z, meas_z;
  for (int i = 0; i < 40; ++i) {
    px.emplace_back(4.f * i, 100.f);
    map_z.push_back(1.0f + 0.1f * i);
    meas_z.push_back(1.0f + 0.1f * i + 0.01f * ((i % 3) - 1));  // sensor noise
  }
  Frame frame = frameWith(px, map_z, meas_z);
  labelKeypoints(frame.features, twoObjects().labels);
  const Rejection r = rejectDepthMovers(frame, c);
  EXPECT_EQ(r.rejected, 0);
  EXPECT_TRUE(r.moving_instances.empty());
}

TEST(KeypointDynamics, PoseIsUsedForPrediction) {
  DynamicsConfig c;
  // The camera moved 0.5 m forward: a point 3 m ahead in the world is 2.5 m ahead now.
  Frame frame = frameWith({{70, 100}}, {3.0f}, {2.5f});
  frame.T_camera_world = makeSE3(Quat::Identity(), Vec3(0, 0, -0.5));
  EXPECT_EQ(rejectDepthMovers(frame, c).rejected, 0);
  frame.T_camera_world = SE3::Identity();
  EXPECT_EQ(rejectDepthMovers(frame, c).rejected, 1);
}

TEST(KeypointDynamics, TurningCameraWidensTheDepthTestOnlyAsFarAsItMoved) {
  // A depth edge at column 80: a cupboard at 1.5 m on the left, the wall at 4 m on the right.
  // A mover stands 1 m in front of the wall at columns 120-159 (rows 20-99).
  cv::Mat depth(120, 160, CV_32F, cv::Scalar(4.0f));
  depth.colRange(0, 80).setTo(1.5f);
  depth(cv::Rect(120, 20, 40, 80)).setTo(3.0f);
  // Keypoint 0: the cupboard's corner (map point at 1.5 m), found 3 px onto the wall in a
  // blurred image. Keypoint 1: on the mover, 20 px from its outline, where the map had the wall.
  Frame frame = frameWith({{83, 60}, {140, 60}}, {1.5f, 4.0f}, {4.0f, 3.0f});
  frame.features.camera = std::make_shared<PinholeCamera>();  // f = 525 px
  DynamicsConfig c;
  DepthTestMotion motion;
  motion.depth_m = depth;
  motion.time_spread_s = 0.005;  // half a 10 ms exposure
  const std::vector<float> predicted = predictedMapPointDepths(frame);

  // Still camera: DynaSLAM's test on the keypoint's own depth flags the corner.
  const MoverVerdict still = findDepthMovers(frame, predicted, c, motion);
  EXPECT_EQ(still.drop.drop, (std::vector<int>{0, 1}));

  // Turning at 150 deg/s: the scene moved ~7 px within the time spread, the cupboard's depth
  // lies within that radius, so the corner is kept; the mover is still dropped.
  motion.velocity.interval_s = 1.0 / 30.0;
  motion.velocity.omega = Vec3(0, 150.0 * 3.14159265 / 180.0 / 30.0, 0);
  const MoverVerdict turning = findDepthMovers(frame, predicted, c, motion);
  EXPECT_EQ(turning.drop.drop, (std::vector<int>{1}));

  // The search radius is capped: with a cap of 2 px the corner is flagged again.
  c.depth_test_max_radius_px = 2;
  EXPECT_EQ(findDepthMovers(frame, predicted, c, motion).drop.drop, (std::vector<int>{0, 1}));
}

TEST(KeypointDynamics, RollingShutterWidensTheDepthTestByTheKeypointsRowTime) {
  // The same cupboard corner found 3 px onto the wall, once in the top row (read ~12 ms before
  // the middle row, when a 25 ms readout runs over 120 rows) and once in the middle row (read at
  // the depth image's instant). No exposure: only the row's time widens the search.
  cv::Mat depth(120, 160, CV_32F, cv::Scalar(4.0f));
  depth.colRange(0, 80).setTo(1.5f);
  Frame frame = frameWith({{83, 2}, {83, 60}}, {1.5f, 1.5f}, {4.0f, 4.0f});
  auto camera = std::make_shared<PinholeCamera>();  // f = 525 px
  camera->height = 120;
  frame.features.camera = camera;
  DynamicsConfig c;
  DepthTestMotion motion;
  motion.depth_m = depth;
  motion.velocity.interval_s = 1.0 / 30.0;
  motion.velocity.omega = Vec3(0, 150.0 * 3.14159265 / 180.0 / 30.0, 0);
  const std::vector<float> predicted = predictedMapPointDepths(frame);
  // Global shutter: neither keypoint had time to be misregistered.
  EXPECT_EQ(findDepthMovers(frame, predicted, c, motion).drop.drop, (std::vector<int>{0, 1}));
  // 25 ms readout: the top row's 12 ms at 150 deg/s is ~16 px, which reaches the cupboard.
  motion.readout_s = 0.025;
  EXPECT_EQ(findDepthMovers(frame, predicted, c, motion).drop.drop, (std::vector<int>{1}));
}
