// Rigid object motion (EPnP-RANSAC + prior + Ceres) and the centroid velocity v = t - (I - R) c
// on synthetic points with known answers; the constant-velocity Kalman filter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include "dynamics/kalman_cv.hpp"
#include "dynamics/object_motion.hpp"

using namespace dynanav;

namespace {

/// fx = fy = 525, centre (319.5, 239.5), no distortion: PinholeCamera's defaults.
PinholeCamera camera() {
  return PinholeCamera{};
}

/// A person-sized blob of points 3 m in front of a camera at T_world_camera.
std::vector<Vec3> blob(int n, const Vec3& centre_world, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i)
    points.push_back(centre_world + Vec3(0.25 * u(rng), 0.6 * u(rng), 0.15 * u(rng)));
  return points;
}

}  // namespace

TEST(ObjectMotion, InlierCentroidVelocityLeavesOutliersOut) {
  // A rotation about the inliers' centroid (1, 0, 4): it stays, so the velocity is zero; the
  // outlier far away would move the centroid, and with it the velocity, were it counted.
  const Vec3 c(1.0, 0.0, 4.0);
  ObjectMotion motion;
  motion.ok = true;
  const Mat3 R = Eigen::AngleAxisd(0.2, Vec3::UnitY()).toRotationMatrix();
  motion.H_world.linear() = R;
  motion.H_world.translation() = c - R * c;
  const std::vector<Vec3> p_prev{c + Vec3(0.1, 0, 0), c - Vec3(0.1, 0, 0), Vec3(5, 5, 5)};
  motion.inlier = {1, 1, 0};
  motion.inliers = 2;
  EXPECT_LT(inlierCentroidVelocity(motion, p_prev, 1.0 / 30.0).norm(), 1e-9);
  motion.inlier = {1, 1, 1};
  motion.inliers = 3;
  EXPECT_GT(inlierCentroidVelocity(motion, p_prev, 1.0 / 30.0).norm(), 1.0);
}

TEST(ObjectMotion, CentroidDisplacementOfKnownRigidMotions) {
  const Vec3 c(1.0, -0.5, 4.0);
  // Pure translation: the centroid moves by t.
  SE3 H = makeSE3(Quat::Identity(), Vec3(0.03, 0.0, -0.02));
  EXPECT_TRUE(centroidDisplacement(H, c).isApprox(Vec3(0.03, 0.0, -0.02), 1e-12));
  // A rotation about the centroid itself: the centroid stays.
  const Mat3 R = Eigen::AngleAxisd(0.2, Vec3::UnitY()).toRotationMatrix();
  H = SE3::Identity();
  H.linear() = R;
  H.translation() = c - R * c;
  EXPECT_LT(centroidDisplacement(H, c).norm(), 1e-12);
  // The general case equals H c - c.
  H.translation() = Vec3(0.1, 0.2, 0.3);
  EXPECT_TRUE(centroidDisplacement(H, c).isApprox(H * c - c, 1e-12));
}

