#pragma once
// Our own ORB vocabulary tree (Nistér & Stewénius, CVPR 2006; the binary variant of
// Gálvez-López & Tardós, T-RO 2012, as ORB-SLAM2 uses it): hierarchical k-means with k-majority
// centres over 256-bit descriptors, leaves = words with IDF weights, TF-IDF bag-of-words vectors
// and a direct index for guided matching. Written from the papers; no DBoW2 code.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "slam/vocabulary/bow_vector.hpp"
#include "slam/vocabulary/descriptor_bits.hpp"

namespace dynanav {

struct VocabularyTrainOptions {
  int branching = 10;      // k: children per node
  int levels = 5;          // L: depth of the tree (k^L words at most)
  uint64_t seed = 1;       // k-means++ seeding; the same seed and input give the same tree
  int max_iterations = 15; // k-means iterations per node (stops earlier when assignments settle)
  std::string source;      // what it was trained on, kept in the file for `vocabulary info`
};

/// What a vocabulary file says about itself.
struct VocabularyInfo {
  int branching = 0;
  int levels = 0;
  uint64_t training_images = 0;
  uint64_t training_descriptors = 0;
  uint64_t seed = 0;
  std::string source;
  bool operator==(const VocabularyInfo&) const = default;
};

class Vocabulary {
 public:
  /// Trains on descriptors grouped by image (each N x 32 CV_8U); the grouping gives the IDF
  /// (a word's weight is ln(images / images containing the word)).
  static Vocabulary train(const std::vector<cv::Mat>& descriptors_per_image,
                          const VocabularyTrainOptions& options);

  /// Binary file (format in docs/orb_vocabulary.md). load() throws InputError naming `path` for a
  /// missing, truncated, corrupt or foreign file.
  void save(const std::string& path) const;
  static Vocabulary load(const std::string& path);

  /// Bag-of-words of an image's descriptors (rows of N x 32 CV_8U): TF-IDF weights, L1-normalised.
  /// With `features`, also the direct index: feature indices grouped by their ancestor node at
  /// `direct_index_depth` (1 = children of the root; ORB-SLAM2 uses levels - 4 with L = 6).
  void transform(const cv::Mat& descriptors, BowVector& bow, FeatureVector* features = nullptr,
                 int direct_index_depth = 2) const;

  /// Leaf word of one descriptor, and its ancestor node at `depth` (the leaf if it is shallower).
  [[nodiscard]] WordId word(const Descriptor256& descriptor, int depth = 0,
                            NodeId* node_at_depth = nullptr) const;

  [[nodiscard]] bool empty() const { return word_node_.empty(); }
  [[nodiscard]] size_t words() const { return word_node_.size(); }
  [[nodiscard]] size_t nodes() const { return parent_.size(); }
  [[nodiscard]] float weight(WordId word) const { return idf_[word]; }
  [[nodiscard]] const Descriptor256& wordDescriptor(WordId word) const {
    return descriptor_[word_node_[word]];
  }
  [[nodiscard]] const VocabularyInfo& info() const { return info_; }

  bool operator==(const Vocabulary&) const = default;

 private:
  /// Derives children ranges, depths and word ids from the parent array (nodes in breadth-first
  /// order, so each node's children are contiguous). Returns "" or what is inconsistent.
  std::string index();

  VocabularyInfo info_;
  // Per node, breadth-first; node 0 is the root (its descriptor unused).
  std::vector<uint32_t> parent_;
  std::vector<Descriptor256> descriptor_;
  std::vector<uint32_t> first_child_, child_count_, depth_;
  std::vector<int32_t> node_word_;  // -1 for inner nodes
  // Per word.
  std::vector<uint32_t> word_node_;
  std::vector<float> idf_;
};

}  // namespace dynanav
