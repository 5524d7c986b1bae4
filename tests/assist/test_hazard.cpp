// Hazard geometry in the wearer's body frame: closest approach, corridor, uncertainty, clock
// directions, the walking heading against the head's yaw, and the velocity fit.
#include <gtest/gtest.h>

#include <cmath>

#include "assist/body_frame.hpp"
#include "assist/hazard.hpp"
#include "assist/object_motion_fit.hpp"

namespace dynanav {
namespace {

/// A wearer at `origin` walking along +z (world) at `speed_mps`.
BodyFrame walkingNorth(double speed_mps, const Vec3& origin = Vec3::Zero()) {
  BodyFrame b;
  b.origin_world = origin;
  b.velocity_world_mps = Vec3(0, 0, speed_mps);
  b.walking = speed_mps > 0.0;
  b.valid = true;
  return b;
}

TrackedObject person(const Vec3& p_world, const Vec3& v_world_mps) {
  TrackedObject o;
  o.id = 1;
  o.class_name = "person";
  o.dynamic = true;
  o.p_world = p_world;
  o.v_world_mps = v_world_mps;
  return o;
}

TEST(Hazard, HeadOnWalkerClosestApproachAndTtc) {
  // 6 m ahead, 0.5 m to the right, walking at us at 1 m/s while we walk at 1 m/s: closing at
  // 2 m/s, closest approach 0.5 m after 3 s.
  const AssistConfig config;
  const Hazard h = assessHazard(person({0.5, 0.0, 6.0}, {0, 0, -1}), walkingNorth(1.0), config);
  EXPECT_TRUE(h.moving);
  EXPECT_NEAR(h.t_closest_s, 3.0, 1e-9);
  EXPECT_NEAR(h.closest_m, 0.5, 1e-9);
  EXPECT_NEAR(h.ttc_s, 3.0, 1e-9);
  EXPECT_NEAR(h.closing_mps, 2.0 * 6.0 / std::hypot(0.5, 6.0), 1e-9);
  EXPECT_TRUE(h.user_related);
  EXPECT_NEAR(h.distance_m, std::hypot(0.5, 6.0), 1e-9);
  EXPECT_EQ(h.clock, 12);
  EXPECT_GT(h.bearing_deg, 0.0);  // right of the walking direction
  EXPECT_TRUE(h.seen);
  TrackedObject carried = person({0.5, 0.0, 6.0}, {0, 0, -1});
  carried.missed_frames = 2;  // the segmenter missed it: carried by its flow points
  EXPECT_FALSE(assessHazard(carried, walkingNorth(1.0), config).seen);
}

TEST(Hazard, HeightDoesNotCount) {
  // The torso 0.6 m below the camera (y down): ground-plane distance and closest approach.
  const Hazard h =
      assessHazard(person({0.5, 0.6, 6.0}, {0, 0, -1}), walkingNorth(1.0), AssistConfig{});
  EXPECT_NEAR(h.closest_m, 0.5, 1e-9);
  EXPECT_NEAR(h.distance_m, std::hypot(0.5, 6.0), 1e-9);
}

TEST(Hazard, CorridorDecidesUserRelated) {
  AssistConfig config;
  const TrackedObject passing = person({1.5, 0.0, 6.0}, {0, 0, -1});
  const Hazard outside = assessHazard(passing, walkingNorth(1.0), config);
  EXPECT_NEAR(outside.closest_m, 1.5, 1e-9);
  EXPECT_FALSE(outside.user_related);
  EXPECT_GT(outside.ttc_s, 0.0);  // still closing: it has a time to closest approach
  config.corridor_m = 2.0;
  EXPECT_TRUE(assessHazard(passing, walkingNorth(1.0), config).user_related);
}

TEST(Hazard, OnlyWithinTheHorizon) {
  AssistConfig config;
  // On a collision course but 6 s away (12 m at 2 m/s closing).
  const TrackedObject far = person({0.0, 0.0, 12.0}, {0, 0, -1});
  EXPECT_FALSE(assessHazard(far, walkingNorth(1.0), config).user_related);
  config.user_horizon_s = 7.0;
  EXPECT_TRUE(assessHazard(far, walkingNorth(1.0), config).user_related);
}

TEST(Hazard, WalkingAwayHasNoTimeToCollision) {
  const Hazard h =
      assessHazard(person({0.0, 0.0, 2.0}, {0, 0, 1.4}), walkingNorth(0.8), AssistConfig{});
  EXPECT_LT(h.closing_mps, 0.0);
  EXPECT_LT(h.t_closest_s, 0.0);
  EXPECT_LT(h.ttc_s, 0.0);
  EXPECT_FALSE(h.user_related);
}

TEST(Hazard, UncertaintySpreadsTheMissDistanceAndAdvancesTheWarning) {
  AssistConfig config;
  TrackedObject o = person({1.0, 0.0, 6.0}, {0, 0, -1});  // passes 1.0 m aside, 3 s from now
  EXPECT_FALSE(assessHazard(o, walkingNorth(1.0), config).user_related);
  // Velocity sigma 0.2 m/s: 0.6 m after 3 s, so the corridor reaches 0.8 + 0.6 m.
  for (int k = 3; k < 6; ++k) o.covariance(k, k) = 0.04;
  const Hazard uncertain = assessHazard(o, walkingNorth(1.0), config);
  EXPECT_NEAR(uncertain.closest_sigma_m, 0.6, 1e-9);
  EXPECT_FALSE(uncertain.user_related);  // more likely outside than inside (below)
  EXPECT_NEAR(uncertain.ttc_s, 3.0, 1e-9);
  EXPECT_NEAR(uncertain.ttc_warn_s, 3.0 * 2.0 / 2.2, 1e-9);  // closing could be 0.2 m/s faster
  // Miss distance 1.0 m +- 0.6 m: inside +-0.8 m with probability Phi(-1/3) - Phi(-3).
  EXPECT_NEAR(uncertain.corridor_probability, 0.36944 - 0.00135, 1e-4);
  config.corridor_min_probability = 0.3;  // a user who wants warnings on weaker evidence
  EXPECT_TRUE(assessHazard(o, walkingNorth(1.0), config).user_related);
}

TEST(Hazard, CorridorProbabilityOfAGaussianMissDistance) {
  EXPECT_EQ(corridorProbability(0.5, 0.0, 0.8), 1.0);  // certain: the plain corridor
  EXPECT_EQ(corridorProbability(-0.9, 0.0, 0.8), 0.0);
  EXPECT_NEAR(corridorProbability(0.0, 0.8, 0.8), 0.682689, 1e-6);  // +-1 sigma
  EXPECT_NEAR(corridorProbability(1.3, 0.5, 0.8), corridorProbability(-1.3, 0.5, 0.8), 1e-12);
  EXPECT_NEAR(corridorProbability(1.8, 1e-3, 0.8), 0.0, 1e-12);
  // The default threshold (0.5) sits at the corridor's edge whatever a small sigma.
  EXPECT_NEAR(corridorProbability(0.8, 0.1, 0.8), 0.5, 1e-6);
  EXPECT_NEAR(corridorProbability(0.8, 0.02, 0.8), 0.5, 1e-6);
}

TEST(Hazard, UncertaintyAlongTheRelativePathDoesNotWidenTheCorridor) {
  // A walker crossing 1.7 m in front of a standing wearer, right to left at 1.4 m/s, whose
  // sideways position is unknown (cut by the image edge: 1 m sigma along world x) while its
  // depth is known to 5 cm. Along the path the uncertainty only moves the time of the closest
  // approach; the miss distance stays 1.7 +- 0.05 m: outside the 0.8 m corridor.
  TrackedObject crossing = person({3.0, 0.0, 1.7}, {-1.4, 0, 0});
  crossing.covariance(0, 0) = 1.0;
  crossing.covariance(2, 2) = 0.05 * 0.05;
  const Hazard h = assessHazard(crossing, walkingNorth(0.0), AssistConfig{});
  EXPECT_NEAR(h.closest_m, 1.7, 1e-9);
  EXPECT_NEAR(h.closest_sigma_m, 0.05, 1e-9);
  EXPECT_NEAR(h.corridor_probability, 0.0, 1e-9);
  EXPECT_GT(h.ttc_s, 0.0);
  EXPECT_FALSE(h.user_related);
  // The same uncertainty across the path (depth unknown to 1 m) makes it possible, not likely:
  // P(|N(1.7, 1)| <= 0.8) = Phi(-0.9) - Phi(-2.5).
  crossing.covariance(0, 0) = 0.05 * 0.05;
  crossing.covariance(2, 2) = 1.0;
  const Hazard across = assessHazard(crossing, walkingNorth(0.0), AssistConfig{});
  EXPECT_NEAR(across.closest_sigma_m, 1.0, 1e-9);
  EXPECT_NEAR(across.corridor_probability, 0.18406 - 0.00621, 1e-4);
  EXPECT_FALSE(across.user_related);
}

TEST(Hazard, AnUnknownPathIsNotACollisionCourse) {
  // Head-on but with the miss distance unknown to +-1.5 m: passing inside +-0.8 m has
  // probability 0.41, so the walker is not user-related yet (advisories by time to collision
  // still apply); known to +-0.5 m it is (0.89).
  TrackedObject o = person({0.0, 0.0, 6.0}, {0, 0, -1});
  o.covariance(0, 0) = 1.5 * 1.5;
  const Hazard unknown = assessHazard(o, walkingNorth(1.0), AssistConfig{});
  EXPECT_NEAR(unknown.corridor_probability, 0.406, 1e-3);
  EXPECT_FALSE(unknown.user_related);
  o.covariance(0, 0) = 0.25;
  EXPECT_TRUE(assessHazard(o, walkingNorth(1.0), AssistConfig{}).user_related);
}

TEST(Hazard, StaticObstacleHasDirectionAndDistanceOnly) {
  TrackedObject chair = person({0.3, 0.5, 1.2}, {0, 0, 0});
  chair.class_name = "chair";
  chair.dynamic = false;
  const Hazard h = assessHazard(chair, walkingNorth(1.0), AssistConfig{});
  EXPECT_FALSE(h.moving);
  EXPECT_LT(h.ttc_s, 0.0);
  EXPECT_LT(h.closest_m, 0.0);
  EXPECT_FALSE(h.user_related);
  EXPECT_TRUE(h.in_corridor_ahead);
  EXPECT_NEAR(h.distance_m, std::hypot(0.3, 1.2), 1e-9);
  chair.p_world = Vec3(-1.5, 0.5, 1.2);  // beside the path
  EXPECT_FALSE(assessHazard(chair, walkingNorth(1.0), AssistConfig{}).in_corridor_ahead);
}

TEST(Hazard, ClockPositions) {
  EXPECT_EQ(clockOf(0.0), 12);
  EXPECT_EQ(clockOf(30.0), 1);
  EXPECT_EQ(clockOf(60.0), 2);
  EXPECT_EQ(clockOf(-30.0), 11);
  EXPECT_EQ(clockOf(-90.0), 9);
  EXPECT_EQ(clockOf(180.0), 6);
  EXPECT_EQ(clockOf(-180.0), 6);
  EXPECT_EQ(clockOf(14.0), 12);
  EXPECT_EQ(clockOf(16.0), 1);
}

/// Camera pose: at z = z_m, yawed `yaw_rad` right of +z (camera y down, so a right turn is a
/// positive rotation about y).
SE3 cameraAt(double z_m, double yaw_rad, double x_m = 0.0) {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_rad, Vec3::UnitY()).toRotationMatrix();
  T.translation() = Vec3(x_m, 0, z_m);
  return T;
}

TEST(BodyFrame, HeadingIsTheWalkingDirectionNotTheHeadYaw) {
  AssistConfig config;
  BodyFrameTracker tracker(config);
  // Walking +z at 1 m/s for 3 s while the head looks 60 degrees left and right (period 2 s) and
  // sways 3 cm sideways with the stride.
  BodyFrame body;
  double yaw = 0.0;
  for (int i = 0; i <= 90; ++i) {
    const double t = i / 30.0;
    yaw = (60.0 * M_PI / 180.0) * std::sin(M_PI * t);
    body = tracker.update(t, cameraAt(t * 1.0, yaw, 0.03 * std::sin(2.0 * M_PI * t / 1.2)), true);
  }
  EXPECT_TRUE(body.walking);
  EXPECT_NEAR(body.velocity_world_mps.z(), 1.0, 0.05);
  EXPECT_LT(std::acos(body.forward_world.dot(Vec3::UnitZ())) * 180.0 / M_PI, 3.0);
  EXPECT_NEAR(body.right_world.x(), 1.0, 1e-3);
  // A person 3 m straight down the path is at 12 o'clock, wherever the head looks.
  TrackedObject ahead = person(body.origin_world + Vec3(0, 0.5, 3.0), Vec3::Zero());
  ahead.dynamic = false;
  const Hazard h = assessHazard(ahead, body, config);
  EXPECT_EQ(h.clock, 12);
  EXPECT_NEAR(h.bearing_deg, 0.0, 3.0);
}

TEST(BodyFrame, StandingStillFacesWhereTheCameraLooks) {
  AssistConfig config;
  BodyFrameTracker tracker(config);
  const double yaw = 90.0 * M_PI / 180.0;  // looking right (+x)
  BodyFrame body;
  for (int i = 0; i < 30; ++i) body = tracker.update(i / 30.0, cameraAt(0.0, yaw), true);
  EXPECT_FALSE(body.walking);
  EXPECT_NEAR(body.forward_world.x(), 1.0, 1e-9);
  // An untracked frame keeps the last body frame.
  const BodyFrame kept = tracker.update(1.1, cameraAt(5.0, 0.0), false);
  EXPECT_NEAR(kept.origin_world.z(), 0.0, 1e-12);
}

TEST(MotionFit, ExactLineAndRobustToOneJump) {
  std::vector<double> t;
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < 18; ++i) {
    t.push_back(i / 30.0);
    p.push_back(Eigen::Vector2d(1.4 * t.back(), 4.0));
  }
  GroundMotion fit;
  ASSERT_TRUE(fitLine(t, p, t.back(), 0.2, 0.05, fit));
  EXPECT_NEAR(fit.v.x(), 1.4, 1e-9);
  EXPECT_NEAR(fit.v.y(), 0.0, 1e-9);
  EXPECT_NEAR(fit.p.x(), 1.4 * t.back(), 1e-9);
  EXPECT_GT(fit.cov_vv(0, 0), 0.0);  // floored: a perfect line is not certain
  // The newest centre jumps 0.1 m (a resampled mask): one-frame velocity 3 m/s, the fit ~0.3.
  p.back().y() -= 0.1;
  ASSERT_TRUE(fitLine(t, p, t.back(), 0.2, 0.005, fit));
  EXPECT_LT(std::abs(fit.v.y()), 0.5);
  EXPECT_GT(std::sqrt(fit.cov_vv(1, 1)), std::sqrt(fit.cov_vv(0, 0)));  // residuals show it
  // Too short a history: no fit.
  EXPECT_FALSE(fitLine({0.0, 0.033, 0.066}, {p[0], p[1], p[2]}, 0.066, 0.2, 0.05, fit));
}

