#include "slam/vocabulary/vocabulary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "slam/vocabulary/kmajority_tree.hpp"

namespace dynanav {
namespace {

void checkDescriptors(const cv::Mat& descriptors) {
  if (!descriptors.empty() && (descriptors.type() != CV_8UC1 || descriptors.cols != 32))
    throw std::invalid_argument("Vocabulary: descriptors must be N x 32 CV_8U (ORB)");
}

}  // namespace

Vocabulary Vocabulary::train(const std::vector<cv::Mat>& descriptors_per_image,
                             const VocabularyTrainOptions& options) {
  if (options.branching < 2 || options.levels < 1)
    throw std::invalid_argument("Vocabulary::train: need branching >= 2 and levels >= 1");
  std::vector<Descriptor256> data;
  for (const cv::Mat& d : descriptors_per_image) {
    checkDescriptors(d);
    for (int r = 0; r < d.rows; ++r) data.push_back(Descriptor256::fromRow(d.ptr<uchar>(r)));
  }
  if (data.empty()) throw std::invalid_argument("Vocabulary::train: no descriptors to train on");

  KMajorityTree tree = buildKMajorityTree(data, options.branching, options.levels, options.seed,
                                          options.max_iterations);
  Vocabulary vocabulary;
  vocabulary.parent_ = std::move(tree.parent);
  vocabulary.descriptor_ = std::move(tree.centre);
  vocabulary.info_ = {options.branching, options.levels, descriptors_per_image.size(), data.size(),
                      options.seed, options.source};
  if (const std::string problem = vocabulary.index(); !problem.empty())
    throw std::logic_error("Vocabulary::train built an inconsistent tree: " + problem);

  // IDF (Sivic & Zisserman 2003): ln(N / n_i) over the training images, counting an image once
  // per word. Words are found by descending the finished tree, as queries will be. A word no
  // training image descends to is treated as seen once (as rare as can be measured).
  std::vector<uint32_t> images_with_word(vocabulary.words(), 0);
  std::vector<uint32_t> last_image(vocabulary.words(), std::numeric_limits<uint32_t>::max());
  for (uint32_t image = 0; image < descriptors_per_image.size(); ++image) {
    const cv::Mat& d = descriptors_per_image[image];
    for (int r = 0; r < d.rows; ++r) {
      const WordId w = vocabulary.word(Descriptor256::fromRow(d.ptr<uchar>(r)));
      if (last_image[w] != image) {
        last_image[w] = image;
        ++images_with_word[w];
      }
    }
  }
  const double n_images = static_cast<double>(descriptors_per_image.size());
  vocabulary.idf_.resize(vocabulary.words());
  for (size_t w = 0; w < vocabulary.words(); ++w)
    vocabulary.idf_[w] = static_cast<float>(std::log(n_images / std::max<uint32_t>(images_with_word[w], 1)));
  return vocabulary;
}

std::string Vocabulary::index() {
  const size_t n = parent_.size();
  if (n == 0 || parent_[0] != KMajorityTree::kNoParent) return "node 0 must be the root";
  if (descriptor_.size() != n) return "descriptor count differs from node count";
  first_child_.assign(n, 0);
  child_count_.assign(n, 0);
  depth_.assign(n, 0);
  for (size_t i = 1; i < n; ++i) {
    const uint32_t p = parent_[i];
    if (p >= i) return "node " + std::to_string(i) + " has parent " + std::to_string(p) + " after it";
    if (p < parent_[i - 1] && i > 1) return "nodes are not in breadth-first order at " + std::to_string(i);
    if (child_count_[p] == 0) first_child_[p] = static_cast<uint32_t>(i);
    if (++child_count_[p] > static_cast<uint32_t>(info_.branching))
      return "node " + std::to_string(p) + " has more than k children";
    depth_[i] = depth_[p] + 1;
    if (depth_[i] > static_cast<uint32_t>(info_.levels)) return "tree deeper than its level count";
  }
  node_word_.assign(n, -1);
  word_node_.clear();
  for (size_t i = 1; i < n; ++i) {
    if (child_count_[i] == 0) {
      node_word_[i] = static_cast<int32_t>(word_node_.size());
      word_node_.push_back(static_cast<uint32_t>(i));
    }
  }
  if (word_node_.empty()) return "no words";
  return "";
}

WordId Vocabulary::word(const Descriptor256& descriptor, int depth, NodeId* node_at_depth) const {
  uint32_t node = 0;
  if (node_at_depth) *node_at_depth = 0;
  while (child_count_[node] > 0) {
    // Nearest child by Hamming distance; ties go to the first child, so descent is deterministic.
    const uint32_t first = first_child_[node], end = first + child_count_[node];
    uint32_t best = first;
    int best_d = hamming(descriptor, descriptor_[first]);
    for (uint32_t c = first + 1; c < end; ++c) {
      const int d = hamming(descriptor, descriptor_[c]);
      if (d < best_d) best_d = d, best = c;
    }
    node = best;
    if (node_at_depth && depth_[node] <= static_cast<uint32_t>(depth)) *node_at_depth = node;
  }
  return static_cast<WordId>(node_word_[node]);
}

void Vocabulary::transform(const cv::Mat& descriptors, BowVector& bow, FeatureVector* features,
                           int direct_index_depth) const {
  checkDescriptors(descriptors);
  bow.entries.clear();
  if (features) features->nodes.clear();
  if (empty() || descriptors.empty()) return;
  const int depth = std::clamp(direct_index_depth, 1, info_.levels);
  std::vector<std::pair<WordId, float>> hits;
  std::vector<std::pair<NodeId, int>> grouped;
  hits.reserve(descriptors.rows);
  if (features) grouped.reserve(descriptors.rows);
  for (int r = 0; r < descriptors.rows; ++r) {
    NodeId node = 0;
    const WordId w = word(Descriptor256::fromRow(descriptors.ptr<uchar>(r)), depth, &node);
    // TF-IDF (Gálvez-López & Tardós 2012, eq. 2 with the L1 norm): each occurrence adds the
    // word's IDF; normalising by the total turns counts into frequencies.
    if (idf_[w] > 0.0f) hits.emplace_back(w, idf_[w]);
    if (features) grouped.emplace_back(node, r);
  }
  std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  double total = 0.0;
  for (const auto& [w, v] : hits) {
    if (!bow.entries.empty() && bow.entries.back().first == w) bow.entries.back().second += v;
    else bow.entries.emplace_back(w, v);
    total += v;
  }
  if (total > 0.0)
    for (auto& entry : bow.entries) entry.second = static_cast<float>(entry.second / total);

  if (features) {
    std::sort(grouped.begin(), grouped.end());
    for (const auto& [node, r] : grouped) {
      if (features->nodes.empty() || features->nodes.back().first != node)
        features->nodes.push_back({node, {}});
      features->nodes.back().second.push_back(r);
    }
  }
}

}  // namespace dynanav
