#include "slam/orb_quadtree.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace dynanav {
namespace {

// A quadtree node: its region and the range [begin, end) of the shared index array whose
// keypoints fall inside it. Splitting partitions that range in place (no allocation per node).
struct Node {
  float x0, x1, y0, y1;
  int begin, end;
  [[nodiscard]] int count() const { return end - begin; }
  // Below half a pixel, points cannot be separated any more (FAST corners are whole pixels).
  [[nodiscard]] bool splittable() const { return count() > 1 && x1 - x0 > 0.5f; }
};

// Splits `node` into its non-empty quadrants, appended to `children`.
void split(const Node& node, const std::vector<cv::KeyPoint>& kps, std::vector<int>& index,
           std::vector<Node>& children) {
  const float mx = 0.5f * (node.x0 + node.x1);
  const float my = 0.5f * (node.y0 + node.y1);
  auto* first = index.data() + node.begin;
  auto* last = index.data() + node.end;
  auto* mid_y = std::partition(first, last, [&](int i) { return kps[i].pt.y < my; });
  auto* mid_top = std::partition(first, mid_y, [&](int i) { return kps[i].pt.x < mx; });
  auto* mid_bottom = std::partition(mid_y, last, [&](int i) { return kps[i].pt.x < mx; });
  const auto at = [&](const int* p) { return static_cast<int>(p - index.data()); };
  const Node quads[4] = {{node.x0, mx, node.y0, my, at(first), at(mid_top)},
                         {mx, node.x1, node.y0, my, at(mid_top), at(mid_y)},
                         {node.x0, mx, my, node.y1, at(mid_y), at(mid_bottom)},
                         {mx, node.x1, my, node.y1, at(mid_bottom), at(last)}};
  for (const Node& q : quads) {
    if (q.count() > 0) children.push_back(q);
  }
}

}  // namespace

std::vector<cv::KeyPoint> distributeQuadtree(const std::vector<cv::KeyPoint>& candidates,
                                             float x0, float x1, float y0, float y1,
                                             int n_wanted) {
  if (candidates.empty() || n_wanted <= 0) return {};
  std::vector<int> index(candidates.size());
  for (size_t i = 0; i < index.size(); ++i) index[i] = static_cast<int>(i);

  // Roots: about square cells side by side (a 640x480 image has one root, a wide one several).
  const float width = x1 - x0, height = y1 - y0;
  const int n_roots = std::max(1, static_cast<int>(std::lround(width / std::max(height, 1.0f))));
  const float root_width = width / static_cast<float>(n_roots);
  const auto root_of = [&](int i) {
    const int r = static_cast<int>((candidates[i].pt.x - x0) / root_width);
    return std::clamp(r, 0, n_roots - 1);
  };
  if (n_roots > 1)
    std::stable_sort(index.begin(), index.end(), [&](int a, int b) { return root_of(a) < root_of(b); });
  std::vector<Node> leaves;
  for (int r = 0, begin = 0; r < n_roots; ++r) {
    int end = begin;
    while (end < static_cast<int>(index.size()) && root_of(index[end]) == r) ++end;
    const float rx0 = x0 + root_width * static_cast<float>(r);
    const float rx1 = r + 1 == n_roots ? x1 : rx0 + root_width;
    if (end > begin) leaves.push_back({rx0, rx1, y0, y1, begin, end});
    begin = end;
  }

  // Breadth-first rounds: every splittable node splits, while the result cannot overshoot.
  std::vector<Node> next;
  while (static_cast<int>(leaves.size()) < n_wanted) {
    const auto n_splittable =
        std::count_if(leaves.begin(), leaves.end(), [](const Node& n) { return n.splittable(); });
    if (n_splittable == 0 || static_cast<int>(leaves.size() + 3 * n_splittable) > n_wanted) break;
    next.clear();
    for (const Node& n : leaves) {
      if (n.splittable()) split(n, candidates, index, next);
      else next.push_back(n);
    }
    const bool changed = next.size() != leaves.size();
    leaves.swap(next);
    if (!changed) break;
  }

  // Last round: most populated node first (ties: lower leaf index), until the count is reached.
  using Entry = std::pair<int, int>;  // (count, -leaf index): max-heap pops largest, then lowest
  std::priority_queue<Entry> heap;
  for (size_t i = 0; i < leaves.size(); ++i)
    if (leaves[i].splittable()) heap.push({leaves[i].count(), -static_cast<int>(i)});
  std::vector<Node> children;
  while (static_cast<int>(leaves.size()) < n_wanted && !heap.empty()) {
    const int i = -heap.top().second;
    heap.pop();
    children.clear();
    split(leaves[i], candidates, index, children);
    leaves[i] = children[0];
    if (leaves[i].splittable()) heap.push({leaves[i].count(), -i});
    for (size_t c = 1; c < children.size(); ++c) {
      leaves.push_back(children[c]);
      const int j = static_cast<int>(leaves.size()) - 1;
      if (leaves[j].splittable()) heap.push({leaves[j].count(), -j});
    }
  }

  // Strongest response per leaf; ties go to the earlier candidate.
  std::vector<int> best;
  best.reserve(leaves.size());
  for (const Node& n : leaves) {
    int b = index[n.begin];
    for (int k = n.begin + 1; k < n.end; ++k) {
      const int c = index[k];
      const float rc = candidates[c].response, rb = candidates[b].response;
      if (rc > rb || (rc == rb && c < b)) b = c;
    }
    best.push_back(b);
  }
  std::sort(best.begin(), best.end());  // candidate order: independent of the split history
  if (static_cast<int>(best.size()) > n_wanted) {
    std::stable_sort(best.begin(), best.end(), [&](int a, int b) {
      return candidates[a].response > candidates[b].response;
    });
    best.resize(n_wanted);
    std::sort(best.begin(), best.end());
  }
  std::vector<cv::KeyPoint> kept;
  kept.reserve(best.size());
  for (int b : best) kept.push_back(candidates[b]);
  return kept;
}

}  // namespace dynanav