TEST(ObjectMotion, RecoversKnownMotionWithOutliers) {
  std::mt19937 rng(5);
  const PinholeCamera cam = camera();
  const SE3 T_world_camera =
      makeSE3(Quat(Eigen::AngleAxisd(0.1, Vec3::UnitY())), Vec3(0.2, 0.0, 0.5));
  const Vec3 centre = T_world_camera * Vec3(0.3, 0.1, 3.0);
  const auto p_prev = blob(300, centre, rng);
  // A walker: 1.2 m/s for one 30 Hz frame, turning 2 degrees about its vertical axis.
  SE3 H_true = SE3::Identity();
  H_true.linear() = Eigen::AngleAxisd(2.0 * M_PI / 180.0, Vec3::UnitY()).toRotationMatrix();
  H_true.translation() = centre - H_true.linear() * centre + Vec3(0.04, 0.0, 0.0);
  const SE3 T_camera_world = T_world_camera.inverse();
  std::vector<Eigen::Vector2d> pixels;
  std::normal_distribution<double> noise(0.0, 0.3);
  std::uniform_real_distribution<double> far(-40.0, 40.0);
  for (size_t i = 0; i < p_prev.size(); ++i) {
    Eigen::Vector2d px = cam.project(T_camera_world * (H_true * p_prev[i]));
    px += Eigen::Vector2d(noise(rng), noise(rng));
    if (i % 5 == 0) px += Eigen::Vector2d(far(rng), far(rng));  // 20 % gross outliers
    pixels.push_back(px);
  }
  const ObjectMotion m =
      estimateObjectMotion(p_prev, pixels, T_camera_world, cam, SE3::Identity(), {});
  ASSERT_TRUE(m.ok);
  EXPECT_FALSE(m.from_prior);
  EXPECT_GT(m.inliers, 200);
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : p_prev) c += p;
  c /= double(p_prev.size());
  const Vec3 v_mps = centroidDisplacement(m.H_world, c) * 30.0;
  const Vec3 v_true = centroidDisplacement(H_true, c) * 30.0;
  EXPECT_LT((v_mps - v_true).norm(), 0.05) << v_mps.transpose() << " vs " << v_true.transpose();
  // The prior wins when it is the truth itself (as many inliers, no worse).
  const ObjectMotion again = estimateObjectMotion(p_prev, pixels, T_camera_world, cam, H_true, {});
  ASSERT_TRUE(again.ok);
  EXPECT_LT((centroidDisplacement(again.H_world, c) * 30.0 - v_true).norm(), 0.05);
}

TEST(ObjectMotion, TooFewPointsIsNoEstimate) {
  std::mt19937 rng(1);
  const auto p = blob(8, Vec3(0, 0, 3), rng);
  std::vector<Eigen::Vector2d> px(p.size(), Eigen::Vector2d(320, 240));
  EXPECT_FALSE(estimateObjectMotion(p, px, SE3::Identity(), camera(), SE3::Identity(), {}).ok);
}

TEST(KalmanCv, ConvergesToConstantVelocityAndPredictsThePath) {
  std::mt19937 rng(2);
  std::normal_distribution<double> pos(0.0, 0.03), vel(0.0, 0.3);
  const Vec3 v_true(1.2, 0.0, -0.5);
  const double dt = 1.0 / 30.0;
  KalmanCv filter(Vec3(0, 0, 3), {});
  const double sigma_v0 = std::sqrt(filter.covariance()(3, 3));
  Vec3 p(0, 0, 3);
  for (int k = 1; k <= 120; ++k) {
    p += v_true * dt;
    filter.predict(dt);
    filter.update(p + Vec3(pos(rng), pos(rng), pos(rng)),
                  v_true + Vec3(vel(rng), vel(rng), vel(rng)));
  }
  EXPECT_LT((filter.velocity() - v_true).norm(), 0.15);
  EXPECT_LT((filter.position() - p).norm(), 0.05);
  EXPECT_LT(std::sqrt(filter.covariance()(3, 3)), 0.5 * sigma_v0);
  const auto path = filter.predictPath(2.0, 0.5);
  ASSERT_EQ(path.size(), 4u);
  EXPECT_NEAR(path.back().ahead_s, 2.0, 1e-9);
  EXPECT_LT((path.back().p_world - (filter.position() + 2.0 * filter.velocity())).norm(), 1e-9);
  EXPECT_GT(path.back().sigma_m, path.front().sigma_m);  // uncertainty grows with the horizon
  // Covariance stays symmetric.
  EXPECT_LT((filter.covariance() - filter.covariance().transpose()).norm(), 1e-9);
  filter.holdStill();
  EXPECT_EQ(filter.velocity(), Vec3::Zero());
}

TEST(KalmanCv, PositionOnlyUpdatesInferVelocity) {
  KalmanCv filter(Vec3::Zero(), {});
  const double dt = 0.1;
  for (int k = 1; k <= 60; ++k) {
    filter.predict(dt);
    filter.update(Vec3(0.8 * k * dt, 0, 0), std::nullopt);
  }
  EXPECT_NEAR(filter.velocity().x(), 0.8, 0.05);
}

