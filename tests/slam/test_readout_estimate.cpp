// Online rolling-shutter readout estimate: keypoints seen row by row by a turning camera must
// give back the readout they were rendered with, whatever readout the pose was fitted with, and
// a pose error alone (a global-shutter camera) must not read as a readout.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "core/config.hpp"
#include "slam/keyframe.hpp"
#include "slam/readout_estimate.hpp"
#include "test_rolling_shutter_motion.hpp"

namespace dynanav {
namespace {

using testing::makeVelocity;
using testing::seenByRow;

/// The keyframe that created the map points: where it was, how it moved, the readout it re-timed
/// its keypoints with. Its view of the points decides where the map puts them.
struct KeyFrameView {
  SE3 T_camera_world = SE3::Identity();
  CameraVelocity motion;  ///< interval 0: not known
  double readout_used_s = 0.0;
};

/// A frame at `T_camera_world` matched to 300 points 0.8-6 m away, its keypoints where a camera
/// with readout `readout_s` moving by `velocity` saw them, plus `noise_px` of pixel noise. The
/// map points are where `creator` (the same camera) put them: true positions unless it moved.
struct Scene {
  Frame frame;
  KeyFramePtr keyframe;  ///< keeps the observations' keyframe alive
};

Scene makeScene(const SE3& T_camera_world, const CameraVelocity& velocity, double readout_s,
                double noise_px, unsigned seed, const KeyFrameView& creator) {
  auto camera = std::make_shared<PinholeCamera>();
  auto scales = std::make_shared<PyramidScales>(PyramidScales::fromConfig(OrbConfig{}));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  Features f, kf_features;
  std::vector<Vec3> map_world;
  const SE3 T_world_camera = T_camera_world.inverse();
  const auto add = [&](Features& to, const Eigen::Vector2d& uv, double z, double noise_scale) {
    cv::KeyPoint kp(float(uv.x() + noise_scale * noise(rng)),
                    float(uv.y() + noise_scale * noise(rng)), 31.f);
    kp.octave = 0;
    to.keypoints.push_back(kp);
    to.points.push_back(kp.pt);
    to.depth_m.push_back(float(z));
    to.u_right.push_back(float(kp.pt.x - camera->bf() / z));
  };
  for (int attempt = 0; f.size() < 300; ++attempt) {
    if (attempt > 100000) throw std::logic_error("makeScene: the views share too few points");
    const double z = 0.8 + 5.2 * u01(rng);
    const Vec3 p_mid((u01(rng) - 0.5) * 1.2 * z, (u01(rng) - 0.5) * 0.9 * z, z);
    const Vec3 p_world = T_world_camera * p_mid;
    const Vec3 p_row = seenByRow(*camera, velocity, readout_s, p_mid);
    const Eigen::Vector2d uv = camera->project(p_row);
    // The creator saw the point row by row too, and re-timed it with its readout.
    const Vec3 p_creator_mid = creator.T_camera_world * p_world;
    const Vec3 p_creator_row = creator.motion.interval_s > 0.0
                                   ? seenByRow(*camera, creator.motion, readout_s, p_creator_mid)
                                   : p_creator_mid;
    const Eigen::Vector2d uv_creator = camera->project(p_creator_row);
    if (!camera->inImage(uv.x(), uv.y(), 1.0) ||
        !camera->inImage(uv_creator.x(), uv_creator.y(), 1.0))
      continue;
    const double s_creator = uv_creator.y() / camera->height - 0.5;
    const Vec3 p_creator_retimed =
        creator.motion.interval_s > 0.0
            ? motionOver(creator.motion, s_creator * creator.readout_used_s).inverse() *
                  p_creator_row
            : p_creator_row;
    map_world.push_back(creator.T_camera_world.inverse() * p_creator_retimed);
    add(f, uv, p_row.z(), 1.0);
    add(kf_features, uv_creator, p_creator_row.z(), 0.0);
  }
  for (Features* features : {&f, &kf_features}) {
    features->usable.assign(features->keypoints.size(), 1);
    features->instance_id.assign(features->keypoints.size(), 0);
    features->camera = camera;
    features->scales = scales;
  }
  std::vector<MapPointPtr> points;
  for (size_t i = 0; i < map_world.size(); ++i)
    points.push_back(std::make_shared<MapPoint>(i, map_world[i], nullptr));
  Scene scene{Frame(1, 0.0, std::move(f)),
              std::make_shared<KeyFrame>(0, 0, 0.0, std::move(kf_features), creator.T_camera_world,
                                         points)};
  scene.keyframe->motion = creator.motion;
  scene.keyframe->readout_used_s = creator.readout_used_s;
  for (size_t i = 0; i < points.size(); ++i)
    points[i]->addObservation(scene.keyframe.get(), int(i));
  scene.frame.T_camera_world = T_camera_world;
  scene.frame.map_points = points;
  return scene;
}

const SE3 kPose =
    makeSE3(Quat(Eigen::AngleAxisd(0.3, Vec3(0.2, 1.0, 0.1).normalized())), Vec3(0.4, -0.2, 1.5));
// A brisk head turn: 100 deg/s yaw, 30 deg/s pitch, walking 1 m/s.
const CameraVelocity kTurning = makeVelocity(Vec3(0.0175, 0.058, 0.0), Vec3(0.01, 0.0, -0.03));
// A keyframe that stood still where the frame is: its map points are exact.
const KeyFrameView kStillCreator{kPose, makeVelocity(Vec3::Zero(), Vec3::Zero()), 0.0};

TEST(ReadoutEstimate, OneTurningFrameGivesBackTheReadout) {
  for (const double readout_s : {0.0, 0.010, 0.025, 0.033}) {
    const Scene scene = makeScene(kPose, kTurning, readout_s, 0.0, 3, kStillCreator);
    const ReadoutEvidence e =
        readoutEvidence(scene.frame, KeypointMeasurements::of(scene.frame.features), kTurning, 0.0);
    ASSERT_TRUE(e.valid) << readout_s;
    EXPECT_EQ(e.points, 300);
    // First order in the readout: a few per cent of it at most.
    EXPECT_NEAR(e.readout_s, readout_s, 0.0005 + 0.03 * readout_s) << readout_s;
    EXPECT_GT(e.information_per_s2, ReadoutEstimator::kMinInformationPerS2);
  }
}

TEST(ReadoutEstimate, LinearisingAtTheReadoutUsedGivesTheSameAnswer) {
  // The tracker fits the pose with keypoints re-timed by the readout it uses; the evidence is
  // linearised there and must point back to the truth from either side.
  const Scene scene = makeScene(kPose, kTurning, 0.025, 0.0, 4, kStillCreator);
  for (const double used_s : {0.0, 0.015, 0.025, 0.033}) {
    const ReadoutEvidence e = readoutEvidence(
        scene.frame, KeypointMeasurements::of(scene.frame.features), kTurning, used_s);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.readout_s, 0.025, 0.001) << used_s;
  }
}

TEST(ReadoutEstimate, AMapShiftedByTheShutterIsModelled) {
  // The map's keyframe moved as the frame does, 0.1 s earlier: a wrong readout shifted its
  // points the way the frame sees them, and the shear largely cancels in the residuals. The
  // model of that shift still gives the truth, whatever readout the keyframe re-timed with.
  const Mat3 R_back = expSO3(-3.0 * kTurning.omega);
  const SE3 T_keyframe = makeSE3(Quat(R_back), -3.0 * kTurning.translation) * kPose;
  for (const double keyframe_used_s : {0.0, 0.010, 0.025}) {
    const KeyFrameView creator{T_keyframe, kTurning, keyframe_used_s};
    const Scene scene = makeScene(kPose, kTurning, 0.025, 0.0, 8, creator);
    for (const double used_s : {0.0, 0.025}) {
      const ReadoutEvidence e = readoutEvidence(
          scene.frame, KeypointMeasurements::of(scene.frame.features), kTurning, used_s);
      ASSERT_TRUE(e.valid);
      EXPECT_NEAR(e.readout_s, 0.025, 0.0015) << keyframe_used_s << " " << used_s;
    }
  }
  // A keyframe whose motion is not known cannot be modelled: its points give no evidence.
  const Scene unknown = makeScene(kPose, kTurning, 0.025, 0.0, 9, {T_keyframe, {}, 0.0});
  const ReadoutEvidence e = readoutEvidence(
      unknown.frame, KeypointMeasurements::of(unknown.frame.features), kTurning, 0.0);
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(e.points, 0);
}

TEST(ReadoutEstimate, APoseErrorIsNotReadAsAReadout) {
  // A global-shutter frame whose pose is off by 0.5 degrees and 1 cm: the residuals are large
  // but a pose change explains them, so the readout stays near 0.
  Scene scene = makeScene(kPose, kTurning, 0.0, 0.0, 5, kStillCreator);
  Eigen::Matrix<double, 6, 1> xi;
  xi << 0.01, -0.005, 0.0, 0.0, 0.0087, 0.002;
  scene.frame.T_camera_world = leftPerturb(xi, kPose);
  const ReadoutEvidence e =
      readoutEvidence(scene.frame, KeypointMeasurements::of(scene.frame.features), kTurning, 0.0);
  ASSERT_TRUE(e.valid);
  EXPECT_NEAR(e.readout_s, 0.0, 0.001);
}

TEST(ReadoutEstimate, AStillCameraGivesNoUsableEvidence) {
  const CameraVelocity still = makeVelocity(Vec3::Zero(), Vec3::Zero());
  const Scene scene = makeScene(kPose, still, 0.025, 0.5, 6, kStillCreator);
  const Frame& frame = scene.frame;
  const ReadoutEvidence e =
      readoutEvidence(frame, KeypointMeasurements::of(frame.features), still, 0.0);
  EXPECT_LT(e.information_per_s2, ReadoutEstimator::kMinInformationPerS2);
  ReadoutEstimator estimator;
  estimator.add(e);
  EXPECT_EQ(estimator.frames(), 0);
  // No motion known (after a loss): no evidence at all.
  EXPECT_FALSE(
      readoutEvidence(frame, KeypointMeasurements::of(frame.features), CameraVelocity{}, 0.0)
          .valid);
}

TEST(ReadoutEstimate, OutliersAndFewMatchesAreLeftOut) {
  Scene scene = makeScene(kPose, kTurning, 0.025, 0.0, 7, kStillCreator);
  Frame& frame = scene.frame;
  for (int i = 0; i < frame.size(); ++i) frame.outlier[i] = i % 3 == 0 ? 0 : 1;
  const ReadoutEvidence e =
      readoutEvidence(frame, KeypointMeasurements::of(frame.features), kTurning, 0.0);
  EXPECT_EQ(e.points, 100);
  for (int i = 0; i < frame.size(); ++i) frame.outlier[i] = i >= ReadoutEstimator::kMinPoints - 1;
  EXPECT_FALSE(
      readoutEvidence(frame, KeypointMeasurements::of(frame.features), kTurning, 0.0).valid);
}

TEST(ReadoutEstimate, NoisyFramesPoolToTheTruthWithAnHonestSigma) {
  ReadoutEstimator estimator;
  std::mt19937 rng(11);
  std::normal_distribution<double> yaw(0.0, 0.05);  // rad per frame: turns both ways
  for (int k = 0; k < 60; ++k) {
    const CameraVelocity v = makeVelocity(Vec3(0.3 * yaw(rng), yaw(rng), 0.0), Vec3::Zero());
    const Scene scene = makeScene(kPose, v, 0.025, 1.0, 100 + k, kStillCreator);
    estimator.add(
        readoutEvidence(scene.frame, KeypointMeasurements::of(scene.frame.features), v, 0.0));
    if (estimator.frames() < ReadoutEstimator::kMinFrames) {
      EXPECT_TRUE(std::isinf(estimator.sigmaS()));
    }
  }
  ASSERT_GE(estimator.frames(), ReadoutEstimator::kMinFrames);
  EXPECT_NEAR(estimator.readoutS(), 0.025, 0.002);
  EXPECT_LT(estimator.sigmaS(), 0.002);
  EXPECT_GT(estimator.sigmaS(), 0.0);
  EXPECT_LT(std::abs(estimator.readoutS() - 0.025), 4.0 * estimator.sigmaS() + 0.0005);
  estimator.restart();
  EXPECT_EQ(estimator.frames(), 0);
  EXPECT_TRUE(std::isinf(estimator.sigmaS()));
}

}  // namespace
}  // namespace dynanav
