#pragma once
// Textures for simulated people, made to look like people to a person detector trained on
// photographs (COCO): skin in human tones, a face with eyes, brows, nose and mouth, hair, and
// clothing in the plain or lightly patterned colours people wear (no logos or loud patterns).
// Heads and garments are wrapped round lathe meshes (Mesh::addLathe): u once round from the
// back, so the face sits in the middle of the width; v from top to bottom.
#include <opencv2/core.hpp>

#include "sim/rng.hpp"

namespace dynanav::sim {

/// One person's colours, drawn once so face, hands and hair agree.
struct BodyColours {
  cv::Scalar skin, hair, shirt, trousers, shoes;  ///< BGR
  int shirt_pattern = 0;                          ///< 0 plain, 1 fine stripes, 2 check, 3 heather
  bool long_sleeves = true;                       ///< else forearms show skin
  double hair_length = 0.0;  ///< 0 short .. 1 to the shoulders (back of the head)
};
BodyColours randomBodyColours(Rng& rng);

/// Skin with a faint mottle (hands, forearms, neck).
cv::Mat skinTexture(cv::Size size, const BodyColours& colours, Rng& rng);
/// A head wrapped round an ellipsoid: hair on the crown and back, the face at the front.
cv::Mat faceTexture(cv::Size size, const BodyColours& colours, Rng& rng);
/// Woven cloth with soft folds; `pattern` as in BodyColours.
cv::Mat garmentTexture(cv::Size size, const cv::Scalar& colour, int pattern, Rng& rng);

}  // namespace dynanav::sim
