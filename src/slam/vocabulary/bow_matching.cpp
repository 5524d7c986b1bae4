#include "slam/vocabulary/bow_matching.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slam/vocabulary/descriptor_bits.hpp"

namespace dynanav {
namespace {

// Keeps matches whose angle difference falls in the three fullest histogram bins; the second and
// third only if they hold at least a tenth of the first (ORB-SLAM2's ComputeThreeMaxima).
void keepDominantRotation(std::vector<cv::DMatch>& matches, const std::vector<cv::KeyPoint>& ka,
                          const std::vector<cv::KeyPoint>& kb, int bins) {
  if (matches.empty() || bins < 1) return;
  std::vector<int> bin_of(matches.size());
  std::vector<int> count(bins, 0);
  for (size_t i = 0; i < matches.size(); ++i) {
    float diff = ka[matches[i].queryIdx].angle - kb[matches[i].trainIdx].angle;
    if (diff < 0.0f) diff += 360.0f;
    bin_of[i] = std::min(bins - 1, static_cast<int>(diff * static_cast<float>(bins) / 360.0f));
    ++count[bin_of[i]];
  }
  std::vector<int> order(bins);
  for (int b = 0; b < bins; ++b) order[b] = b;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return count[a] > count[b]; });
  std::vector<bool> keep(bins, false);
  keep[order[0]] = true;
  for (int r = 1; r < std::min(3, bins); ++r)
    if (count[order[r]] > 0 && count[order[r]] >= 0.1 * count[order[0]]) keep[order[r]] = true;
  size_t kept = 0;
  for (size_t i = 0; i < matches.size(); ++i)
    if (keep[bin_of[i]]) matches[kept++] = matches[i];
  matches.resize(kept);
}

}  // namespace

std::vector<cv::DMatch> matchByDirectIndex(const FeatureVector& features_a, const cv::Mat& descriptors_a,
                                           const std::vector<cv::KeyPoint>& keypoints_a,
                                           const FeatureVector& features_b, const cv::Mat& descriptors_b,
                                           const std::vector<cv::KeyPoint>& keypoints_b,
                                           const BowMatchOptions& options,
                                           const std::function<bool(int)>& usable_a) {
  // best_for_b[j]: the A feature currently matched to B feature j, or -1.
  std::vector<int> best_for_b(descriptors_b.rows, -1);
  std::vector<int> distance_for_b(descriptors_b.rows, std::numeric_limits<int>::max());
  auto ia = features_a.nodes.begin();
  auto ib = features_b.nodes.begin();
  while (ia != features_a.nodes.end() && ib != features_b.nodes.end()) {
    if (ia->first < ib->first) {
      ++ia;
      continue;
    }
    if (ib->first < ia->first) {
      ++ib;
      continue;
    }
    for (int a : ia->second) {
      if (usable_a && !usable_a(a)) continue;
      const Descriptor256 da = Descriptor256::fromRow(descriptors_a.ptr<uchar>(a));
      int best = std::numeric_limits<int>::max(), second = best, best_b = -1;
      for (int b : ib->second) {
        const int d = hamming(da, Descriptor256::fromRow(descriptors_b.ptr<uchar>(b)));
        if (d < best) {
          second = best;
          best = d;
          best_b = b;
        } else if (d < second) {
          second = d;
        }
      }
      if (best_b < 0 || best > options.max_distance) continue;
      if (static_cast<float>(best) >= options.nn_ratio * static_cast<float>(second)) continue;
      // One A per B: the closer wins; on a tie the earlier A (lower index) keeps it.
      if (best < distance_for_b[best_b]) {
        distance_for_b[best_b] = best;
        best_for_b[best_b] = a;
      }
    }
    ++ia;
    ++ib;
  }
  std::vector<cv::DMatch> matches;
  for (int b = 0; b < static_cast<int>(best_for_b.size()); ++b)
    if (best_for_b[b] >= 0) matches.emplace_back(best_for_b[b], b, static_cast<float>(distance_for_b[b]));
  std::sort(matches.begin(), matches.end(),
            [](const cv::DMatch& x, const cv::DMatch& y) { return x.queryIdx < y.queryIdx; });
  if (options.check_orientation)
    keepDominantRotation(matches, keypoints_a, keypoints_b, options.orientation_bins);
  return matches;
}

}  // namespace dynanav
