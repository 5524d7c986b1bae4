// The message policy, rule by rule: priorities, confirmation, the rate limit, repeat suppression
// and change detection, urgent interrupts, stale drops, the hold on news of a new person.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "assist/message_policy.hpp"

namespace dynanav {
namespace {

constexpr double kDt = 1.0 / 30.0;

Hazard approachingPerson(uint64_t id, double distance_m, double ttc_s, bool user_related) {
  Hazard h;
  h.object_id = id;
  h.class_name = "person";
  h.person = true;
  h.moving = true;
  h.distance_m = distance_m;
  h.speed_mps = 1.0;
  h.closing_mps = 1.6;
  h.t_closest_s = ttc_s;
  h.ttc_s = ttc_s;
  h.ttc_warn_s = ttc_s;
  h.closest_m = user_related ? 0.3 : 1.5;
  h.user_related = user_related;
  return h;
}

Hazard standingPerson(uint64_t id, double distance_m, double bearing_deg = 0.0) {
  Hazard h;
  h.object_id = id;
  h.class_name = "person";
  h.person = true;
  h.distance_m = distance_m;
  h.bearing_deg = bearing_deg;
  h.clock = clockOf(bearing_deg);
  return h;
}

/// Runs `frames` frames from `t0_s` with the same hazards; returns every message.
std::vector<FeedbackEvent> run(MessagePolicy& policy, double t0_s, int frames,
                               const std::vector<Hazard>& hazards) {
  std::vector<FeedbackEvent> all;
  for (int i = 0; i < frames; ++i)
    for (auto& e : policy.step(t0_s + i * kDt, hazards)) all.push_back(e);
  return all;
}

TEST(MessagePolicy, Priorities) {
  const AssistConfig c;
  EXPECT_EQ(classifyHazard(approachingPerson(1, 4, 2.4, true), true, c)->priority,
            FeedbackPriority::kUrgent);
  // Not user-related: at most advisory, however soon.
  EXPECT_EQ(classifyHazard(approachingPerson(1, 4, 1.0, false), true, c)->priority,
            FeedbackPriority::kAdvisory);
  EXPECT_EQ(classifyHazard(approachingPerson(1, 4, 3.5, true), true, c)->priority,
            FeedbackPriority::kAdvisory);
  // Passing far aside: no advisory; only news if never announced.
  Hazard passing = approachingPerson(1, 4, 2.0, false);
  passing.closest_m = 3.0;
  EXPECT_FALSE(classifyHazard(passing, true, c));
  EXPECT_EQ(classifyHazard(passing, false, c)->kind, "new_person");
  EXPECT_EQ(classifyHazard(standingPerson(2, 1.2), true, c)->kind, "nearby");
  EXPECT_FALSE(classifyHazard(standingPerson(2, 2.0), false, c));  // standing: no news
  Hazard chair = standingPerson(3, 1.0);
  chair.person = false;
  chair.class_name = "chair";
  chair.in_corridor_ahead = true;
  EXPECT_EQ(classifyHazard(chair, true, c)->kind, "obstacle");
  chair.in_corridor_ahead = false;
  EXPECT_FALSE(classifyHazard(chair, true, c));
}

TEST(MessagePolicy, UrgentNeedsConfirmFramesAndThenStartsAtOnce) {
  MessagePolicy policy(AssistConfig{}, Language::kEnglish);
  const std::vector<Hazard> h = {approachingPerson(1, 4.0, 2.2, true)};
  EXPECT_TRUE(policy.step(0.0, h).empty());  // one frame is not enough (a velocity spike)
  const auto events = policy.step(kDt, h);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].priority, FeedbackPriority::kUrgent);
  EXPECT_EQ(events[0].kind, "approaching");
  EXPECT_EQ(events[0].text, "Person, 12 o'clock, 4 metres, approaching fast");
  EXPECT_NEAR(events[0].ttc_s, 2.2, 1e-12);
  EXPECT_TRUE(events[0].user_related);
  EXPECT_GT(events[0].spoken_s, 0.5);
  EXPECT_LT(events[0].audio_start_s, 0.0);  // the audio stage fills it
  // A one-frame urgency raises no urgent warning (only, after its hold, the news of a person).
  MessagePolicy spiky(AssistConfig{}, Language::kEnglish);
  int said = 0;
  for (int i = 0; i < 30; ++i) {
    const std::vector<Hazard> frame = {i % 2 ? approachingPerson(1, 4.0, 2.2, true)
                                             : approachingPerson(1, 4.0, 6.0, false)};
    for (const FeedbackEvent& e : spiky.step(i * kDt, frame)) {
      EXPECT_EQ(e.priority, FeedbackPriority::kInfo) << i;
      ++said;
    }
  }
  EXPECT_EQ(said, 1);
}

TEST(MessagePolicy, NoRepeatWhileTheSituationIsUnchanged) {
  MessagePolicy policy(AssistConfig{}, Language::kEnglish);
  const auto events = run(policy, 0.0, 300, {standingPerson(1, 1.2)});  // 10 s
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].text, "Person, 12 o'clock, 1 metre, standing");
}

