#include "viz/colours.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace dynanav {

cv::Scalar colourOfId(uint64_t id) {
  const double hue = std::fmod(double(id) * 0.618033988749895, 1.0) * 180.0;
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, 220, 255)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  const auto c = bgr.at<cv::Vec3b>(0, 0);
  return {double(c[0]), double(c[1]), double(c[2])};
}

}  // namespace dynanav
