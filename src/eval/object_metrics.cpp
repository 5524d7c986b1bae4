#include "eval/object_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "core/median.hpp"

namespace dynanav {
namespace {

struct Sums {
  double position2 = 0, speed2 = 0, velocity2 = 0, moving2 = 0, stopped = 0, stopped2 = 0;
  double known2 = 0;  // speed errors of frames whose estimate reports its velocity as known
  int known = 0;
};

double rootMean(double sum2, int n) {
  return n ? std::sqrt(sum2 / n) : 0.0;
}

/// Index of the estimated frame nearest in time to `stamp_s`, or -1 beyond max_dt_s.
int nearestFrame(const std::vector<ObjectsFrame>& est, double stamp_s, double max_dt_s) {
  const auto it = std::lower_bound(est.begin(), est.end(), stamp_s,
                                   [](const ObjectsFrame& f, double t) { return f.stamp_s < t; });
  int best = -1;
  double best_dt = max_dt_s;
  for (auto c : {it, it == est.begin() ? it : it - 1}) {
    if (c == est.end()) continue;
    const double dt = std::abs(c->stamp_s - stamp_s);
    if (dt <= best_dt) {
      best_dt = dt;
      best = int(c - est.begin());
    }
  }
  return best;
}

}  // namespace

ObjectMetrics scoreObjects(const std::vector<ObjectsFrame>& gt,
                           const std::vector<ObjectsFrame>& est,
                           const ObjectMetricsOptions& options) {
  ObjectMetrics out;
  std::map<uint64_t, ObjectScore> scores;
  std::map<uint64_t, Sums> sums;
  std::map<uint64_t, uint64_t> last_track;  // gt id -> track id it was last matched to
  std::set<uint64_t> false_ids;
  Sums total;
  for (const ObjectsFrame& g : gt) {
    for (const TrackedObject& o : g.objects) {
      ObjectScore& s = scores[o.id];
      s.gt_id = o.id;
      s.class_name = o.class_name;
    }
    const int e_index = nearestFrame(est, g.stamp_s, options.max_dt_s);
    if (e_index < 0) continue;
    ++out.frames;
    const ObjectsFrame& e = est[size_t(e_index)];
    // Greedy nearest-first matching over all pairs within max_match_m.
    std::vector<std::tuple<double, size_t, size_t>> pairs;
    for (size_t i = 0; i < g.objects.size(); ++i)
      for (size_t j = 0; j < e.objects.size(); ++j) {
        const double d = (g.objects[i].p_world - e.objects[j].p_world).norm();
        if (d <= options.max_match_m) pairs.emplace_back(d, i, j);
      }
    std::sort(pairs.begin(), pairs.end());
    std::vector<int> est_of(g.objects.size(), -1);
    std::vector<uint8_t> est_used(e.objects.size(), 0);
    for (const auto& [d, i, j] : pairs) {
      if (est_of[i] >= 0 || est_used[j]) continue;
      est_of[i] = int(j);
      est_used[j] = 1;
    }
    for (size_t j = 0; j < e.objects.size(); ++j)
      if (!est_used[j]) {
        ++out.false_tracks;
        false_ids.insert(e.objects[j].id);
      }
    for (size_t i = 0; i < g.objects.size(); ++i) {
      const TrackedObject& truth = g.objects[i];
      const bool visible = truth.visible_share >= 0.0
                               ? truth.visible_share >= options.min_visible_share
                               : truth.points > 0;
      if (!visible) continue;
      ObjectScore& s = scores[truth.id];
      Sums& sum = sums[truth.id];
      ++s.scored_frames;
      ++out.scored;
      if (est_of[i] < 0) continue;
      const TrackedObject& guess = e.objects[size_t(est_of[i])];
      ++s.matched;
      ++out.matched;
      const auto last = last_track.find(truth.id);
      if (last != last_track.end() && last->second != guess.id) {
        ++s.id_switches;
        ++out.id_switches;
      }
      last_track[truth.id] = guess.id;
      const double dp2 = (guess.p_world - truth.p_world).squaredNorm();
      const double ds = guess.speed_mps - truth.speed_mps;
      const double dv2 = (guess.v_world_mps - truth.v_world_mps).squaredNorm();
      sum.position2 += dp2;
      sum.speed2 += ds * ds;
      sum.velocity2 += dv2;
      total.position2 += dp2;
      total.speed2 += ds * ds;
      total.velocity2 += dv2;
      if (guess.velocity_known) {
        sum.known2 += ds * ds;
        ++sum.known;
        total.known2 += ds * ds;
        ++total.known;
      }
      if (truth.speed_mps > options.moving_mps) {
        ++s.moving_frames;
        sum.moving2 += ds * ds;
      } else {
        ++s.stopped_frames;
        sum.stopped += guess.speed_mps;
        sum.stopped2 += ds * ds;
        s.speed_max_stopped_mps = std::max(s.speed_max_stopped_mps, guess.speed_mps);
      }
    }
  }
  for (auto& [id, s] : scores) {
    const Sums& sum = sums[id];
    s.position_rmse_m = rootMean(sum.position2, s.matched);
    s.speed_rmse_mps = rootMean(sum.speed2, s.matched);
    s.velocity_rmse_mps = rootMean(sum.velocity2, s.matched);
    s.speed_rmse_moving_mps = rootMean(sum.moving2, s.moving_frames);
    s.speed_known_frames = sum.known;
    s.speed_rmse_known_mps = rootMean(sum.known2, sum.known);
    s.speed_mean_stopped_mps = s.stopped_frames ? sum.stopped / s.stopped_frames : 0.0;
    s.speed_rmse_stopped_mps = rootMean(sum.stopped2, s.stopped_frames);
    out.objects.push_back(s);
  }
  out.position_rmse_m = rootMean(total.position2, out.matched);
  out.speed_rmse_mps = rootMean(total.speed2, out.matched);
  out.velocity_rmse_mps = rootMean(total.velocity2, out.matched);
  out.speed_known_frames = total.known;
  out.speed_rmse_known_mps = rootMean(total.known2, total.known);
  out.false_track_ids = int(false_ids.size());
  return out;
}

std::vector<TrackSpeedShare> trackSpeedShares(const std::vector<ObjectsFrame>& est, double min_mps,
                                              double max_mps) {
  std::map<uint64_t, TrackSpeedShare> shares;
  std::map<uint64_t, std::vector<double>> speeds;
  for (const ObjectsFrame& f : est)
    for (const TrackedObject& o : f.objects) {
      TrackSpeedShare& s = shares[o.id];
      s.id = o.id;
      s.class_name = o.class_name;
      ++s.frames;
      if (!o.dynamic) continue;
      ++s.dynamic_frames;
      s.in_band += o.speed_mps >= min_mps && o.speed_mps <= max_mps ? 1 : 0;
      speeds[o.id].push_back(o.speed_mps);
    }
  std::vector<TrackSpeedShare> out;
  for (auto& [id, s] : shares) {
    auto& v = speeds[id];
    if (!v.empty()) {
      s.median_speed_mps = medianInPlace(v);
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace dynanav
