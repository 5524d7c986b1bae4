#pragma once
// Spatial distribution of keypoints by quadtree, as ORB-SLAM2's extractor does it
// (Mur-Artal & Tardós, T-RO 2017, §III; "DistributeOctTree" in their code): the image region is
// split into quadrants until there are about as many non-empty nodes as wanted features, then
// each node keeps its strongest keypoint. Dense textured corners thus cannot take the whole
// budget, which keeps pose estimates well conditioned.
#include <opencv2/core/types.hpp>
#include <vector>

namespace dynanav {

/// Keeps at most `n_wanted` keypoints of `candidates`, spread over the region [x0,x1) x [y0,y1)
/// (same coordinates as the keypoints). Deterministic: ties are broken by candidate order.
/// Nodes are split breadth-first (all at once) while that does not overshoot `n_wanted`; the last
/// round splits the most populated nodes first until the count is reached.
std::vector<cv::KeyPoint> distributeQuadtree(const std::vector<cv::KeyPoint>& candidates,
                                             float x0, float x1, float y0, float y1,
                                             int n_wanted);

}  // namespace dynanav