TEST(KalmanCv, ReanchoringPlacesThePositionWithoutTouchingTheVelocity) {
  // Walking at 1 m/s along x, its velocity known; then a centre 0.3 m off measured on another
  // part of it. An update reads the offset as a change of speed; a reanchoring moves the
  // position to the new part and leaves the velocity and its variance as they were, also in the
  // frames after it (the offset must not leak in through the position-velocity correlation).
  const double dt = 1.0 / 30.0;
  KalmanCv walked(Vec3::Zero(), {});
  for (int k = 1; k <= 60; ++k) {
    walked.predict(dt);
    walked.update(Vec3(k * dt, 0, 0), Vec3(1, 0, 0));
  }
  KalmanCv updated = walked, reanchored = walked;
  for (KalmanCv* f : {&updated, &reanchored}) f->predict(dt);
  const Mat3 velocity_cov = reanchored.covariance().bottomRightCorner<3, 3>();
  const Vec3 offset_part(61 * dt + 0.3, 0, 0);
  updated.update(offset_part, std::nullopt);
  reanchored.reanchor(offset_part, 1.0);
  EXPECT_GT(updated.velocity().x(), 1.5);
  EXPECT_NEAR(reanchored.velocity().x(), 1.0, 0.02);
  EXPECT_NEAR(reanchored.position().x(), offset_part.x(), 0.01);
  EXPECT_LT((reanchored.covariance().bottomRightCorner<3, 3>() - velocity_cov).norm(), 1e-12);
  for (int k = 62; k <= 70; ++k) {
    reanchored.predict(dt);
    reanchored.update(Vec3(k * dt + 0.3, 0, 0), std::nullopt);
  }
  EXPECT_NEAR(reanchored.velocity().x(), 1.0, 0.05);
  // A new centre that leaves its sideways position unknown (cut by the image's side, 1 m) opens
  // only what it measures: the predicted x stays, the depth goes to the new part's.
  KalmanCv cut = walked;
  cut.predict(dt);
  const double x_predicted = cut.position().x();
  cut.reanchor(Vec3(x_predicted + 0.5, 0, 0.3), 1.0, Vec3(1.0, 0.0025, 0.0025).asDiagonal());
  EXPECT_NEAR(cut.position().x(), x_predicted, 0.01);
  EXPECT_NEAR(cut.position().z(), 0.3, 0.01);
}

TEST(KalmanCv, NormalisedInnovationIsTheMeasurementsMahalanobisDistance) {
  // A new filter at the origin: position variance 0.05^2, velocity 1^2 per axis; the
  // measurement noises are 0.05 m and 0.6 m/s. A centre 0.1 m off along x: 0.1^2 / (2 * 0.05^2)
  // = 2; with a velocity of 1 m/s along x as well: + 1 / (1 + 0.36).
  const KalmanCvNoise noise{0.5, 0.05, 0.6, 1.0};
  const KalmanCv filter(Vec3::Zero(), noise);
  EXPECT_NEAR(filter.normalisedInnovation(Vec3(0.1, 0, 0), std::nullopt), 2.0, 1e-9);
  EXPECT_NEAR(filter.normalisedInnovation(Vec3(0.1, 0, 0), Vec3(1, 0, 0)), 2.0 + 1.0 / 1.36, 1e-9);
  // A wider measurement covariance makes the same offset less surprising.
  EXPECT_NEAR(
      filter.normalisedInnovation(Vec3(0.1, 0, 0), std::nullopt, Mat3::Identity() * 0.15 * 0.15),
      0.01 / (0.0025 + 0.0225), 1e-9);
}

