#pragma once
// Procedural textures, rich in corners and blobs at many scales: a feature-based SLAM runs on
// the rendered images, so surfaces must be high-contrast and never repeat. Every generator takes
// the scene's Rng; nothing depends on global state. Sizes are in texels.
#include <filesystem>
#include <opencv2/core.hpp>
#include <vector>

#include "sim/rng.hpp"

namespace dynanav::sim {

/// Optional real photographs (e.g. Debian's opencv-doc example images) used on posters. Read at
/// run time in sorted file order; empty when the folder is absent, and the simulator then paints
/// procedural posters instead.
class PhotoLibrary {
 public:
  PhotoLibrary() = default;
  explicit PhotoLibrary(const std::filesystem::path& dir);
  /// The Debian opencv-doc data folder if it exists, else an empty library.
  static PhotoLibrary systemDefault();
  [[nodiscard]] bool empty() const { return files_.empty(); }
  /// A photo chosen by `rng`, decoded on first use (a scene needs only a few of them).
  [[nodiscard]] const cv::Mat& pick(Rng& rng) const;

 private:
  std::vector<std::filesystem::path> files_;
  mutable std::vector<cv::Mat> decoded_;
};

/// Smooth noise in [-1, 1] (CV_32F) with features about `cell` texels wide, `octaves` finer ones
/// added.
cv::Mat fractalNoise(cv::Size size, float cell, int octaves, Rng& rng);
cv::Scalar randomColour(Rng& rng, int lo = 30, int hi = 230);

cv::Mat plaster(cv::Size size, Rng& rng);
cv::Mat bricks(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat woodPlanks(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat floorTiles(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat carpet(cv::Size size, Rng& rng);
cv::Mat ceilingTiles(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat poster(cv::Size size, Rng& rng, const PhotoLibrary& photos);
cv::Mat whiteboard(cv::Size size, Rng& rng);
/// Cork board with pinned notes, photos and cards.
cv::Mat pinboard(cv::Size size, float texels_per_m, Rng& rng, const PhotoLibrary& photos);
/// Wallpaper: small motifs on a jittered grid, each with its own colour and rotation (no repeats).
cv::Mat wallpaper(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat bookshelfFront(cv::Size size, float texels_per_m, Rng& rng);
cv::Mat fabric(cv::Size size, Rng& rng);
cv::Mat cardboard(cv::Size size, Rng& rng);
cv::Mat screen(cv::Size size, Rng& rng);
cv::Mat doorPanel(cv::Size size, Rng& rng);

/// Hangs posters, whiteboards, notices, text and blobs on a wall texture (in place).
void decorateWall(cv::Mat& wall, float texels_per_m, Rng& rng, const PhotoLibrary& photos);
/// Scatters papers, marks and rugs on a floor texture (in place).
void decorateFloor(cv::Mat& floor, float texels_per_m, Rng& rng);

}  // namespace dynanav::sim
