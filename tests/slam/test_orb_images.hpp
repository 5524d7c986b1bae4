#pragma once
// Synthetic test images for the ORB and vocabulary tests (no files needed).
#include <cstdint>
#include <opencv2/imgproc.hpp>

namespace dynanav::test {

/// Blobs of random grey levels at several scales: corners everywhere, like a textured wall.
/// Different seeds give different "places".
inline cv::Mat texturedImage(int width, int height, uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat image(height, width, CV_8UC1, cv::Scalar(128));
  for (int i = 0; i < 1500; ++i) {
    const cv::Point c(rng.uniform(0, width), rng.uniform(0, height));
    const int r = rng.uniform(3, 25);
    if (rng.uniform(0, 2) == 0)
      cv::circle(image, c, r, cv::Scalar(rng.uniform(0, 256)), cv::FILLED);
    else
      cv::rectangle(image, cv::Rect(c.x, c.y, r, rng.uniform(3, 25)), cv::Scalar(rng.uniform(0, 256)),
                    cv::FILLED);
  }
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  return image;
}

/// The same scene seen from a slightly different pose: turned by `degrees` about the centre,
/// scaled and shifted, with sensor noise.
inline cv::Mat perturbedView(const cv::Mat& image, double degrees, double scale, cv::Point2d shift,
                             uint64_t noise_seed) {
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(image.cols / 2.0f, image.rows / 2.0f), degrees, scale);
  m.at<double>(0, 2) += shift.x;
  m.at<double>(1, 2) += shift.y;
  cv::Mat warped, noise(image.size(), CV_16S);
  cv::warpAffine(image, warped, m, image.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  cv::RNG(noise_seed).fill(noise, cv::RNG::NORMAL, 0, 3);
  cv::Mat out;
  warped.convertTo(out, CV_16S);
  out += noise;
  out.convertTo(out, CV_8U);
  return out;
}

}  // namespace dynanav::test
