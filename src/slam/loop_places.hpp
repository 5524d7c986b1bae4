#pragma once
// The vocabulary and keyframe database as the map sees them (issue 4): keyframes get their bag of
// words once, when they enter the database; culled keyframes leave it. Relocalisation (tracking
// thread) and loop detection (mapping thread) query it with the map locked.
#include <memory>
#include <set>
#include <vector>

#include "core/config/loop.hpp"
#include "slam/frame.hpp"
#include "slam/keyframe.hpp"
#include "slam/keyframe_database.hpp"
#include "slam/map.hpp"
#include "slam/vocabulary/vocabulary.hpp"

namespace dynanav {

class PlaceIndex {
 public:
  PlaceIndex(std::shared_ptr<const Vocabulary> vocabulary, const LoopConfig& config)
      : vocabulary_(std::move(vocabulary)), config_(config) {}

  /// Computes the keyframe's bag of words if it has none yet.
  void computeBow(KeyFrame& keyframe) const;
  void computeBow(const Frame& frame, BowVector& bow, FeatureVector& features) const;
  /// computeBow() and add to the database (map locked).
  void add(KeyFrame& keyframe);
  /// Removes keyframes that went bad or left the map (map locked).
  void eraseCulled(const Map& map);

  [[nodiscard]] const KeyframeDatabase& database() const { return database_; }
  [[nodiscard]] size_t size() const { return database_.size(); }
  /// Covisibility callback for database queries: the best 10 covisible keyframes (map locked).
  [[nodiscard]] static std::function<std::vector<KeyframeId>(KeyframeId)> covisibleOf(
      const Map& map);

 private:
  std::shared_ptr<const Vocabulary> vocabulary_;
  LoopConfig config_;
  KeyframeDatabase database_;
  std::set<KeyframeId> ids_;
};

/// Looks a keyframe up by id (nullptr if culled or bad).
KeyFrame* findKeyFrame(const Map& map, KeyframeId id);

}  // namespace dynanav
