#pragma once
// Textures for the rasteriser: a BGR image with its mip pyramid, sampled bilinearly with
// wrap-around. Texture coordinates are texels of level 0; level l is sampled at (u, v) / 2^l.
#include <opencv2/core.hpp>
#include <vector>

namespace dynanav::sim {

class Texture {
 public:
  Texture() = default;
  /// Builds the mip pyramid (pyrDown) of a CV_8UC3 image down to ~8 texels.
  explicit Texture(const cv::Mat& bgr);

  [[nodiscard]] int levels() const { return int(levels_.size()); }
  [[nodiscard]] const cv::Mat& level(int l) const { return levels_[size_t(l)]; }
  [[nodiscard]] cv::Size size() const { return levels_.empty() ? cv::Size() : levels_[0].size(); }

  /// Bilinear sample at level-0 texel coordinates (u, v) on mip level `l` (clamped), repeating.
  /// Writes B, G, R as floats in [0, 255]. Inline: it runs once per visible pixel.
  void sample(float u, float v, int l, float out_bgr[3]) const {
    l = l < 0 ? 0 : (l >= int(levels_.size()) ? int(levels_.size()) - 1 : l);
    const cv::Mat& img = levels_[size_t(l)];
    const float scale = 1.0f / float(1 << l);
    // Texel centres sit at integer + 0.5, as in OpenGL, so levels stay aligned.
    const float x = u * scale - 0.5f, y = v * scale - 0.5f;
    int x0 = int(x), y0 = int(y);
    x0 -= x < float(x0);  // floor
    y0 -= y < float(y0);
    const float ax = x - float(x0), ay = y - float(y0);
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

 private:
  static int wrap(int i, int n) {
    i %= n;
    return i < 0 ? i + n : i;
  }
  std::vector<cv::Mat> levels_;
};

/// All textures of a scene; meshes refer to them by index.
using TextureSet = std::vector<Texture>;

}  // namespace dynanav::sim
