#include "slam/loop_correction.hpp"

#include <spdlog/spdlog.h>

#include "slam/essential_graph.hpp"
#include "slam/matcher.hpp"

namespace dynanav {
namespace {

using EdgeKey = std::pair<uint64_t, uint64_t>;

EdgeKey edgeKey(const KeyFrame* a, const KeyFrame* b) {
  return {std::min(a->id, b->id), std::max(a->id, b->id)};
}

}  // namespace

EssentialGraphResult optimizeEssentialGraph(Map& map, const KeyFrame& fixed,
                                            const KeyFramePoses& uncorrected,
                                            const LoopLinks& loop_links, const LoopConfig& config) {
  PoseGraph graph;
  std::map<const KeyFrame*, int> node;
  std::vector<KeyFrame*> keyframes;
  for (const auto& [id, kf] : map.keyframes()) {
    if (kf->bad) continue;
    node[kf.get()] = static_cast<int>(keyframes.size());
    keyframes.push_back(kf.get());
    graph.nodes.push_back({kf->id, kf->T_world_camera(), kf.get() == &fixed});
  }
  auto measured = [&](KeyFrame* kf) {
    const auto it = uncorrected.find(kf);
    return it != uncorrected.end() ? it->second : kf->T_world_camera();
  };
  std::set<EdgeKey> added;
  auto add = [&](KeyFrame* a, KeyFrame* b, const SE3& T_world_a, const SE3& T_world_b) {
    const auto ia = node.find(a), ib = node.find(b);
    if (ia == node.end() || ib == node.end() || a == b || !added.insert(edgeKey(a, b)).second)
      return;
    graph.edges.push_back({ia->second, ib->second, T_world_a.inverse() * T_world_b, 1.0});
  };
  // New loop links first: they carry the correction (measured after it).
  for (const auto& [kf, links] : loop_links) {
    for (KeyFrame* other : links) {
      const auto w = kf->connections.find(other);
      const bool strong =
          w != kf->connections.end() && w->second >= config.essential_graph_min_weight;
      if (strong || (kf->loop_edges.count(other) > 0))
        add(kf, other, kf->T_world_camera(), other->T_world_camera());
    }
  }
  for (KeyFrame* kf : keyframes) {
    if (kf->parent) add(kf->parent, kf, measured(kf->parent), measured(kf));
    for (KeyFrame* other : kf->loop_edges) {
      if (node.count(other)) add(other, kf, measured(other), measured(kf));
    }
    for (KeyFrame* other : kf->covisibleAtLeast(config.essential_graph_min_weight)) {
      if (other->bad || other->id > kf->id) continue;
      add(other, kf, measured(other), measured(kf));
    }
  }
  std::map<const KeyFrame*, SE3> before;  // T_camera_world before the optimisation
  for (KeyFrame* kf : keyframes) before[kf] = kf->T_camera_world();
  const PoseGraphSummary summary = optimizePoseGraph(graph, config.essential_graph_iterations);
  for (size_t k = 0; k < keyframes.size(); ++k)
    keyframes[k]->setPose(graph.nodes[k].T_world_camera.inverse());
  // Points keep their place relative to their first observer.
  for (const auto& [id, p] : map.points()) {
    if (p->bad || p->observations.empty()) continue;
    KeyFrame* ref = p->observations.begin()->first;
    const auto it = before.find(ref);
    if (it == before.end()) continue;
    p->p_world = ref->T_world_camera() * (it->second * p->p_world);
    p->updateNormalAndDepth(*ref->features.scales);
  }
  return {static_cast<int>(graph.edges.size()), summary.initial_cost, summary.final_cost};
}

LoopCorrectionSummary correctLoop(Map& map, KeyFrame& current, const VerifiedLoop& loop,
                                  const LoopConfig& config, int covisibility_min_weight) {
  LoopCorrectionSummary summary;
  current.updateConnections(covisibility_min_weight);
  std::vector<KeyFrame*> window{&current};
  for (KeyFrame* kf : current.ordered_covisible)
    if (!kf->bad) window.push_back(kf);
  summary.window_keyframes = static_cast<int>(window.size());
  // 1. The window moves rigidly with the current keyframe's correction.
  const SE3 T_world_current_old = current.T_world_camera();
  KeyFramePoses uncorrected;
  std::set<uint64_t> corrected_points;
  for (KeyFrame* kf : window) {
    const SE3 T_kf_world_old = kf->T_camera_world();
    uncorrected[kf] = kf->T_world_camera();
    const SE3 T_kf_world_new = T_kf_world_old * T_world_current_old * loop.T_camera_world_corrected;
    const SE3 T_world_kf_new = T_kf_world_new.inverse();
    for (const auto& p : kf->map_points) {
      if (!p || p->bad || !corrected_points.insert(p->id).second) continue;
      p->p_world = T_world_kf_new * (T_kf_world_old * p->p_world);
    }
    kf->setPose(T_kf_world_new);
  }
  for (KeyFrame* kf : window)
    for (const auto& p : kf->map_points)
      if (p && !p->bad) p->updateNormalAndDepth(*kf->features.scales);
  // 2. Loop fusion: the current keyframe's matches take the loop's points (they are older and
  // better observed), then the loop's points are fused into the whole window.
  for (const auto& m : loop.matches) {
    const MapPointPtr loop_point = resolveReplaced(m.point);
    if (!loop_point || loop_point->bad) continue;
    const MapPointPtr existing = current.map_points[m.keypoint];
    if (existing == loop_point) continue;
    if (existing && !existing->bad) {
      existing->replaceWith(loop_point);
    } else if (!loop_point->observedBy(&current)) {
      current.map_points[m.keypoint] = loop_point;
      loop_point->addObservation(&current, m.keypoint);
      loop_point->updateDescriptor();
    }
    ++summary.points_fused;
  }
  std::vector<MapPointPtr> loop_points;
  for (const auto& p : loop.loop_points) {
    MapPointPtr r = resolveReplaced(p);
    if (r && !r->bad) loop_points.push_back(r);
  }
  std::map<KeyFrame*, std::set<KeyFrame*>> previous;
  for (KeyFrame* kf : window)
    previous[kf] = {kf->ordered_covisible.begin(), kf->ordered_covisible.end()};
  for (KeyFrame* kf : window) summary.points_fused += matcher::fuse(*kf, loop_points, 4.0f);
  // 3. New links across the loop, then the essential graph.
  std::set<KeyFrame*> in_window(window.begin(), window.end());
  LoopLinks links;
  for (KeyFrame* kf : window) {
    kf->updateConnections(covisibility_min_weight);
    for (KeyFrame* n : kf->ordered_covisible) {
      if (in_window.count(n) || previous[kf].count(n)) continue;
      links[kf].insert(n);
    }
  }
  current.loop_edges.insert(loop.loop);
  loop.loop->loop_edges.insert(&current);
  links[&current].insert(loop.loop);
  const EssentialGraphResult graph =
      optimizeEssentialGraph(map, *loop.loop, uncorrected, links, config);
  summary.graph_edges = graph.edges;
  summary.graph_initial_cost = graph.initial_cost;
  summary.graph_final_cost = graph.final_cost;
  map.removeBad();
  return summary;
}

}  // namespace dynanav
