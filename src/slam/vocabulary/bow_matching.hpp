#pragma once
// Descriptor matching guided by the vocabulary's direct index (ORB-SLAM2's SearchByBoW, §VI-B of
// Mur-Artal et al., T-RO 2015): only features under the same vocabulary node are compared, which
// makes matching a keyframe against a frame (relocalisation) or a keyframe (loop closing) cheap.
// Independent of frames and map points: it works on keypoints, descriptors and feature vectors.
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "slam/vocabulary/bow_vector.hpp"

namespace dynanav {

struct BowMatchOptions {
  int max_distance = 50;        // Hamming; ORB-SLAM2's TH_LOW
  float nn_ratio = 0.75f;       // best must be below this times the second best (Lowe's test)
  bool check_orientation = true;
  int orientation_bins = 30;    // histogram of angle differences; the 3 fullest bins survive
};

/// Matches features of A to features of B that share a direct-index node. Each A feature
/// (only those `usable_a` accepts, e.g. ones with a map point) takes its nearest B feature in the
/// node if it passes the distance and ratio tests; each B feature keeps only its best A feature.
/// With check_orientation, matches whose keypoint-angle difference is not among the three most
/// common (ORB-SLAM2: a rotation shared by most matches) are dropped. DMatch: queryIdx = A index,
/// trainIdx = B index, distance = Hamming. Ordered by queryIdx; deterministic.
std::vector<cv::DMatch> matchByDirectIndex(const FeatureVector& features_a, const cv::Mat& descriptors_a,
                                           const std::vector<cv::KeyPoint>& keypoints_a,
                                           const FeatureVector& features_b, const cv::Mat& descriptors_b,
                                           const std::vector<cv::KeyPoint>& keypoints_b,
                                           const BowMatchOptions& options = {},
                                           const std::function<bool(int)>& usable_a = {});

}  // namespace dynanav
