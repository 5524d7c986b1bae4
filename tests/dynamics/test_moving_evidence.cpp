#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/keypoint_dynamics.hpp"
#include "dynamics/moving_evidence.hpp"
#include "slam/keyframe.hpp"
#include "slam/keypoint_drop.hpp"

using namespace dynanav;

TEST(MovingEvidence, ANewPointIsDroppedOnItsFirstFailureAsAOneFrameVoteWould) {
  const DynamicsConfig c;
  EXPECT_FALSE(movingByEvidence(0.f, c));
  EXPECT_TRUE(movingByEvidence(addMovingEvidence(0.f, DepthVote::kMoving, c), c));
  EXPECT_FALSE(movingByEvidence(addMovingEvidence(0.f, DepthVote::kStatic, c), c));
  EXPECT_EQ(addMovingEvidence(0.5f, DepthVote::kNone, c), 0.5f);
}

TEST(MovingEvidence, ALongStaticPointSurvivesOneFailureButNotTwoInARow) {
  const DynamicsConfig c;
  float e = 0.f;
  for (int k = 0; k < 20; ++k) e = addMovingEvidence(e, DepthVote::kStatic, c);
  EXPECT_FLOAT_EQ(e, float(c.moving_evidence_min));  // clamped: history does not make it immune
  e = addMovingEvidence(e, DepthVote::kMoving, c);
  EXPECT_FALSE(movingByEvidence(e, c)) << "one failure (a head turn's misregistration)";
  e = addMovingEvidence(e, DepthVote::kMoving, c);
  EXPECT_TRUE(movingByEvidence(e, c)) << "two in a row: it may have started moving";
}

TEST(MovingEvidence, APointVotedMovingStaysSuspectUntilItPassesSeveralTests) {
  const DynamicsConfig c;
  float e = 0.f;
  for (int k = 0; k < 5; ++k) e = addMovingEvidence(e, DepthVote::kMoving, c);
  EXPECT_FLOAT_EQ(e, float(c.moving_evidence_max));
  // Frames where the test cannot check it (no depth) keep it out.
  EXPECT_TRUE(movingByEvidence(addMovingEvidence(e, DepthVote::kNone, c), c));
  int passed = 0;
  while (movingByEvidence(e, c)) {
    e = addMovingEvidence(e, DepthVote::kStatic, c);
    ++passed;
  }
  EXPECT_EQ(passed, 4);
}

TEST(MovingEvidence, FuseKeepsUnmappedKeypointsOnTheirOwnVote) {
  const DynamicsConfig c;
  std::vector<bool> moving;
  const std::vector<float> after =
      fuseMovingEvidence({DepthVote::kMoving, DepthVote::kMoving, DepthVote::kNone},
                         {std::nanf(""), float(c.moving_evidence_min), 3.f}, c, moving);
  EXPECT_TRUE(std::isnan(after[0]));
  EXPECT_EQ(moving, (std::vector<bool>{true, false, true}));
  EXPECT_FLOAT_EQ(after[1], float(c.moving_evidence_min + c.moving_vote_log_odds));
  EXPECT_FLOAT_EQ(after[2], 3.f);
}

namespace {
/// One keypoint at the image centre matched to a map point 2 m ahead, measured at `measured_m`.
Frame frameMeasuring(float measured_m, const MapPointPtr& point) {
  Features f;
  f.keypoints.emplace_back(cv::Point2f(80, 60), 31.f);
  f.points = {cv::Point2f(80, 60)};
  f.depth_m = {measured_m};
  f.usable.assign(1, 1);
  f.instance_id.assign(1, 0);
  Frame frame(7, 0.0, f);
  frame.map_points[0] = point;
  return frame;
}
}  // namespace

TEST(MovingEvidence, DepthTestDropsByTheMapPointsHistoryAndStoresIt) {
  const DynamicsConfig c;
  const auto point = std::make_shared<MapPoint>(1, Vec3(0, 0, 2.0), nullptr);
  const auto run = [&](float measured_m) {
    Frame frame = frameMeasuring(measured_m, point);
    const MoverVerdict verdict = findDepthMovers(frame, predictedMapPointDepths(frame), c, {},
                                                 mapPointMovingEvidence(frame));
    applyKeypointDrop(frame, verdict.drop);
    return !verdict.drop.drop.empty();
  };
  // Static for a while: stored evidence falls; one occlusion 1 m nearer is then not enough...
  for (int k = 0; k < 6; ++k) EXPECT_FALSE(run(2.0f));
  EXPECT_FLOAT_EQ(point->moving_evidence, float(c.moving_evidence_min));
  EXPECT_FALSE(run(1.0f));
  // ...two are; and the point then stays out while the test passes once.
  EXPECT_TRUE(run(1.0f));
  EXPECT_TRUE(run(2.0f));
  // Without evidence (dynamics.moving_evidence off: System passes none): the one-frame vote.
  Frame frame = frameMeasuring(1.0f, point);
  EXPECT_FALSE(findDepthMovers(frame, predictedMapPointDepths(frame), c).drop.drop.empty());
}
