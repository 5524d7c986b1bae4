#include "slam/loop_detector.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace dynanav {

std::vector<KeyFrame*> LoopDetector::detect(KeyFrame& keyframe, const PlaceIndex& places,
                                            const Map& map) {
  // The lowest similarity to a covisible neighbour: a loop keyframe must look at least as much
  // like this one as the keyframes that share its view do.
  double min_score = 1.0;
  std::set<KeyframeId> connected{keyframe.id};
  for (KeyFrame* n : keyframe.ordered_covisible) {
    connected.insert(n->id);
    if (n->bad || n->bow.empty()) continue;
    min_score = std::min(min_score, l1Score(keyframe.bow, n->bow));
  }
  if (keyframe.ordered_covisible.empty()) min_score = 0.0;
  PlaceQuery query;
  query.min_score = min_score;
  query.min_common_words_ratio = config_.min_common_words_ratio;
  query.min_accumulated_ratio = config_.min_accumulated_ratio;
  query.exclude = [&connected](KeyframeId id) { return connected.count(id) > 0; };
  query.covisible = PlaceIndex::covisibleOf(map);
  const auto candidates = places.database().query(keyframe.bow, query);
  if (candidates.empty()) {
    groups_.clear();
    return {};
  }
  // Temporal consistency: each candidate's group (it and its covisible keyframes) is compared
  // with the groups that were consistent for the previous keyframe; sharing a keyframe extends
  // the chain by one.
  std::vector<KeyFrame*> accepted;
  std::vector<ConsistentGroup> current;
  std::vector<uint8_t> previous_extended(groups_.size(), 0);
  for (const auto& c : candidates) {
    KeyFrame* candidate = findKeyFrame(map, c.id);
    if (!candidate) continue;
    ConsistentGroup group;
    group.keyframes.insert(candidate->id);
    for (KeyFrame* n : candidate->ordered_covisible) group.keyframes.insert(n->id);
    bool enough = false, extended_any = false;
    for (size_t g = 0; g < groups_.size(); ++g) {
      const bool shares =
          std::any_of(group.keyframes.begin(), group.keyframes.end(),
                      [&](KeyframeId id) { return groups_[g].keyframes.count(id) > 0; });
      if (!shares) continue;
      extended_any = true;
      const int consistency = groups_[g].consistency + 1;
      if (!previous_extended[g]) {
        current.push_back({group.keyframes, consistency});
        previous_extended[g] = 1;
      }
      if (consistency >= config_.loop_consistency && !enough) {
        accepted.push_back(candidate);
        enough = true;  // one acceptance per candidate
      }
    }
    if (!extended_any) current.push_back({group.keyframes, 0});
  }
  groups_ = std::move(current);
  spdlog::debug("loop detection kf {}: {} candidates (min score {:.4f}), {} consistent",
                keyframe.id, candidates.size(), min_score, accepted.size());
  return accepted;
}

}  // namespace dynanav
