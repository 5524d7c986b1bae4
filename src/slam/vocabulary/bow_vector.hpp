#pragma once
// Bag-of-words vectors (Sivic & Zisserman 2003; Gálvez-López & Tardós, T-RO 2012): an image as
// TF-IDF weights over vocabulary words, and the features grouped by vocabulary node for guided
// matching (only features under the same node are compared).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace dynanav {

using WordId = uint32_t;
using NodeId = uint32_t;

/// Sparse word weights, sorted by word id, L1-normalised by Vocabulary::transform.
struct BowVector {
  std::vector<std::pair<WordId, float>> entries;

  [[nodiscard]] bool empty() const { return entries.empty(); }
  [[nodiscard]] size_t size() const { return entries.size(); }
  bool operator==(const BowVector&) const = default;
};

/// Feature indices per vocabulary node at the direct-index depth, sorted by node id; indices
/// within a node in increasing order.
struct FeatureVector {
  std::vector<std::pair<NodeId, std::vector<int>>> nodes;

  [[nodiscard]] bool empty() const { return nodes.empty(); }
  bool operator==(const FeatureVector&) const = default;
};

/// L1 similarity of two L1-normalised vectors (Nistér & Stewénius 2006, as DBoW2 uses it):
/// s = 1 - 0.5 * |a - b|_1, in [0, 1]; 1 for identical vectors, 0 when no word is shared.
/// Computed over shared words only: |a-b|_1 = 2 - sum_shared(|a_i| + |b_i| - |a_i - b_i|).
double l1Score(const BowVector& a, const BowVector& b);

/// Number of words present in both vectors.
int commonWords(const BowVector& a, const BowVector& b);

}  // namespace dynanav
