#include "eval/event_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"

namespace dynanav {
namespace {

double groundDistance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x() - b.x(), a.z() - b.z());
}

/// The item whose stamp is nearest to t (items sorted by stamp), or null beyond max_dt_s.
template <class T, class Stamp>
const T* nearest(const std::vector<T>& items, double t, double max_dt_s, Stamp stamp) {
  auto it = std::lower_bound(items.begin(), items.end(), t,
                             [&](const T& item, double v) { return stamp(item) < v; });
  const T* best = nullptr;
  for (auto c : {it, it == items.begin() ? it : std::prev(it)}) {
    if (c == items.end()) continue;
    if (!best || std::abs(stamp(*c) - t) < std::abs(stamp(*best) - t)) best = &*c;
  }
  return best && std::abs(stamp(*best) - t) <= max_dt_s ? best : nullptr;
}

}  // namespace

int maxInWindow(std::vector<double> stamps_s, double window_s) {
  std::sort(stamps_s.begin(), stamps_s.end());
  int best = 0;
  size_t lo = 0;
  for (size_t hi = 0; hi < stamps_s.size(); ++hi) {
    while (stamps_s[hi] - stamps_s[lo] >= window_s) ++lo;
    best = std::max(best, int(hi - lo + 1));
  }
  return best;
}

EventMetrics scoreEvents(const std::vector<ObjectsFrame>& gt,
                         const std::vector<StampedPose>& gt_poses,
                         const std::vector<FeedbackEvent>& events,
                         const EventMetricsOptions& options) {
  EventMetrics m;
  // Ground truth: each person's closest approach to the camera.
  std::map<uint64_t, PersonEncounter> people;
  for (const ObjectsFrame& frame : gt) {
    const StampedPose* pose = nearest(gt_poses, frame.stamp_s, options.max_dt_s,
                                      [](const StampedPose& p) { return p.stamp_s; });
    if (!pose)
      throw InputError("ground-truth poses", "no pose within " + std::to_string(options.max_dt_s) +
                                                 " s of the objects frame at " +
                                                 std::to_string(frame.stamp_s) + " s");
    const Vec3 camera = pose->T_world_camera.translation();
    for (const TrackedObject& o : frame.objects) {
      if (o.class_name != "person") continue;
      const double d = groundDistance(o.p_world, camera);
      auto [it, fresh] = people.try_emplace(o.id);
      PersonEncounter& p = it->second;
      if (fresh || d < p.closest_m) {
        p.gt_id = o.id;
        p.closest_m = d;
        p.t_closest_s = frame.stamp_s;
      }
    }
  }
  for (auto& [id, p] : people) p.in_corridor = p.closest_m <= options.corridor_m;

  std::map<uint64_t, const FeedbackEvent*> previous;  // by the run's object id
  std::vector<double> non_urgent;
  for (const FeedbackEvent& e : events) {
    ++m.events;
    const bool urgent = e.priority == FeedbackPriority::kUrgent;
    m.urgent += urgent ? 1 : 0;
    m.advisory += e.priority == FeedbackPriority::kAdvisory ? 1 : 0;
    m.info += e.priority == FeedbackPriority::kInfo ? 1 : 0;
    if (!urgent) non_urgent.push_back(e.stamp_s);
    const auto before = previous.find(e.object_id);
    if (before != previous.end() && before->second->text == e.text) ++m.unchanged_repeats;
    previous[e.object_id] = &e;
    // Which person it is about: the nearest at the message's time.
    const ObjectsFrame* frame =
        nearest(gt, e.stamp_s, options.max_dt_s, [](const ObjectsFrame& f) { return f.stamp_s; });
    PersonEncounter* match = nullptr;
    double best = options.match_m;
    if (frame)
      for (const TrackedObject& o : frame->objects) {
        const double d = (o.p_world - e.p_world).norm();
        if (o.class_name == "person" && d <= best) best = d, match = &people.at(o.id);
      }
    if (!match) {
      ++m.unmatched;
      continue;
    }
    match->urgent += urgent ? 1 : 0;
    match->advisory += e.priority == FeedbackPriority::kAdvisory ? 1 : 0;
    match->info += e.priority == FeedbackPriority::kInfo ? 1 : 0;
    if (e.stamp_s > match->t_closest_s) continue;
    if (urgent && match->first_urgent_s < 0.0) {
      match->first_urgent_s = e.stamp_s;
      match->lead_s = match->t_closest_s - e.stamp_s;
      if (e.audio_start_s >= 0.0) match->lead_audio_s = match->t_closest_s - e.audio_start_s;
    }
    if (e.priority == FeedbackPriority::kAdvisory && match->first_advisory_s < 0.0)
      match->first_advisory_s = e.stamp_s;
  }
  m.max_non_urgent_in_window = maxInWindow(non_urgent, options.window_s);
  for (const auto& [id, p] : people) m.people.push_back(p);
  return m;
}

}  // namespace dynanav
