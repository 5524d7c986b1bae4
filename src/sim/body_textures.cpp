#include "sim/body_textures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "sim/patterns.hpp"

namespace dynanav::sim {

namespace {
template <size_t N>
cv::Scalar pick(const std::array<cv::Scalar, N>& options, Rng& rng) {
  return options[size_t(rng.uniformInt(0, int(N) - 1))];
}

/// colour * (1 + amplitude * noise) per channel: shading-like variation that keeps the hue.
cv::Mat modulated(const cv::Mat& noise, const cv::Scalar& colour, float amplitude) {
  cv::Mat out(noise.size(), CV_8UC3);
  for (int y = 0; y < noise.rows; ++y) {
    const float* n = noise.ptr<float>(y);
    uint8_t* o = out.ptr<uint8_t>(y);
    for (int x = 0; x < noise.cols; ++x)
      for (int c = 0; c < 3; ++c)
        o[3 * x + c] = cv::saturate_cast<uint8_t>(colour[c] * (1.0f + amplitude * n[x]));
  }
  return out;
}
}  // namespace

BodyColours randomBodyColours(Rng& rng) {
  BodyColours c;
  // BGR; light to deep skin tones, as photographed indoors.
  c.skin = pick(std::array<cv::Scalar, 6>{cv::Scalar(150, 180, 228), cv::Scalar(125, 160, 214),
                                          cv::Scalar(100, 140, 196), cv::Scalar(75, 115, 170),
                                          cv::Scalar(55, 85, 135), cv::Scalar(40, 60, 100)},
                rng);
  c.hair = pick(std::array<cv::Scalar, 6>{cv::Scalar(20, 22, 26), cv::Scalar(25, 35, 50),
                                          cv::Scalar(30, 50, 80), cv::Scalar(55, 90, 130),
                                          cv::Scalar(90, 140, 180), cv::Scalar(190, 192, 196)},
                rng);
  c.shirt = pick(std::array<cv::Scalar, 12>{cv::Scalar(235, 235, 235), cv::Scalar(220, 190, 160),
                                            cv::Scalar(110, 60, 30), cv::Scalar(120, 120, 120),
                                            cv::Scalar(35, 35, 35), cv::Scalar(50, 90, 40),
                                            cv::Scalar(50, 40, 130), cv::Scalar(150, 190, 210),
                                            cv::Scalar(40, 40, 170), cv::Scalar(170, 120, 80),
                                            cv::Scalar(90, 160, 200), cv::Scalar(130, 80, 120)},
                 rng);
  c.trousers = pick(std::array<cv::Scalar, 6>{cv::Scalar(120, 75, 40), cv::Scalar(30, 30, 32),
                                              cv::Scalar(110, 160, 185), cv::Scalar(85, 85, 90),
                                              cv::Scalar(70, 40, 30), cv::Scalar(150, 105, 65)},
                    rng);
  c.shoes = pick(std::array<cv::Scalar, 4>{cv::Scalar(25, 25, 25), cv::Scalar(30, 50, 75),
                                           cv::Scalar(225, 225, 225), cv::Scalar(80, 80, 85)},
                 rng);
  const double p = rng.uniform();
  c.shirt_pattern = p < 0.55 ? 0 : (p < 0.7 ? 1 : (p < 0.85 ? 2 : 3));
  c.long_sleeves = rng.chance(0.6);
  c.hair_length = rng.chance(0.35) ? rng.uniform(0.5, 1.0) : rng.uniform(0.0, 0.25);
  return c;
}

cv::Mat skinTexture(cv::Size size, const BodyColours& colours, Rng& rng) {
  return modulated(fractalNoise(size, 12.0f, 3, rng), colours.skin, 0.06f);
}

cv::Mat faceTexture(cv::Size size, const BodyColours& colours, Rng& rng) {
  const int W = size.width, H = size.height;
  cv::Mat img = skinTexture(size, colours, rng);
  const cv::Scalar skin = colours.skin;
  const cv::Scalar hair = colours.hair;
  const int cx = W / 2;  // the face's centre column (the front of the head)
  const int fw = W / 6;  // half the face's width in texels
  // Hair: the crown, and the back of the head down to the nape (or further for long hair);
  // the hairline over the forehead is a soft arc.
  cv::Mat hair_mask(size, CV_8U, cv::Scalar(0));
  const int crown = int(0.31 * H);
  cv::rectangle(hair_mask, cv::Rect(0, 0, W, crown), 255, cv::FILLED);
  cv::ellipse(hair_mask, {cx, crown}, {int(1.25 * fw), int(0.07 * H)}, 0, 0, 180, 255, cv::FILLED,
              cv::LINE_AA);
  const int back_to = int((0.62 + 0.3 * colours.hair_length) * H);
  const int side = int(1.45 * fw);  // hair reaches round to just behind the ears
  cv::rectangle(hair_mask, cv::Rect(0, 0, cx - side, back_to), 255, cv::FILLED);
  cv::rectangle(hair_mask, cv::Rect(cx + side, 0, W - cx - side, back_to), 255, cv::FILLED);
  const cv::Mat strands = fractalNoise(size, 3.0f, 2, rng);
  for (int y = 0; y < H; ++y) {
    cv::Vec3b* row = img.ptr<cv::Vec3b>(y);
    const uint8_t* m = hair_mask.ptr<uint8_t>(y);
    const float* n = strands.ptr<float>(y);
    for (int x = 0; x < W; ++x) {
      const float a = float(m[x]) / 255.0f;  // anti-aliased hairline
      for (int c = 0; c < 3; ++c) {
        const float h = float(hair[c]) * (1.0f + 0.25f * n[x]) + 6.0f * n[x];
        row[x][c] = cv::saturate_cast<uint8_t>(a * h + (1.0f - a) * float(row[x][c]));
      }
    }
  }
  // Ears at the sides, a shade darker than the skin.
  for (int sgn : {-1, 1})
    cv::ellipse(img, {cx + sgn * int(1.5 * fw), int(0.52 * H)},
                {std::max(2, fw / 6), int(0.08 * H)}, 0, 0, 360, skin * 0.85, cv::FILLED,
                cv::LINE_AA);
  // Eyes (white, iris, lid shadow), brows, nose shading, lips; cheeks slightly warmer.
  const int eye_y = int(0.50 * H), eye_dx = int(0.38 * fw);
  const int eye_rx = std::max(2, int(0.17 * fw)), eye_ry = std::max(1, int(0.025 * H));
  for (int sgn : {-1, 1}) {
    const cv::Point e(cx + sgn * eye_dx, eye_y);
    cv::ellipse(img, e + cv::Point(0, -eye_ry), {eye_rx + 1, eye_ry + 2}, 0, 180, 360, skin * 0.75,
                cv::FILLED, cv::LINE_AA);
    cv::ellipse(img, e, {eye_rx, eye_ry}, 0, 0, 360, cv::Scalar(215, 220, 225), cv::FILLED,
                cv::LINE_AA);
    cv::circle(img, e, std::max(1, eye_ry), cv::Scalar(40, 45, 55), cv::FILLED, cv::LINE_AA);
    cv::ellipse(img, e + cv::Point(0, -int(0.06 * H)),
                {int(eye_rx * 1.3), std::max(1, int(0.015 * H))}, 0, 180, 360, hair * 0.9,
                std::max(1, int(0.012 * H)), cv::LINE_AA);
    cv::circle(img, e + cv::Point(sgn * int(0.1 * fw), int(0.14 * H)), int(0.22 * fw),
               skin * 0.97 + cv::Scalar(0, 0, 12), cv::FILLED, cv::LINE_AA);
  }
  cv::line(img, {cx + int(0.08 * fw), int(0.54 * H)}, {cx + int(0.1 * fw), int(0.64 * H)},
           skin * 0.78, std::max(1, fw / 14), cv::LINE_AA);
  cv::ellipse(img, {cx, int(0.655 * H)}, {int(0.16 * fw), int(0.015 * H)}, 0, 0, 360, skin * 0.75,
              cv::FILLED, cv::LINE_AA);
  cv::ellipse(img, {cx, int(0.74 * H)}, {int(0.3 * fw), std::max(1, int(0.022 * H))}, 0, 0, 360,
              skin * 0.8 + cv::Scalar(10, 10, 40), cv::FILLED, cv::LINE_AA);
  cv::line(img, {cx - int(0.28 * fw), int(0.74 * H)}, {cx + int(0.28 * fw), int(0.74 * H)},
           skin * 0.5, 1, cv::LINE_AA);
  cv::GaussianBlur(img, img, cv::Size(3, 3), 0.7);
  return img;
}

cv::Mat garmentTexture(cv::Size size, const cv::Scalar& colour, int pattern, Rng& rng) {
  cv::Mat img(size, CV_8UC3, colour);
  const cv::Scalar second = colour[0] + colour[1] + colour[2] > 360 ? colour * 0.8 : colour * 1.35;
  const int step = rng.uniformInt(5, 9);
  if (pattern == 1) {
    for (int x = 0; x < size.width; x += 2 * step)
      cv::line(img, {x, 0}, {x, size.height}, second, 1, cv::LINE_AA);
  } else if (pattern == 2) {
    for (int y = 0; y < size.height; y += 3 * step)
      cv::rectangle(img, cv::Rect(0, y, size.width, step), second, cv::FILLED);
    for (int x = 0; x < size.width; x += 3 * step)
      cv::rectangle(img, cv::Rect(x, 0, step, size.height), second * 0.9, cv::FILLED);
  }
  // Weave grain and soft folds (vertical creases): the light varies as on real cloth.
  cv::Mat folds = fractalNoise(size, 40.0f, 2, rng);
  cv::Mat grain = fractalNoise(size, 2.0f, 1, rng);
  const float grain_amp = pattern == 3 ? 0.1f : 0.05f;
  for (int y = 0; y < size.height; ++y) {
    cv::Vec3b* row = img.ptr<cv::Vec3b>(y);
    const float* f = folds.ptr<float>(y);
    const float* g = grain.ptr<float>(y);
    for (int x = 0; x < size.width; ++x)
      for (int c = 0; c < 3; ++c)
        row[x][c] = cv::saturate_cast<uint8_t>(
            row[x][c] * (1.0f + 0.12f * f[x] + grain_amp * g[x]) + 4.0f * g[x]);
  }
  return img;
}

}  // namespace dynanav::sim