TEST(MotionFit, CentresAPartialViewCouldNotPlaceBarelyPullTheLine) {
  // A walker at 1.4 m/s along x. The first 9 centres come from a view cut by the image edge:
  // their x is unknown (1 m sigma from the tracker) and biased 0.3 m inwards; the last 9 are
  // measured to 2 cm.
  std::vector<double> t;
  std::vector<Eigen::Vector2d> p;
  std::vector<Eigen::Matrix2d> cov;
  for (int i = 0; i < 18; ++i) {
    t.push_back(i / 30.0);
    const bool cut = i < 9;
    p.push_back(Eigen::Vector2d(1.4 * t.back() + (cut ? 0.3 : 0.0), 4.0));
    cov.push_back(Eigen::Vector2d(cut ? 1.0 : 4e-4, 4e-4).asDiagonal());
  }
  GroundMotion weighted, plain;
  ASSERT_TRUE(fitLine(t, p, t.back(), 0.2, 0.02, weighted, cov));
  ASSERT_TRUE(fitLine(t, p, t.back(), 0.2, 0.02, plain));
  EXPECT_NEAR(weighted.v.x(), 1.4, 0.1);
  EXPECT_LT(plain.v.x(), 0.8);  // the unweighted line follows the bias: 0.65 m/s
  // Only cut views: the line's sideways velocity is as unknown as the centres were.
  for (auto& c : cov) c = Eigen::Vector2d(1.0, 4e-4).asDiagonal();
  ASSERT_TRUE(fitLine(t, p, t.back(), 0.2, 0.02, weighted, cov));
  EXPECT_GT(std::sqrt(weighted.cov_vv(0, 0)), 1.0);
  EXPECT_LT(std::sqrt(weighted.cov_vv(1, 1)), 0.2);
}

