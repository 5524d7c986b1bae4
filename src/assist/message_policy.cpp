#include "assist/message_policy.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {
namespace {

int rank(FeedbackPriority p) {
  return static_cast<int>(p);  // kInfo < kAdvisory < kUrgent
}

double angleBetweenDeg(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

}  // namespace

std::optional<MessageCandidate> classifyHazard(const Hazard& h, bool announced,
                                               const AssistConfig& config, bool urgent_allowed) {
  const bool closing = h.ttc_warn_s >= 0.0;
  if (urgent_allowed && h.user_related && closing && h.ttc_warn_s <= config.urgent_ttc_s)
    return MessageCandidate{FeedbackPriority::kUrgent, "approaching"};
  if (closing && h.ttc_warn_s <= config.advisory_ttc_s && h.closest_m <= config.advisory_pass_m)
    return MessageCandidate{FeedbackPriority::kAdvisory, "approaching"};
  if (h.person && h.distance_m <= config.near_person_m)
    return MessageCandidate{FeedbackPriority::kAdvisory, "nearby"};
  if (!h.person && !h.moving && h.in_corridor_ahead && h.distance_m <= config.obstacle_ahead_m)
    return MessageCandidate{FeedbackPriority::kAdvisory, "obstacle"};
  if (h.person && h.moving && !announced)
    return MessageCandidate{FeedbackPriority::kInfo, "new_person"};
  return std::nullopt;
}

MessagePolicy::MessagePolicy(const AssistConfig& config, Language language)
    : config_(config), language_(language) {}

bool MessagePolicy::changed(const Said& said, FeedbackPriority priority, const Hazard& h,
                            MotionWord motion) const {
  if (rank(priority) > rank(said.priority)) return true;  // it became more pressing
  if (motion != said.motion) return true;
  // Class edges need a real move too, so noise around an edge does not repeat a message.
  if (h.clock != said.clock &&
      angleBetweenDeg(h.bearing_deg, said.bearing_deg) >= config_.repeat_bearing_deg)
    return true;
  return spokenDistanceM(h.distance_m) != spokenDistanceM(said.distance_m) &&
         std::abs(h.distance_m - said.distance_m) >= config_.repeat_distance_m;
}

bool MessagePolicy::confirmed(double stamp_s, const Hazard& h,
                              const std::optional<MessageCandidate>& candidate) {
  // A streak per priority: frames in a row the condition of that priority (or a higher one) held.
  Streaks& s = streaks_[h.object_id];
  const int level = candidate ? rank(candidate->priority) : -1;
  if (s.info == 0) s.info_since_s = stamp_s;
  s.info = level >= rank(FeedbackPriority::kInfo) ? s.info + 1 : 0;
  s.advisory = level >= rank(FeedbackPriority::kAdvisory) ? s.advisory + 1 : 0;
  s.urgent = level >= rank(FeedbackPriority::kUrgent) ? s.urgent + 1 : 0;
  if (!candidate) return false;
  const int streak = candidate->priority == FeedbackPriority::kUrgent     ? s.urgent
                     : candidate->priority == FeedbackPriority::kAdvisory ? s.advisory
                                                                          : s.info;
  // "A new person" waits info_hold_s: if the person turns out to be a hazard within that time,
  // the one message about them is the advisory, not the news (the rate limit allows only one).
  if (candidate->priority == FeedbackPriority::kInfo &&
      stamp_s - s.info_since_s < config_.info_hold_s)
    return false;
  return streak >= config_.confirm_frames;
}

FeedbackEvent MessagePolicy::makeEvent(double stamp_s, const MessageCandidate& candidate,
                                       const Hazard& h, MotionWord motion) const {
  FeedbackEvent e;
  e.stamp_s = stamp_s;
  e.priority = candidate.priority;
  e.kind = candidate.kind;
  e.text = phrase({h.person, h.clock, h.distance_m, motion}, language_);
  e.object_id = h.object_id;
  e.bearing_deg = h.bearing_deg;
  e.distance_m = h.distance_m;
  e.ttc_s = h.ttc_s;
  e.clock = h.clock;
  e.closest_m = h.closest_m;
  e.user_related = h.user_related;
  e.spoken_s = spokenDurationS(e.text, config_);
  e.p_world = h.p_world;
  e.language = languageCode(language_);
  return e;
}

void MessagePolicy::remember(const Pending& p) {
  said_[p.event.object_id] = {p.event.priority, p.event.clock, p.event.bearing_deg,
                              p.event.distance_m, p.motion};
}

std::optional<uint64_t> MessagePolicy::choose(double stamp_s) const {
  const bool idle = stamp_s >= busy_until_s_;
  std::optional<uint64_t> best;
  auto better = [&](const FeedbackEvent& a, const FeedbackEvent& b) {
    if (a.priority != b.priority) return rank(a.priority) > rank(b.priority);
    if (a.priority == FeedbackPriority::kUrgent && a.ttc_s != b.ttc_s) return a.ttc_s < b.ttc_s;
    return a.distance_m < b.distance_m;  // ties: the nearer object (then the lower id)
  };
  for (const auto& [id, p] : pending_)
    if (!best || better(p.event, pending_.at(*best).event)) best = id;
  if (!best) return std::nullopt;
  if (pending_.at(*best).event.priority == FeedbackPriority::kUrgent)
    return (idle || !speaking_urgent_) ? best : std::nullopt;  // urgent interrupts non-urgent
  if (idle && stamp_s - last_non_urgent_s_ >= config_.min_gap_s) return best;
  return std::nullopt;
}

std::vector<FeedbackEvent> MessagePolicy::step(double stamp_s, const std::vector<Hazard>& hazards) {
  std::map<uint64_t, Pending> fresh;
  for (const Hazard& h : hazards) {
    const auto said = said_.find(h.object_id);
    const bool announced = said != said_.end();
    // Urgency is for what the segmenter confirms: carried by its flow points alone, an object
    // keeps the urgency it had when last found but does not gain one (a carried false segment's
    // points drift with the depth's error and read as an approach; a walker found approaching and
    // then lost in blur stays urgent).
    bool& urgent_when_seen = streaks_[h.object_id].urgent_when_seen;
    const bool urgent_allowed = !config_.urgent_needs_sight || h.seen || urgent_when_seen;
    const auto candidate = classifyHazard(h, announced, config_, urgent_allowed);
    if (h.seen) urgent_when_seen = candidate && candidate->priority == FeedbackPriority::kUrgent;
    const auto waiting = pending_.find(h.object_id);
    if (!confirmed(stamp_s, h, candidate)) {
      // A condition still being confirmed (say, a new urgency) keeps what was waiting as it was.
      if (candidate && waiting != pending_.end()) fresh.insert(*waiting);
      continue;
    }
    const MessageCandidate& message = *candidate;
    const MotionWord motion = motionWordOf(h.person, h.moving, h.closing_mps, config_);
    if (announced && !changed(said->second, message.priority, h, motion)) continue;
    const double raised_s = waiting != pending_.end() ? waiting->second.raised_s : stamp_s;
    fresh[h.object_id] = {makeEvent(stamp_s, message, h, motion), motion, raised_s};
  }
  // Waiting messages whose condition ended are stale; the rest carry this frame's values.
  for (const auto& [id, p] : pending_) dropped_ += fresh.count(id) ? 0 : 1;
  std::erase_if(streaks_, [&](const auto& entry) {
    return std::none_of(hazards.begin(), hazards.end(),
                        [&](const Hazard& h) { return h.object_id == entry.first; });
  });
  pending_ = std::move(fresh);
  // Old news: a message that waited too long is dropped; the object is spoken of again when its
  // situation changes.
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (stamp_s - it->second.raised_s <= config_.stale_s) {
      ++it;
      continue;
    }
    remember(it->second);
    ++dropped_;
    it = pending_.erase(it);
  }
  std::vector<FeedbackEvent> starting;
  const auto chosen = choose(stamp_s);
  if (!chosen) return starting;
  Pending p = pending_.at(*chosen);
  pending_.erase(*chosen);
  const bool urgent = p.event.priority == FeedbackPriority::kUrgent;
  p.event.interrupts = urgent && stamp_s < busy_until_s_;
  busy_until_s_ = stamp_s + p.event.spoken_s;
  speaking_urgent_ = urgent;
  if (!urgent) last_non_urgent_s_ = stamp_s;
  remember(p);
  starting.push_back(std::move(p.event));
  return starting;
}

}  // namespace dynanav
