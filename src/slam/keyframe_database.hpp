#pragma once
// Inverted file over vocabulary words for place recognition (Gálvez-López & Tardós 2012; ORB-SLAM2
// §VI, §VII-A): for each word, the keyframes whose bag-of-words contain it, so a query scores only
// keyframes that share words with it. Independent of the keyframe class: it stores (id, BowVector)
// and takes the covisibility graph as a callback, so tracking and loop closing can wire it up.
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <vector>

#include "slam/vocabulary/bow_vector.hpp"

namespace dynanav {

using KeyframeId = uint64_t;

struct PlaceCandidate {
  KeyframeId id = 0;
  double score = 0.0;              // L1 score against the query
  double accumulated_score = 0.0;  // best score summed over its covisibility group (or = score)
  int common_words = 0;
};

struct PlaceQuery {
  /// Candidates must score at least this (loop closing: the lowest score of the query keyframe's
  /// covisible neighbours; relocalisation: 0).
  double min_score = 0.0;
  /// Candidates must share at least this fraction of the largest number of shared words
  /// (ORB-SLAM2: 0.8), which discards keyframes that only share a few common words.
  double min_common_words_ratio = 0.8;
  /// Keyframes to leave out (loop closing: the query's covisible keyframes). Optional.
  std::function<bool(KeyframeId)> exclude;
  /// Covisible neighbours of a keyframe (ORB-SLAM2 takes the best 10). When given, each
  /// candidate's score is accumulated over its neighbours that are candidates too, and only
  /// candidates whose group reaches `min_accumulated_ratio` of the best group are kept: one
  /// lucky keyframe alone does not make a place.
  std::function<std::vector<KeyframeId>(KeyframeId)> covisible;
  double min_accumulated_ratio = 0.75;
  /// 0 = all.
  size_t max_results = 0;
};

class KeyframeDatabase {
 public:
  /// Adds (or replaces) the keyframe's bag of words.
  void add(KeyframeId id, const BowVector& bow);
  /// Removes a keyframe (culled by local mapping); unknown ids are ignored.
  void erase(KeyframeId id);
  void clear();
  [[nodiscard]] size_t size() const;
  [[nodiscard]] bool contains(KeyframeId id) const;

  /// Candidates sharing words with `bow`, ordered by accumulated score, then score (both
  /// descending), then id (ascending): the same database and query always give the same list.
  /// The callbacks in `options` run under the database's lock: they must not call back into it.
  [[nodiscard]] std::vector<PlaceCandidate> query(const BowVector& bow, const PlaceQuery& options) const;

 private:
  // One mutex: tracking (relocalisation), local mapping (add/erase) and loop closing share it.
  mutable std::mutex mutex_;
  std::map<KeyframeId, BowVector> bows_;
  std::map<WordId, std::vector<KeyframeId>> inverted_;  // ids in insertion order per word
};

}  // namespace dynanav
