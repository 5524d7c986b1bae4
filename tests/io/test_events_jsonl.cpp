// events.jsonl: what the writer writes the reader reads back; null for "none"; bad lines name
// the file and line.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "io/events_jsonl.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
using dynanav::test::scratchDir;

TEST(EventsJsonl, RoundTripWithNulls) {
  const auto dir = scratchDir("events_jsonl");
  FeedbackEvent a;
  a.stamp_s = 4.633333;
  a.priority = FeedbackPriority::kUrgent;
  a.kind = "approaching";
  a.text = "Person, 12 Uhr, 4 Meter, kommt schnell näher";
  a.object_id = 12;
  a.bearing_deg = -6.5;
  a.distance_m = 4.25;
  a.ttc_s = 2.4;
  a.audio_start_s = 4.7;
  a.clock = 12;
  a.closest_m = 0.4;
  a.user_related = true;
  a.interrupts = true;
  a.spoken_s = 3.2;
  a.p_world = Vec3(0.5, -0.25, 7.0);
  a.language = "de";
  FeedbackEvent b;  // not rendered, no time to collision
  b.stamp_s = 9.8;
  b.priority = FeedbackPriority::kAdvisory;
  b.kind = "nearby";
  b.text = "Person, 12 o'clock, 1.5 metres, standing";
  {
    EventsWriter writer(dir / "events.jsonl");
    writer.write(a);
    writer.write(b);
  }
  const std::string text = test::readFile(dir / "events.jsonl");
  EXPECT_NE(text.find("\"audio_start\":null"), std::string::npos) << text;
  EXPECT_NE(text.find("\"ttc\":null"), std::string::npos) << text;
  const auto events = readEventsJsonl(dir / "events.jsonl");
  ASSERT_EQ(events.size(), 2u);
  const FeedbackEvent& r = events[0];
  EXPECT_EQ(r.stamp_s, a.stamp_s);
  EXPECT_EQ(r.priority, a.priority);
  EXPECT_EQ(r.kind, a.kind);
  EXPECT_EQ(r.text, a.text);
  EXPECT_EQ(r.object_id, a.object_id);
  EXPECT_EQ(r.bearing_deg, a.bearing_deg);
  EXPECT_EQ(r.distance_m, a.distance_m);
  EXPECT_EQ(r.ttc_s, a.ttc_s);
  EXPECT_EQ(r.audio_start_s, a.audio_start_s);
  EXPECT_EQ(r.closest_m, a.closest_m);
  EXPECT_TRUE(r.user_related);
  EXPECT_TRUE(r.interrupts);
  EXPECT_EQ(r.p_world, a.p_world);
  EXPECT_EQ(r.language, "de");
  EXPECT_LT(events[1].ttc_s, 0.0);
  EXPECT_LT(events[1].audio_start_s, 0.0);
  EXPECT_LT(events[1].closest_m, 0.0);
  EXPECT_EQ(events[1].priority, FeedbackPriority::kAdvisory);
}

TEST(EventsJsonl, DesignKeysOnlyAreEnough) {
  const auto dir = scratchDir("events_jsonl_min");
  std::ofstream(dir / "e.jsonl")
      << R"({"t":1.5,"priority":"info","kind":"new_person","text":"Person","object_id":2,)"
      << R"("bearing_deg":10,"distance":3,"ttc":null,"audio_start":null})"
      << "\n";
  const auto events = readEventsJsonl(dir / "e.jsonl");
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].priority, FeedbackPriority::kInfo);
  EXPECT_EQ(events[0].clock, 12);
}

TEST(EventsJsonl, BadLinesNameFileAndLine) {
  const auto dir = scratchDir("events_jsonl_bad");
  const std::string good =
      R"({"t":1,"priority":"urgent","kind":"k","text":"x","object_id":1,"bearing_deg":0,)"
      R"("distance":1,"ttc":1,"audio_start":null})";
  for (const std::string& bad : {std::string("{not json"), std::string(R"({"t":1})"),
                                 std::string(good).replace(good.find("urgent"), 6, "loud")}) {
    std::ofstream(dir / "e.jsonl") << good << "\n" << bad << "\n";
    const std::string message = test::errorOf([&] { readEventsJsonl(dir / "e.jsonl"); });
    EXPECT_NE(message.find("e.jsonl:2"), std::string::npos) << bad << " -> " << message;
  }
}
