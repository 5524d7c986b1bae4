#pragma once
// Depth helpers shared by the segmenters: an object's depth mode inside a box or mask, the
// depth refinement of a person mask, and masks made from depth alone inside a detector box.
// Why depth: a box holds the object and whatever is behind it; the object is the dominant
// (usually nearest) depth layer, and the background lies well beyond it.
#include <opencv2/core.hpp>

namespace dynanav {

/// Dominant depth (m) of the valid samples of `depth_m` where `mask` (CV_8U, same size) is set
/// (all pixels if mask is empty), from a histogram with `bin_m` bins smoothed over 3 bins.
/// With near_share < 1 the nearest bin holding at least near_share × the highest bin wins
/// (prefers the object in front over a larger background). 0 when no valid sample.
float depthMode(const cv::Mat& depth_m, const cv::Mat& mask, double bin_m, double near_share = 1.0);

/// Clears mask pixels whose valid depth is farther than band_m from the mask's depth mode;
/// pixels without depth are kept (the image model's word stands there). In place, same sizes.
void refineMaskByDepth(cv::Mat& mask, const cv::Mat& depth_m, double bin_m, double band_m);

/// Mask (CV_8U, the box's size) of the object inside `box`: pixels within band_m of the
/// nearest strong depth layer of the box's central part, largest connected part only.
/// Empty (all zero) when the box has no valid depth.
cv::Mat depthMaskInBox(const cv::Mat& depth_m, const cv::Rect& box, double bin_m, double band_m);

}  // namespace dynanav