/// The motion history of an object reported moving that stands at z_before for 15 frames, then at
/// z_after (its centre measured on another extent or part of it) for 3: told so in the frame of
/// the jump by `tell` (setting TrackedObject::restarted or ::reanchored), or not told.
GroundMotion motionAfterAJump(const std::string& class_name, double z_before, double z_after,
                              void (*tell)(TrackedObject&)) {
  MotionHistory history{AssistConfig{}};
  std::vector<GroundMotion> motion;
  for (int i = 0; i < 18; ++i) {
    TrackedObject o;
    o.id = 7;
    o.class_name = class_name;
    o.dynamic = true;
    o.p_world = Vec3(0.0, 0.0, i < 15 ? z_before : z_after);
    o.covariance.topLeftCorner<3, 3>() = Mat3::Identity() * 4e-4;
    o.covariance.bottomRightCorner<3, 3>() = Mat3::Identity() * 0.01;
    if (tell && i == 15) tell(o);
    motion = history.update(i / 30.0, {o});
  }
  EXPECT_EQ(motion.size(), 1u);
  return motion.empty() ? GroundMotion{} : motion[0];
}

TEST(MotionHistory, AReanchoredTrackForgetsTheCentresOfItsOtherPart) {
  // A still person whose trunk is lost: its centre moves 0.25 m nearer, to the whole mask's.
  // Told that the tracker reanchored it there, the motion is the tracker's (standing); not told,
  // the line through the earlier centres reads an approach.
  const auto reanchor = [](TrackedObject& o) { o.reanchored = true; };
  EXPECT_LT(motionAfterAJump("person", 2.0, 1.75, reanchor).v.norm(), 0.05);
  EXPECT_LT(motionAfterAJump("person", 2.0, 1.75, nullptr).v.y(), -0.3);
}

TEST(MotionHistory, ARestartedTrackForgetsTheCentresOfItsOtherExtent) {
  // A chair reported moving (falsely) stands at 2.5 m for 15 frames; its segment then takes in a
  // neighbour and its centre jumps 0.5 m nearer. Told that the tracker restarted it there, the
  // motion is the tracker's (standing); not told, the line through the jump reads an approach.
  const auto restart = [](TrackedObject& o) { o.restarted = true; };
  EXPECT_LT(motionAfterAJump("chair", 2.5, 2.0, restart).v.norm(), 0.05);
  // Toward the wearer (world -z): 0.7 m/s.
  EXPECT_LT(motionAfterAJump("chair", 2.5, 2.0, nullptr).v.y(), -0.5);
}

}  // namespace
}  // namespace dynanav
