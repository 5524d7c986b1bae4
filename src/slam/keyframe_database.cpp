#include "slam/keyframe_database.hpp"

#include <algorithm>
#include <unordered_map>

namespace dynanav {

void KeyframeDatabase::add(KeyframeId id, const BowVector& bow) {
  std::lock_guard lock(mutex_);
  if (auto it = bows_.find(id); it != bows_.end()) {  // replace: drop the old postings first
    for (const auto& [word, weight] : it->second.entries) std::erase(inverted_[word], id);
  }
  bows_[id] = bow;
  for (const auto& [word, weight] : bow.entries) inverted_[word].push_back(id);
}

void KeyframeDatabase::erase(KeyframeId id) {
  std::lock_guard lock(mutex_);
  const auto it = bows_.find(id);
  if (it == bows_.end()) return;
  for (const auto& [word, weight] : it->second.entries) {
    auto posting = inverted_.find(word);
    if (posting == inverted_.end()) continue;
    std::erase(posting->second, id);
    if (posting->second.empty()) inverted_.erase(posting);
  }
  bows_.erase(it);
}

void KeyframeDatabase::clear() {
  std::lock_guard lock(mutex_);
  bows_.clear();
  inverted_.clear();
}

size_t KeyframeDatabase::size() const {
  std::lock_guard lock(mutex_);
  return bows_.size();
}

bool KeyframeDatabase::contains(KeyframeId id) const {
  std::lock_guard lock(mutex_);
  return bows_.count(id) > 0;
}

std::vector<PlaceCandidate> KeyframeDatabase::query(const BowVector& bow,
                                                    const PlaceQuery& options) const {
  std::lock_guard lock(mutex_);
  // 1. Keyframes sharing words with the query, and how many (ORB-SLAM2 DetectLoopCandidates).
  std::unordered_map<KeyframeId, int> shared;
  for (const auto& [word, weight] : bow.entries) {
    const auto posting = inverted_.find(word);
    if (posting == inverted_.end()) continue;
    for (KeyframeId id : posting->second) ++shared[id];
  }
  int max_shared = 0;
  for (const auto& [id, n] : shared) {
    if (options.exclude && options.exclude(id)) continue;
    max_shared = std::max(max_shared, n);
  }
  const int min_shared = std::max(1, static_cast<int>(options.min_common_words_ratio * max_shared));

  // 2. Score those with enough shared words.
  std::map<KeyframeId, PlaceCandidate> scored;  // ordered by id: deterministic accumulation
  for (const auto& [id, n] : shared) {
    if (n < min_shared || (options.exclude && options.exclude(id))) continue;
    const double s = l1Score(bow, bows_.at(id));
    if (s >= options.min_score) scored[id] = {id, s, s, n};
  }

  // 3. Group scores over the covisibility graph; keep the groups near the best one.
  std::vector<PlaceCandidate> out;
  if (options.covisible) {
    double best_group = 0.0;
    for (auto& [id, candidate] : scored) {
      double group = candidate.score;
      for (KeyframeId neighbour : options.covisible(id)) {
        if (neighbour == id) continue;
        if (const auto it = scored.find(neighbour); it != scored.end()) group += it->second.score;
      }
      candidate.accumulated_score = group;
      best_group = std::max(best_group, group);
    }
    for (const auto& [id, candidate] : scored)
      if (candidate.accumulated_score >= options.min_accumulated_ratio * best_group) out.push_back(candidate);
  } else {
    for (const auto& [id, candidate] : scored) out.push_back(candidate);
  }
  std::sort(out.begin(), out.end(), [](const PlaceCandidate& a, const PlaceCandidate& b) {
    if (a.accumulated_score != b.accumulated_score) return a.accumulated_score > b.accumulated_score;
    if (a.score != b.score) return a.score > b.score;
    return a.id < b.id;
  });
  if (options.max_results > 0 && out.size() > options.max_results) out.resize(options.max_results);
  return out;
}

}  // namespace dynanav