TEST(KalmanCv, AReopenedHeldFilterFollowsTheNextMeasurementsAtOnce) {
  // Held still at the origin while the object already moved 0.2 m and walks at 1 m/s along x:
  // reopened, the filter reads the speed within a few frames and the centre's lag enters the
  // position rather than the velocity; not reopened, the held state's tight covariance decides.
  const double dt = 1.0 / 30.0;
  for (const bool reopened : {false, true}) {
    KalmanCv filter(Vec3::Zero(), {});
    filter.holdStill();
    if (reopened) filter.reopen(1.0, 1.0);
    const double x0 = 0.2;  // moved while it was held
    for (int k = 1; k <= 5; ++k) {
      filter.predict(dt);
      filter.update(Vec3(x0 + k * dt, 0, 0), std::nullopt);
    }
    if (reopened) {
      EXPECT_NEAR(filter.velocity().x(), 1.0, 0.3);
      EXPECT_NEAR(filter.position().x(), x0 + 5 * dt, 0.05);
    } else {  // the held state's confidence decides instead: a ramp, or the lag read as speed
      EXPECT_GT(std::abs(filter.velocity().x() - 1.0), 0.25);
    }
  }
}

TEST(KalmanCv, UnknownComponentOfAPositionMeasurementIsNotFollowed) {
  // A centre whose x is 1 m off but marked unknown (sigma 1 m) moves x little, y normally.
  KalmanCv filter(Vec3::Zero(), {});
  KalmanCv isotropic(Vec3::Zero(), {});
  const Mat3 cov = Vec3(1.0, 0.05 * 0.05, 0.05 * 0.05).asDiagonal();
  filter.predict(1.0 / 30.0);
  isotropic.predict(1.0 / 30.0);
  filter.update(Vec3(1.0, 0.1, 0.0), std::nullopt, cov);
  isotropic.update(Vec3(1.0, 0.1, 0.0), std::nullopt);
  EXPECT_LT(filter.position().x(), 0.01);
  EXPECT_GT(isotropic.position().x(), 0.3);
  EXPECT_NEAR(filter.position().y(), isotropic.position().y(), 1e-9);
  EXPECT_LT((filter.covariance() - filter.covariance().transpose()).norm(), 1e-9);
}

TEST(KalmanCv, AVelocityMeasuredAcrossTheRayLeavesTheComponentAlongItAlone) {
  // A new filter (velocity 0 +- 1 m/s per axis) hears 1 m/s across the line of sight (x) and
  // 2.5 m/s toward the camera along it (-z): the across component follows the measurement as a
  // whole measurement's would (1 / (1 + 0.36)), the one along the ray stays at the prior.
  const KalmanCvNoise noise{0.5, 0.05, 0.6, 1.0};
  KalmanCv across(Vec3(0, 0, 3), noise);
  KalmanCv whole(Vec3(0, 0, 3), noise);
  const Vec3 v(1.0, 0.0, -2.5);
  const Vec3 ray(0, 0, 3);  // camera at the origin, object 3 m ahead
  across.updateVelocityAcross(v, ray);
  whole.updateVelocity(v);
  EXPECT_NEAR(across.velocity().x(), 1.0 / 1.36, 1e-9);
  EXPECT_NEAR(across.velocity().x(), whole.velocity().x(), 1e-9);
  EXPECT_NEAR(across.velocity().z(), 0.0, 1e-9);
  EXPECT_LT(whole.velocity().z(), -1.5);
  // Its variance along the ray is still the prior's; across it, narrowed.
  EXPECT_NEAR(across.covariance()(5, 5), 1.0, 1e-9);
  EXPECT_NEAR(across.covariance()(3, 3), 0.36 / 1.36, 1e-9);
  EXPECT_LT((across.covariance() - across.covariance().transpose()).norm(), 1e-12);
}

