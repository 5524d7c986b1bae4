#pragma once
// Test scenes for flow-based mask carrying: a blurred-noise texture (DIS flow locks onto it)
// and translated copies of it.
#include <opencv2/imgproc.hpp>

namespace dynanav::test {

inline cv::Mat texture(cv::Size size, int seed) {
  cv::Mat noise(size, CV_8UC3);
  cv::RNG rng{uint64_t(seed)};
  rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.0);  // blobs a few pixels wide, flow-friendly
  return noise;
}

inline cv::Mat shifted(const cv::Mat& image, int dx, int dy) {
  cv::Mat out;
  cv::warpAffine(image, out, cv::Matx23d(1, 0, dx, 0, 1, dy), image.size(), cv::INTER_NEAREST,
                 cv::BORDER_REFLECT);
  return out;
}

}  // namespace dynanav::test