TEST(MessagePolicy, ChangesAreSaidAgain) {
  const AssistConfig c;
  {  // distance class: 1 m -> 0.5 m (moved 0.5 m)
    MessagePolicy policy(c, Language::kEnglish);
    run(policy, 0.0, 10, {standingPerson(1, 1.2)});
    const auto e = run(policy, 5.0, 10, {standingPerson(1, 0.6)});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].text, "Person, 12 o'clock, 0.5 metres, standing");
  }
  {  // noise across a class edge (1.2 <-> 1.3 m: 1 <-> 1.5 spoken) is not a change
    MessagePolicy policy(c, Language::kEnglish);
    run(policy, 0.0, 10, {standingPerson(1, 1.2)});
    EXPECT_TRUE(run(policy, 5.0, 10, {standingPerson(1, 1.3)}).empty());
  }
  {  // direction: 12 -> 2 o'clock
    MessagePolicy policy(c, Language::kEnglish);
    run(policy, 0.0, 10, {standingPerson(1, 1.2, 0.0)});
    const auto e = run(policy, 5.0, 10, {standingPerson(1, 1.2, 60.0)});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].clock, 2);
  }
  {  // a bearing wobble across the 12/1 o'clock edge (14 <-> 16 deg) is not a change
    MessagePolicy policy(c, Language::kEnglish);
    run(policy, 0.0, 10, {standingPerson(1, 1.2, 14.0)});
    EXPECT_TRUE(run(policy, 5.0, 10, {standingPerson(1, 1.2, 16.0)}).empty());
  }
  {  // speed class: standing -> approaching
    MessagePolicy policy(c, Language::kEnglish);
    run(policy, 0.0, 10, {standingPerson(1, 1.2)});
    Hazard walking = standingPerson(1, 1.2);
    walking.moving = true;
    walking.closing_mps = 0.6;
    const auto e = run(policy, 5.0, 10, {walking});
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].text, "Person, 12 o'clock, 1 metre, approaching");
  }
}

TEST(MessagePolicy, AtMostOneNonUrgentMessagePerGap) {
  MessagePolicy policy(AssistConfig{}, Language::kEnglish);
  // Two people near at once: the nearer first, the other after min_gap_s.
  std::vector<FeedbackEvent> events;
  for (int i = 0; i < 150; ++i)
    for (auto& e : policy.step(i * kDt, {standingPerson(1, 1.4), standingPerson(2, 1.0, -40)}))
      events.push_back(e);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].object_id, 2u);
  EXPECT_EQ(events[1].object_id, 1u);
  for (size_t k = 1; k < events.size(); ++k)
    EXPECT_GE(events[k].stamp_s - events[k - 1].stamp_s, 3.0 - 1e-9);
}

TEST(MessagePolicy, UrgentInterruptsAnAdvisory) {
  MessagePolicy policy(AssistConfig{}, Language::kEnglish);
  const auto first = run(policy, 0.0, 5, {standingPerson(1, 1.2)});
  ASSERT_EQ(first.size(), 1u);
  EXPECT_FALSE(first[0].interrupts);
  // 0.5 s later, while the advisory is still spoken: an urgent warning about someone else.
  const auto urgent =
      run(policy, 0.5, 3, {standingPerson(1, 1.2), approachingPerson(2, 3.0, 1.8, true)});
  ASSERT_EQ(urgent.size(), 1u);
  EXPECT_EQ(urgent[0].priority, FeedbackPriority::kUrgent);
  EXPECT_TRUE(urgent[0].interrupts);
  // Urgent messages are not rate-limited, but one at a time: a second urgent one waits for the
  // first to end, then starts without cutting anything off.
  const auto second = run(policy, 0.6, 120,
                          {standingPerson(1, 1.2), approachingPerson(2, 3.0, 1.8, true),
                           approachingPerson(3, 2.5, 1.5, true)});
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].object_id, 3u);
  EXPECT_GE(second[0].stamp_s, urgent[0].stamp_s + urgent[0].spoken_s - 1e-9);
  EXPECT_FALSE(second[0].interrupts);
}

TEST(MessagePolicy, MessageThatWaitedTooLongIsDropped) {
  AssistConfig c;
  c.min_gap_s = 10.0;  // the second message would wait 10 s: longer than stale_s
  MessagePolicy policy(c, Language::kEnglish);
  const auto events = run(policy, 0.0, 360, {standingPerson(1, 1.0), standingPerson(2, 1.2, 40)});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(policy.dropped(), 1);
  // Dropped counts as said: person 2 is announced again only when the situation changes.
  const auto later = run(policy, 12.0, 30, {standingPerson(1, 1.0), standingPerson(2, 1.2, 40)});
  EXPECT_TRUE(later.empty());
}

