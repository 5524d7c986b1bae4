#include "perception/depth_masks.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/frame.hpp"

namespace dynanav {
namespace {

constexpr float kMaxDepthM = 12.f;  // beyond the range of Kinect-class sensors

}  // namespace

float depthMode(const cv::Mat& depth_m, const cv::Mat& mask, double bin_m, double near_share) {
  CV_Assert(depth_m.type() == CV_32F && (mask.empty() || mask.size() == depth_m.size()));
  const int bins = int(std::ceil(kMaxDepthM / bin_m)) + 1;
  std::vector<double> hist(size_t(bins), 0.0);
  for (int y = 0; y < depth_m.rows; ++y) {
    const float* z = depth_m.ptr<float>(y);
    const uchar* m = mask.empty() ? nullptr : mask.ptr<uchar>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      if ((m && !m[x]) || !validDepth(z[x]) || z[x] >= kMaxDepthM) continue;
      hist[size_t(z[x] / bin_m)] += 1.0;
    }
  }
  std::vector<double> smooth(hist.size(), 0.0);
  for (size_t i = 0; i < hist.size(); ++i)
    smooth[i] = 2 * hist[i] + (i > 0 ? hist[i - 1] : 0) + (i + 1 < hist.size() ? hist[i + 1] : 0);
  const auto peak = std::max_element(smooth.begin(), smooth.end());
  if (*peak <= 0.0) return 0.f;
  size_t best = size_t(peak - smooth.begin());
  if (near_share < 1.0) {
    // Nearest local maximum strong enough: the object in front, not the wall behind it.
    for (size_t i = 0; i < best; ++i) {
      const bool local_max = (i == 0 || smooth[i] >= smooth[i - 1]) && smooth[i] >= smooth[i + 1];
      if (local_max && smooth[i] >= near_share * *peak) {
        best = i;
        break;
      }
    }
  }
  return float((double(best) + 0.5) * bin_m);
}

void refineMaskByDepth(cv::Mat& mask, const cv::Mat& depth_m, double bin_m, double band_m) {
  const float mode = depthMode(depth_m, mask, bin_m);
  if (mode <= 0.f) return;
  const float band = float(band_m);
  for (int y = 0; y < mask.rows; ++y) {
    uchar* m = mask.ptr<uchar>(y);
    const float* z = depth_m.ptr<float>(y);
    for (int x = 0; x < mask.cols; ++x)
      if (m[x] && validDepth(z[x]) && std::abs(z[x] - mode) > band) m[x] = 0;
  }
}

cv::Mat depthMaskInBox(const cv::Mat& depth_m, const cv::Rect& box, double bin_m, double band_m) {
  const cv::Rect clipped = box & cv::Rect(0, 0, depth_m.cols, depth_m.rows);
  cv::Mat out = cv::Mat::zeros(box.size(), CV_8U);
  if (clipped.area() == 0) return out;
  const cv::Mat roi = depth_m(clipped);
  // The central part of a box is mostly the object; its borders are mostly background.
  const cv::Rect centre(roi.cols / 4, roi.rows / 5, std::max(1, roi.cols / 2), std::max(1, 3 * roi.rows / 5));
  const float mode = depthMode(roi(centre), cv::Mat(), bin_m, 0.5);
  if (mode <= 0.f) return out;
  cv::Mat band = (roi > mode - float(band_m)) & (roi < mode + float(band_m));
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(band, labels, stats, centroids, 8, CV_32S);
  int best = 0, best_area = 0;
  for (int i = 1; i < n; ++i) {
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    if (area > best_area) best = i, best_area = area;
  }
  if (best == 0) return out;
  cv::Mat part = labels == best;
  part.copyTo(out(clipped - box.tl()));
  return out;
}

}  // namespace dynanav
