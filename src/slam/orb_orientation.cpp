#include "slam/orb_orientation.hpp"

namespace dynanav {

std::vector<int> orientationDisc(int radius) {
  std::vector<int> half_width(radius + 1);
  const int limit = radius * (radius + 1);
  for (int v = 0; v <= radius; ++v) {
    int u = 0;
    while ((u + 1) * (u + 1) + v * v <= limit) ++u;
    half_width[v] = u;
  }
  return half_width;
}

float intensityCentroidAngle(const cv::Mat& image, cv::Point center, const std::vector<int>& disc) {
  const uchar* c = image.ptr<uchar>(center.y) + center.x;
  const int step = static_cast<int>(image.step1());
  const int radius = static_cast<int>(disc.size()) - 1;
  int m10 = 0, m01 = 0;
  for (int u = -radius; u <= radius; ++u) m10 += u * c[u];  // row v = 0
  // Rows +v and -v together: their x moments add, their y moments subtract.
  for (int v = 1; v <= radius; ++v) {
    int y_sum = 0;
    const int d = disc[v];
    for (int u = -d; u <= d; ++u) {
      const int below = c[u + v * step], above = c[u - v * step];
      y_sum += below - above;
      m10 += u * (below + above);
    }
    m01 += v * y_sum;
  }
  return cv::fastAtan2(static_cast<float>(m01), static_cast<float>(m10));
}

}  // namespace dynanav
