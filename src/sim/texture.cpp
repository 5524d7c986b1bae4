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

namespace {
inline int wrap(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}
}  // namespace

void Texture::sample(float u, float v, int l, float out_bgr[3]) const {
  l = std::clamp(l, 0, int(levels_.size()) - 1);
  const cv::Mat& img = levels_[size_t(l)];
  const float scale = 1.0f / float(1 << l);
  // Texel centres sit at integer + 0.5, as in OpenGL, so levels stay aligned.
  const float x = u * scale - 0.5f;
  const float y = v * scale - 0.5f;
  const float fx0 = std::floor(x), fy0 = std::floor(y);
  const float ax = x - fx0, ay = y - fy0;
  int x0 = int(fx0), y0 = int(fy0);
  // Textures are sized to their surfaces, so wrapping (an integer division) is rarely needed.
  if (x0 < 0 || x0 >= img.cols) x0 = wrap(x0, img.cols);
  if (y0 < 0 || y0 >= img.rows) y0 = wrap(y0, img.rows);
  const int x1 = x0 + 1 == img.cols ? 0 : x0 + 1;
  const int y1 = y0 + 1 == img.rows ? 0 : y0 + 1;
  const uint8_t* r0 = img.ptr<uint8_t>(y0);
  const uint8_t* r1 = img.ptr<uint8_t>(y1);
  const float w00 = (1 - ax) * (1 - ay), w10 = ax * (1 - ay), w01 = (1 - ax) * ay, w11 = ax * ay;
  for (int c = 0; c < 3; ++c)
    out_bgr[c] =
        w00 * r0[3 * x0 + c] + w10 * r0[3 * x1 + c] + w01 * r1[3 * x0 + c] + w11 * r1[3 * x1 + c];
}

}  // namespace dynanav::sim
