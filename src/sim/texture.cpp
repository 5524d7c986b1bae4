#include "sim/texture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace dynanav::sim {

Texture::Texture(const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3 && !bgr.empty());
  levels_.push_back(bgr.clone());
  while (std::min(levels_.back().cols, levels_.back().rows) > 8) {
    cv::Mat down;
    cv::pyrDown(levels_.back(), down);
    levels_.push_back(down);
  }
}

}  // namespace dynanav::sim