TEST(KalmanCv, AVelocityComponentPseudoMeasurementMovesOnlyThatComponent) {
  // A filter that heard (1.2, 0.4, 0) m/s hears "0 +- 0.3 m/s along the up axis (-y)": the
  // vertical component shrinks by the scalar Kalman gain, the horizontal ones keep their value
  // (the prior's axes are uncorrelated), and a zero sigma or axis changes nothing.
  const KalmanCvNoise noise{0.5, 0.05, 0.6, 1.0};
  KalmanCv filter(Vec3(0, 0, 3), noise);
  filter.updateVelocity(Vec3(1.2, 0.4, 0.0));
  const double p_vy = filter.covariance()(4, 4);
  const double vy = filter.velocity().y();
  const Vec3 up(0.0, -2.0, 0.0);  // any length: the axis is normalised
  KalmanCv untouched = filter;
  untouched.updateVelocityAlong(up, 0.0, 0.0);
  untouched.updateVelocityAlong(Vec3::Zero(), 0.0, 0.3);
  EXPECT_EQ(untouched.velocity(), filter.velocity());
  filter.updateVelocityAlong(up, 0.0, 0.3);
  EXPECT_NEAR(filter.velocity().y(), vy * 0.09 / (p_vy + 0.09), 1e-9);
  EXPECT_NEAR(filter.velocity().x(), 1.2 / 1.36, 1e-9);
  EXPECT_NEAR(filter.velocity().z(), 0.0, 1e-9);
  EXPECT_NEAR(filter.covariance()(4, 4), p_vy * 0.09 / (p_vy + 0.09), 1e-9);
  EXPECT_LT((filter.covariance() - filter.covariance().transpose()).norm(), 1e-12);
}

TEST(KalmanCv, AHeadingMeasurementTurnsTheVelocityWithoutChangingItsLength) {
  // A filter walking at 1.2 m/s along x, the floor's normal along y. The points read the walker
  // heading 45 degrees off, at 0.8 m/s (a turn, and the flow's under-read): the velocity turns
  // toward the new heading (z grows), its component along the old direction stays (the under-read
  // does not slow it). A reading along the walk, slower or faster, changes nothing; nor does any
  // reading while the direction is unknown (a new filter at rest).
  const double dt = 1.0 / 30.0;
  const Vec3 up(0.0, -1.0, 0.0);
  KalmanCv walking(Vec3::Zero(), {});
  for (int k = 1; k <= 60; ++k) {
    walking.predict(dt);
    walking.update(Vec3(1.2 * k * dt, 0, 0), std::nullopt);
  }
  ASSERT_NEAR(walking.velocity().x(), 1.2, 0.02);
  KalmanCv turned = walking;
  const double s = 0.8 / std::sqrt(2.0);
  ASSERT_TRUE(turned.updateHeading(Vec3(s, 0.0, s), up, 0.3));
  EXPECT_GT(turned.velocity().z(), 0.1);
  EXPECT_LT(turned.velocity().z(), s);
  EXPECT_NEAR(turned.velocity().x(), walking.velocity().x(), 0.01);
  for (const double along : {0.5, 2.0}) {
    KalmanCv same = walking;
    ASSERT_TRUE(same.updateHeading(Vec3(along, 0.0, walking.velocity().z()), up, 0.3));
    EXPECT_LT((same.velocity() - walking.velocity()).norm(), 1e-9) << along;
  }
  KalmanCv at_rest(Vec3::Zero(), {});
  EXPECT_FALSE(at_rest.updateHeading(Vec3(s, 0.0, s), up, 0.3));
  EXPECT_EQ(at_rest.velocity(), Vec3::Zero());
  EXPECT_FALSE(turned.updateHeading(Vec3(s, 0.0, s), up, 0.0));  // sigma 0: off
}

