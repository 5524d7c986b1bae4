#pragma once
// Hierarchical k-means for binary descriptors (Nistér & Stewénius 2006 with the k-majority centre
// of Grana et al. 2013 / DBoW2): each node's descriptors are split into k clusters seeded by
// k-means++ (Arthur & Vassilvitskii 2007), centres are per-bit majority votes, and every cluster
// is split again down to `levels`.
#include <cstdint>
#include <vector>

#include "slam/vocabulary/descriptor_bits.hpp"

namespace dynanav {

/// The tree in breadth-first order: node 0 is the root (centre unused, parent = kNoParent); the
/// children of a node are contiguous. Nodes without children are the words.
struct KMajorityTree {
  static constexpr uint32_t kNoParent = 0xFFFFFFFFu;
  std::vector<uint32_t> parent;
  std::vector<Descriptor256> centre;
};

/// Deterministic for a given input order and seed: each node seeds its own RNG from (seed, node).
/// A node with at most `branching` distinct descriptors gets one child per distinct descriptor;
/// a node whose descriptors are all equal, or at depth `levels`, is a leaf.
KMajorityTree buildKMajorityTree(const std::vector<Descriptor256>& data, int branching, int levels,
                                 uint64_t seed, int max_iterations);

}  // namespace dynanav
