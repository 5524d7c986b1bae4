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
  /// Writes B, G, R as floats in [0, 255].
  void sample(float u, float v, int l, float out_bgr[3]) const;

 private:
  std::vector<cv::Mat> levels_;
};

/// All textures of a scene; meshes refer to them by index.
using TextureSet = std::vector<Texture>;

}  // namespace dynanav::sim
