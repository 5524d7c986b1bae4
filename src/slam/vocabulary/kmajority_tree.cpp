#include "slam/vocabulary/kmajority_tree.hpp"

#include <algorithm>
#include <deque>
#include <limits>
#include <random>

namespace dynanav {
namespace {

// splitmix64: decorrelates per-node seeds so neighbouring node ids get unrelated streams.
uint64_t mixSeed(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits: the same numbers on every standard library.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// k-means++ seeding on Hamming distance: the next centre is drawn with probability proportional
// to the squared distance to the nearest centre chosen so far. Fewer than k centres if the
// remaining points all coincide with chosen ones.
std::vector<Descriptor256> seedCentres(const std::vector<Descriptor256>& data,
                                       const std::vector<uint32_t>& members, int k,
                                       std::mt19937_64& rng) {
  std::vector<Descriptor256> centres;
  centres.push_back(data[members[rng() % members.size()]]);
  std::vector<double> d2(members.size());
  for (size_t i = 0; i < members.size(); ++i) {
    const double d = hamming(data[members[i]], centres[0]);
    d2[i] = d * d;
  }
  while (static_cast<int>(centres.size()) < k) {
    double total = 0.0;
    for (double v : d2) total += v;
    if (total <= 0.0) break;
    const double target = uniform01(rng) * total;
    size_t pick = 0;
    double cumulative = 0.0;
    for (; pick + 1 < members.size(); ++pick) {
      cumulative += d2[pick];
      if (cumulative > target && d2[pick] > 0.0) break;
    }
    if (d2[pick] <= 0.0) break;  // only reachable through rounding at the very end
    centres.push_back(data[members[pick]]);
    for (size_t i = 0; i < members.size(); ++i) {
      const double d = hamming(data[members[i]], centres.back());
      d2[i] = std::min(d2[i], d * d);
    }
  }
  return centres;
}

int nearest(const Descriptor256& x, const std::vector<Descriptor256>& centres) {
  int best = 0, best_d = std::numeric_limits<int>::max();
  for (int c = 0; c < static_cast<int>(centres.size()); ++c) {
    const int d = hamming(x, centres[c]);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

// Per-bit majority of the members (ties give 0): the binary analogue of the mean.
Descriptor256 majority(const std::vector<Descriptor256>& data, const std::vector<uint32_t>& members) {
  int votes[256] = {};
  for (uint32_t m : members) {
    for (int w = 0; w < 4; ++w) {
      for (uint64_t bits = data[m].words[w]; bits != 0; bits &= bits - 1)
        ++votes[w * 64 + std::countr_zero(bits)];
    }
  }
  Descriptor256 centre;
  const int half = static_cast<int>(members.size());
  for (int b = 0; b < 256; ++b)
    if (2 * votes[b] > half) centre.words[b >> 6] |= uint64_t{1} << (b & 63);
  return centre;
}

// Splits `members` into clusters (each non-empty) with their centres.
void cluster(const std::vector<Descriptor256>& data, const std::vector<uint32_t>& members, int k,
             int max_iterations, std::mt19937_64& rng, std::vector<Descriptor256>& centres,
             std::vector<std::vector<uint32_t>>& groups) {
  // Few points: each distinct descriptor is its own child (the usual k-means would do the same).
  std::vector<Descriptor256> distinct;
  for (uint32_t m : members) {
    if (std::find(distinct.begin(), distinct.end(), data[m]) == distinct.end()) {
      distinct.push_back(data[m]);
      if (static_cast<int>(distinct.size()) > k) break;
    }
  }
  if (static_cast<int>(distinct.size()) <= k) {
    centres = distinct;
  } else {
    centres = seedCentres(data, members, k, rng);
  }
  std::vector<int> assignment(members.size(), -1);
  for (int iteration = 0; iteration < std::max(1, max_iterations); ++iteration) {
    bool changed = false;
    for (size_t i = 0; i < members.size(); ++i) {
      const int c = nearest(data[members[i]], centres);
      changed |= c != assignment[i];
      assignment[i] = c;
    }
    groups.assign(centres.size(), {});
    for (size_t i = 0; i < members.size(); ++i) groups[assignment[i]].push_back(members[i]);
    if (!changed || static_cast<int>(distinct.size()) <= k) break;
    for (size_t c = 0; c < centres.size(); ++c)
      if (!groups[c].empty()) centres[c] = majority(data, groups[c]);
  }
  // Drop clusters that emptied during the iterations.
  size_t kept = 0;
  for (size_t c = 0; c < centres.size(); ++c) {
    if (groups[c].empty()) continue;
    if (kept != c) {  // (a vector moved onto itself would come out empty)
      centres[kept] = centres[c];
      groups[kept] = std::move(groups[c]);
    }
    ++kept;
  }
  centres.resize(kept);
  groups.resize(kept);
}

}  // namespace

KMajorityTree buildKMajorityTree(const std::vector<Descriptor256>& data, int branching, int levels,
                                 uint64_t seed, int max_iterations) {
  KMajorityTree tree;
  tree.parent.push_back(KMajorityTree::kNoParent);
  tree.centre.emplace_back();
  if (data.empty()) return tree;

  struct Pending {
    uint32_t node;
    int depth;
    std::vector<uint32_t> members;
  };
  std::deque<Pending> queue;  // breadth-first, so children of a node get contiguous ids
  std::vector<uint32_t> all(data.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<uint32_t>(i);
  queue.push_back({0, 0, std::move(all)});
  std::vector<Descriptor256> centres;
  std::vector<std::vector<uint32_t>> groups;
  while (!queue.empty()) {
    Pending item = std::move(queue.front());
    queue.pop_front();
    std::mt19937_64 rng(mixSeed(seed ^ mixSeed(item.node)));
    cluster(data, item.members, branching, max_iterations, rng, centres, groups);
    if (centres.size() < 2 && item.node != 0) continue;  // all equal: a leaf
    for (size_t c = 0; c < centres.size(); ++c) {
      const auto child = static_cast<uint32_t>(tree.parent.size());
      tree.parent.push_back(item.node);
      tree.centre.push_back(centres[c]);
      if (item.depth + 1 < levels && groups[c].size() > 1)
        queue.push_back({child, item.depth + 1, std::move(groups[c])});
    }
  }
  return tree;
}

}  // namespace dynanav