TEST(MessagePolicy, WaitingMessageIsDroppedWhenItsConditionEnds) {
  MessagePolicy policy(AssistConfig{}, Language::kEnglish);
  run(policy, 0.0, 5, {standingPerson(1, 1.0)});  // said; the rate limit runs for 3 s
  // Person 2 comes near for a moment, then walks off before its turn.
  EXPECT_TRUE(run(policy, 1.0, 10, {standingPerson(1, 1.0), standingPerson(2, 1.2)}).empty());
  const int dropped_before = policy.dropped();
  EXPECT_TRUE(run(policy, 1.4, 120, {standingPerson(1, 1.0), standingPerson(2, 2.5)}).empty());
  EXPECT_EQ(policy.dropped(), dropped_before + 1);
}

TEST(MessagePolicy, NewsOfANewPersonWaitsAndGivesWayToAHazard) {
  AssistConfig c;
  MessagePolicy policy(c, Language::kEnglish);
  Hazard far = approachingPerson(1, 5.0, 5.0, false);
  far.closest_m = 3.0;  // passing aside: only news
  const auto news = run(policy, 0.0, 30, {far});
  ASSERT_EQ(news.size(), 1u);
  EXPECT_EQ(news[0].priority, FeedbackPriority::kInfo);
  EXPECT_GE(news[0].stamp_s, c.info_hold_s - 1e-9);
  // A person who turns out to be coming our way within the hold gets the advisory instead.
  MessagePolicy second(c, Language::kEnglish);
  run(second, 0.0, 5, {far});
  const auto advisory = run(second, 5 * kDt, 60, {approachingPerson(1, 4.8, 3.5, false)});
  ASSERT_EQ(advisory.size(), 1u);
  EXPECT_EQ(advisory[0].priority, FeedbackPriority::kAdvisory);
}

TEST(MessagePolicy, GermanTemplates) {
  MessagePolicy policy(AssistConfig{}, Language::kGerman);
  const auto e = run(policy, 0.0, 3, {approachingPerson(1, 2.0, 1.2, true)});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].text, "Person, 12 Uhr, 2 Meter, kommt schnell näher");
  EXPECT_EQ(e[0].language, "de");
}

/// The priorities of every message `frames` frames of `hazard` raise, `seen` deciding per frame
/// whether the segmenter found the object.
std::vector<FeedbackPriority> prioritiesSaid(const AssistConfig& config, const Hazard& hazard,
                                             int frames, const std::function<bool(int)>& seen) {
  MessagePolicy policy(config, Language::kEnglish);
  std::vector<FeedbackPriority> said;
  for (int i = 0; i < frames; ++i) {
    Hazard h = hazard;
    h.seen = seen(i);
    for (const FeedbackEvent& e : policy.step(i * kDt, {h})) said.push_back(e.priority);
  }
  return said;
}

bool anyUrgent(const std::vector<FeedbackPriority>& said) {
  return std::count(said.begin(), said.end(), FeedbackPriority::kUrgent) > 0;
}

TEST(MessagePolicy, AnObjectCarriedByItsFlowAloneDoesNotBecomeUrgent) {
  // An approach the segmenter never confirms (a false segment carried by its points): the
  // advisory at most, however near its time to collision.
  const Hazard approach = approachingPerson(1, 4.0, 2.2, true);
  const AssistConfig c;
  const auto carried = prioritiesSaid(c, approach, 30, [](int) { return false; });
  EXPECT_FALSE(anyUrgent(carried));
  EXPECT_EQ(carried, std::vector<FeedbackPriority>{FeedbackPriority::kAdvisory});
  AssistConfig off;
  off.urgent_needs_sight = false;
  EXPECT_TRUE(anyUrgent(prioritiesSaid(off, approach, 30, [](int) { return false; })));
  // Found in the first frame only, with the urgency already there: the urgency carries on (a
  // walker found approaching and then lost in blur), confirmed on the next, carried, frame.
  const auto found_once = prioritiesSaid(c, approach, 30, [](int i) { return i == 0; });
  ASSERT_FALSE(found_once.empty());
  EXPECT_EQ(found_once.front(), FeedbackPriority::kUrgent);
}

TEST(MessagePolicy, AnUrgencyThatAroseWhileCarriedWaitsForTheSegmenter) {
  // Found while still far in time (6 s), then carried while the approach reads urgent: no urgent
  // warning until the segmenter finds it again (frame 20), then after confirm_frames.
  const AssistConfig c;
  MessagePolicy policy(c, Language::kEnglish);
  std::vector<std::pair<int, FeedbackPriority>> said;
  for (int i = 0; i < 30; ++i) {
    Hazard h = approachingPerson(1, 4.0, i < 5 ? 6.0 : 2.2, i >= 5);
    h.seen = i < 5 || i >= 20;
    for (const FeedbackEvent& e : policy.step(i * kDt, {h})) said.emplace_back(i, e.priority);
  }
  const auto first_urgent = std::find_if(said.begin(), said.end(), [](const auto& s) {
    return s.second == FeedbackPriority::kUrgent;
  });
  ASSERT_NE(first_urgent, said.end());
  EXPECT_EQ(first_urgent->first, 20 + c.confirm_frames - 1);
}

}  // namespace
}  // namespace dynanav
