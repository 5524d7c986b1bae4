#include "slam/loop_places.hpp"

namespace dynanav {

void PlaceIndex::computeBow(KeyFrame& keyframe) const {
  if (!keyframe.bow.empty()) return;
  vocabulary_->transform(keyframe.features.descriptors, keyframe.bow, &keyframe.bow_features,
                         config_.direct_index_depth);
}

void PlaceIndex::computeBow(const Frame& frame, BowVector& bow, FeatureVector& features) const {
  vocabulary_->transform(frame.features.descriptors, bow, &features, config_.direct_index_depth);
}

void PlaceIndex::add(KeyFrame& keyframe) {
  if (keyframe.bad) return;
  computeBow(keyframe);
  database_.add(keyframe.id, keyframe.bow);
  ids_.insert(keyframe.id);
}

void PlaceIndex::eraseCulled(const Map& map) {
  for (auto it = ids_.begin(); it != ids_.end();) {
    if (findKeyFrame(map, *it) == nullptr) {
      database_.erase(*it);
      it = ids_.erase(it);
    } else {
      ++it;
    }
  }
}

std::function<std::vector<KeyframeId>(KeyframeId)> PlaceIndex::covisibleOf(const Map& map) {
  return [&map](KeyframeId id) {
    std::vector<KeyframeId> out;
    if (KeyFrame* kf = findKeyFrame(map, id)) {
      for (KeyFrame* n : kf->bestCovisible(10)) out.push_back(n->id);
    }
    return out;
  };
}

KeyFrame* findKeyFrame(const Map& map, KeyframeId id) {
  const auto it = map.keyframes().find(id);
  if (it == map.keyframes().end() || it->second->bad) return nullptr;
  return it->second.get();
}

}  // namespace dynanav
