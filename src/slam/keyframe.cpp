#include "slam/keyframe.hpp"

#include <algorithm>

namespace dynanav {

KeyFrame::KeyFrame(uint64_t id_, uint64_t frame_id_, double stamp, Features f, const SE3& T_cw,
                   std::vector<MapPointPtr> points)
    : id(id_),
      frame_id(frame_id_),
      stamp_s(stamp),
      features(std::move(f)),
      map_points(std::move(points)) {
  setPose(T_cw);
  ++instances_;
}

std::atomic<int64_t> KeyFrame::instances_{0};

KeyFrame::~KeyFrame() {
  --instances_;
}

int64_t KeyFrame::instances() {
  return instances_.load();
}

void KeyFrame::sortConnections() {
  std::vector<std::pair<int, KeyFrame*>> pairs;
  pairs.reserve(connections.size());
  for (const auto& [kf, w] : connections) pairs.emplace_back(w, kf);
  // Heaviest first; ties by id so the order never depends on addresses.
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second->id < b.second->id;
  });
  ordered_covisible.clear();
  ordered_weights.clear();
  for (const auto& [w, kf] : pairs) {
    ordered_covisible.push_back(kf);
    ordered_weights.push_back(w);
  }
}

void KeyFrame::addConnection(KeyFrame* other, int weight) {
  auto it = connections.find(other);
  if (it != connections.end() && it->second == weight) return;
  connections[other] = weight;
  sortConnections();
}

void KeyFrame::eraseConnection(KeyFrame* other) {
  if (connections.erase(other)) sortConnections();
}

void KeyFrame::updateConnections(int min_weight) {
  std::map<KeyFrame*, int, KeyFrameIdLess> counter;
  for (const auto& p : map_points) {
    if (!p || p->bad) continue;
    for (const auto& [kf, index] : p->observations) {
      if (kf != this && !kf->bad) ++counter[kf];
    }
  }
  if (counter.empty()) return;
  KeyFrame* strongest = nullptr;
  int strongest_weight = 0;
  std::map<KeyFrame*, int, KeyFrameIdLess> kept;
  for (const auto& [kf, w] : counter) {
    if (w > strongest_weight) {
      strongest_weight = w;
      strongest = kf;
    }
    if (w >= min_weight) {
      kept[kf] = w;
      kf->addConnection(this, w);
    }
  }
  // ORB-SLAM2: with no link above the threshold, keep the strongest one so the graph stays
  // connected.
  if (kept.empty()) {
    kept[strongest] = strongest_weight;
    strongest->addConnection(this, strongest_weight);
  }
  connections = std::move(kept);
  sortConnections();
  if (first_connection_ && id != 0) {
    parent = ordered_covisible.front();
    parent->children.insert(this);
    first_connection_ = false;
  }
}

std::vector<KeyFrame*> KeyFrame::bestCovisible(int n) const {
  const size_t count = std::min<size_t>(n, ordered_covisible.size());
  return {ordered_covisible.begin(), ordered_covisible.begin() + count};
}

std::vector<KeyFrame*> KeyFrame::covisibleAtLeast(int weight) const {
  std::vector<KeyFrame*> out;
  for (size_t i = 0; i < ordered_covisible.size() && ordered_weights[i] >= weight; ++i)
    out.push_back(ordered_covisible[i]);
  return out;
}

int KeyFrame::trackedMapPoints(int min_observations) const {
  int n = 0;
  for (const auto& p : map_points) {
    if (p && !p->bad && p->numObservations() >= min_observations) ++n;
  }
  return n;
}

void KeyFrame::eraseMapPoint(const MapPoint* point) {
  for (auto& p : map_points) {
    if (p.get() == point) p.reset();
  }
}

void KeyFrame::setBad() {
  // Keyframes closing a loop stay (ORB-SLAM2 mbNotErase): the essential graph needs both ends.
  if (id == 0 || bad || !loop_edges.empty()) return;
  for (const auto& [kf, w] : connections) kf->eraseConnection(this);
  for (size_t i = 0; i < map_points.size(); ++i) {
    if (map_points[i]) map_points[i]->eraseObservation(this);
  }
  connections.clear();
  ordered_covisible.clear();
  ordered_weights.clear();
  // Frames that referred to this keyframe keep their pose through the parent (ORB-SLAM2 mTcp).
  if (parent) {
    T_camera_parent = T_camera_world_ * parent->T_world_camera();
    parent_when_culled = parent->shared_from_this();
  }
  // Re-parent children: each takes its strongest covisible keyframe that is already in the
  // tree (a simplification of ORB-SLAM2's greedy reassignment), else this keyframe's parent.
  for (KeyFrame* child : children) {
    KeyFrame* new_parent = parent;
    for (KeyFrame* candidate : child->ordered_covisible) {
      if (candidate != this && !candidate->bad && candidate->id < child->id) {
        new_parent = candidate;
        break;
      }
    }
    child->parent = new_parent;
    if (new_parent) new_parent->children.insert(child);
  }
  if (parent) parent->children.erase(this);
  children.clear();
  bad = true;
}

}  // namespace dynanav