namespace {
// A walker at 1.2 m/s along x for 2 s turns by 60 degrees over 0.6 s and walks on for 1 s, as in
// the simulated office. A filter with `noise` follows it as the tracker does: its centres (2 cm
// of noise; in the turn they fall 0.1 m inside the path, the measured body's centre cutting the
// corner as the office's did) and its points' heading (their velocity reads 3/4 of the walk's, the
// flow's under-read, with 0.15 m/s of noise). The same draws for every filter. Returns the RMS
// error of the filtered speed over {the straight walk's last second, the turn and the half second
// after it}.
std::pair<double, double> walkAndTurn(const KalmanCvNoise& noise) {
  std::mt19937 rng(5);
  std::normal_distribution<double> centre_noise(0.0, 0.02), points_noise(0.0, 0.15);
  const double dt = 1.0 / 30.0, speed = 1.2, turn_rate = (M_PI / 3.0) / 0.6;
  const Vec3 up(0.0, -1.0, 0.0);
  KalmanCv filter(Vec3::Zero(), noise);
  Vec3 p = Vec3::Zero();
  double heading = 0.0, sq_straight = 0.0, sq_turn = 0.0;
  int n_straight = 0, n_turn = 0;
  for (int k = 1; k <= 108; ++k) {
    const double t = k * dt;
    const bool turning = t > 2.0 && t <= 2.6;
    if (turning) heading += turn_rate * dt;
    const Vec3 direction(std::cos(heading), 0.0, std::sin(heading));
    const Vec3 inward(-direction.z(), 0.0, direction.x());
    p += speed * dt * direction;
    filter.predict(dt);
    const Vec3 noise_m(centre_noise(rng), centre_noise(rng), centre_noise(rng));
    filter.update(p + (turning ? 0.1 : 0.0) * inward + noise_m, std::nullopt);
    const Vec3 points_mps =
        0.75 * speed * direction + Vec3(points_noise(rng), 0.0, points_noise(rng));
    filter.updateHeading(points_mps, up, 0.3);
    const double err = filter.velocity().norm() - speed;
    if (t > 1.0 && t <= 2.0) sq_straight += err * err, ++n_straight;
    if (t > 2.0 && t <= 3.1) sq_turn += err * err, ++n_turn;
  }
  return {std::sqrt(sq_straight / n_straight), std::sqrt(sq_turn / n_turn)};
}
}  // namespace

TEST(KalmanCv, ASteadierPaceThanHeadingReadsStraightWalksAndTurnsBetter) {
  // One isotropic acceleration noise: 0.5 m/s^2 shakes the straight walk's speed, 0.35 holds it
  // steady, and through the turn the velocity follows the centres' shortcut with either, its
  // length sagging. Split, 0.35 along a clear direction of travel and 0.5 across it: the straight
  // walk as steady as with 0.35, and the points' heading turns the velocity with its length kept
  // nearer the walker's.
  const KalmanCvNoise wide{0.5, 0.05, 0.6, 1.0}, low{0.35, 0.05, 0.6, 1.0};
  const KalmanCvNoise split{0.5, 0.05, 0.6, 1.0, 0.35};
  const auto [straight_wide, turn_wide] = walkAndTurn(wide);
  const auto [straight_low, turn_low] = walkAndTurn(low);
  const auto [straight_split, turn_split] = walkAndTurn(split);
  // The speed RMS errors, straight / turn, in the test's XML (--gtest_output=xml:FILE).
  for (const auto& [name, rms] : {std::pair{"wide", std::pair{straight_wide, turn_wide}},
                                  std::pair{"low", std::pair{straight_low, turn_low}},
                                  std::pair{"split", std::pair{straight_split, turn_split}}})
    RecordProperty(name, std::to_string(rms.first) + " / " + std::to_string(rms.second));
  EXPECT_LT(straight_split, 0.9 * straight_wide) << straight_wide;
  EXPECT_LT(straight_split, straight_low + 0.005) << straight_low;
  EXPECT_LT(turn_split, 0.9 * turn_low) << turn_low;
  EXPECT_LT(turn_split, 0.9 * turn_wide) << turn_wide;
  // While the direction of travel is unknown (a new filter at rest) the noise is isotropic.
  KalmanCv a(Vec3::Zero(), wide), b(Vec3::Zero(), split);
  a.predict(0.1);
  b.predict(0.1);
  EXPECT_LT((a.covariance() - b.covariance()).norm(), 1e-12);
  EXPECT_FALSE(b.clearDirection(b.velocity()));
}
