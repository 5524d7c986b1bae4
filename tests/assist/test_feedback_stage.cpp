// The feedback stage as the pipeline calls it: camera poses and tracked objects frame by frame
// in, messages out. A walker coming straight at a walking wearer gets an urgent warning at
// least 2 s before the closest approach; nothing is said without a tracked pose; identical
// input gives identical messages.
#include <gtest/gtest.h>

#include "assist/feedback_stage.hpp"

namespace dynanav {
namespace {

struct Encounter {
  std::vector<std::vector<FeedbackEvent>> events;  // per frame
  double t_closest_s = 0.0;
};

/// The wearer walks +z at 0.8 m/s from t = 0; a person 9 m ahead, 0.4 m to the right, walks
/// towards them at 1.0 m/s: closest approach at 5 s. The tracker's view of the person is noisy
/// (2 cm jitter, deterministic) and its velocity covariance small, as the real tracker's is.
Encounter walkerEncounter(bool tracked) {
  FeedbackStage stage(AssistConfig{});
  Encounter out;
  out.t_closest_s = 9.0 / 1.8;
  for (int i = 0; i < 180; ++i) {
    const double t = i / 30.0;
    SE3 T_world_camera = SE3::Identity();
    T_world_camera.translation() = Vec3(0.0, 0.0, 0.8 * t);
    TrackedObject o;
    o.id = 3;
    o.class_name = "person";
    o.dynamic = true;
    const double jitter = 0.02 * std::sin(7.3 * i);
    o.p_world = Vec3(0.4 + jitter, 0.6, 9.0 - 1.0 * t);
    o.v_world_mps = Vec3(0.0, 0.0, -1.0);
    for (int k = 0; k < 3; ++k) o.covariance(k, k) = 0.02 * 0.02;
    for (int k = 3; k < 6; ++k) o.covariance(k, k) = 0.2 * 0.2;
    out.events.push_back(stage.process({t, T_world_camera, tracked, {o}}));
  }
  return out;
}

TEST(FeedbackStage, WarnsAnApproachingWalkerInTime) {
  const Encounter run = walkerEncounter(true);
  double first_urgent_s = -1.0;
  int urgent = 0;
  for (const auto& frame : run.events)
    for (const FeedbackEvent& e : frame) {
      if (e.priority != FeedbackPriority::kUrgent) continue;
      ++urgent;
      if (first_urgent_s < 0.0) first_urgent_s = e.stamp_s;
      EXPECT_EQ(e.object_id, 3u);
      EXPECT_EQ(e.clock, 12);
      EXPECT_NE(e.text.find("approaching"), std::string::npos) << e.text;
    }
  ASSERT_GE(first_urgent_s, 0.0);
  EXPECT_GE(run.t_closest_s - first_urgent_s, 2.0);
  EXPECT_LE(run.t_closest_s - first_urgent_s, 4.0);  // and not absurdly early
}

TEST(FeedbackStage, SilentWithoutATrackedPose) {
  for (const auto& frame : walkerEncounter(false).events) EXPECT_TRUE(frame.empty());
}

TEST(FeedbackStage, Deterministic) {
  const Encounter a = walkerEncounter(true), b = walkerEncounter(true);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (size_t i = 0; i < a.events.size(); ++i) {
    ASSERT_EQ(a.events[i].size(), b.events[i].size());
    for (size_t k = 0; k < a.events[i].size(); ++k) {
      EXPECT_EQ(a.events[i][k].text, b.events[i][k].text);
      EXPECT_EQ(a.events[i][k].stamp_s, b.events[i][k].stamp_s);
    }
  }
}

}  // namespace
}  // namespace dynanav
