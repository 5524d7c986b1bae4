// Scoring messages against ground truth: closest approach, lead time of the first urgent
// warning, rate window, unchanged repeats.
#include <gtest/gtest.h>

#include "eval/event_metrics.hpp"

namespace dynanav {
namespace {

TEST(EventMetrics, MaxInWindowIsHalfOpen) {
  EXPECT_EQ(maxInWindow({}, 3.0), 0);
  EXPECT_EQ(maxInWindow({0.0, 3.0, 6.0}, 3.0), 1);
  EXPECT_EQ(maxInWindow({0.0, 2.9, 6.0}, 3.0), 2);
  EXPECT_EQ(maxInWindow({5.0, 0.0, 1.0, 2.0}, 3.0), 3);
}

FeedbackEvent message(double t, FeedbackPriority p, uint64_t id, const std::string& text,
                      const Vec3& p_world) {
  FeedbackEvent e;
  e.stamp_s = t;
  e.priority = p;
  e.object_id = id;
  e.text = text;
  e.p_world = p_world;
  return e;
}

TEST(EventMetrics, LeadTimeRateAndRepeats) {
  // The camera walks +z at 1 m/s; a person walks -z at 1 m/s from z = 10 with 0.5 m offset:
  // closest (0.5 m) at t = 5 s.
  std::vector<ObjectsFrame> gt;
  std::vector<StampedPose> poses;
  for (int i = 0; i <= 100; ++i) {
    const double t = i * 0.1;
    StampedPose pose;
    pose.stamp_s = t;
    pose.T_world_camera.translation() = Vec3(0, 0, t);
    poses.push_back(pose);
    ObjectsFrame f;
    f.stamp_s = t;
    TrackedObject o;
    o.id = 1;
    o.class_name = "person";
    o.p_world = Vec3(0.5, 0.6, 10.0 - t);
    f.objects.push_back(o);
    gt.push_back(f);
  }
  const Vec3 at2(0.5, 0.6, 8.0), at3(0.5, 0.6, 7.0), far(5.0, 0.0, 0.0);
  const std::vector<FeedbackEvent> events = {
      message(2.0, FeedbackPriority::kInfo, 7, "Person, 12 o'clock, 6 metres", at2),
      message(3.0, FeedbackPriority::kUrgent, 7, "Person, 12 o'clock, 4 metres", at3),
      message(3.5, FeedbackPriority::kAdvisory, 7, "Person, 12 o'clock, 4 metres", at3),
      message(4.0, FeedbackPriority::kAdvisory, 9, "Obstacle", far),
  };
  const EventMetrics m = scoreEvents(gt, poses, events);
  EXPECT_EQ(m.events, 4);
  EXPECT_EQ(m.urgent, 1);
  EXPECT_EQ(m.advisory, 2);
  EXPECT_EQ(m.info, 1);
  EXPECT_EQ(m.max_non_urgent_in_window, 3);  // 2.0, 3.5, 4.0
  EXPECT_EQ(m.unchanged_repeats, 1);
  EXPECT_EQ(m.unmatched, 1);
  ASSERT_EQ(m.people.size(), 1u);
  const PersonEncounter& p = m.people[0];
  EXPECT_NEAR(p.t_closest_s, 5.0, 1e-9);
  EXPECT_NEAR(p.closest_m, 0.5, 1e-9);
  EXPECT_TRUE(p.in_corridor);
  EXPECT_NEAR(p.lead_s, 2.0, 1e-9);
  EXPECT_LT(p.lead_audio_s, 0.0);  // not rendered
  EXPECT_NEAR(p.first_advisory_s, 3.5, 1e-9);
  EXPECT_EQ(p.urgent, 1);
}

}  // namespace
}  // namespace dynanav
