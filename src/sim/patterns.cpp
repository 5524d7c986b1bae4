// Surface textures: noise, plaster, bricks, wood, tiles, carpet, ceiling, fabric, cardboard.
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/patterns.hpp"

namespace dynanav::sim {

namespace fs = std::filesystem;

PhotoLibrary::PhotoLibrary(const fs::path& dir) {
  if (!fs::is_directory(dir)) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const auto ext = entry.path().extension().string();
    if (ext == ".jpg" || ext == ".png") files_.push_back(entry.path());
  }
  std::sort(files_.begin(), files_.end());  // directory order is not deterministic
  decoded_.resize(files_.size());
}

PhotoLibrary PhotoLibrary::systemDefault() {
  return PhotoLibrary("/usr/share/doc/opencv-doc/examples/data");
}

const cv::Mat& PhotoLibrary::pick(Rng& rng) const {
  static const cv::Mat kGrey(64, 64, CV_8UC3, cv::Scalar::all(128));
  size_t i = size_t(rng.uniformInt(0, int(files_.size()) - 1));
  // Unreadable or tiny files are skipped deterministically (the next file in order).
  for (size_t tries = 0; tries < files_.size(); ++tries, i = (i + 1) % files_.size()) {
    if (decoded_[i].empty()) {
      cv::Mat img = cv::imread(files_[i].string(), cv::IMREAD_COLOR);
      decoded_[i] = (img.empty() || img.cols < 64 || img.rows < 64) ? cv::Mat(1, 1, CV_8UC3) : img;
    }
    if (decoded_[i].cols >= 64) return decoded_[i];
  }
  return kGrey;
}

cv::Mat fractalNoise(cv::Size size, float cell, int octaves, Rng& rng) {
  cv::Mat sum = cv::Mat::zeros(size, CV_32F);
  float amplitude = 1.0f, total = 0.0f;
  for (int o = 0; o < octaves && cell >= 1.0f; ++o, cell /= 2.0f, amplitude *= 0.55f) {
    const int w = std::max(2, int(size.width / cell) + 2),
              h = std::max(2, int(size.height / cell) + 2);
    cv::Mat coarse(h, w, CV_32F);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) coarse.at<float>(y, x) = float(rng.uniform(-1.0, 1.0));
    cv::Mat fine;
    cv::resize(coarse, fine, cv::Size(int(w * cell), int(h * cell)), 0, 0, cv::INTER_CUBIC);
    sum += fine(cv::Rect(0, 0, size.width, size.height)) * amplitude;
    total += amplitude;
  }
  return sum / total;
}

cv::Scalar randomColour(Rng& rng, int lo, int hi) {
  return cv::Scalar(rng.uniformInt(lo, hi), rng.uniformInt(lo, hi), rng.uniformInt(lo, hi));
}

namespace {
/// base colour + amplitude * noise, per channel (noise CV_32F in [-1, 1]).
cv::Mat tinted(const cv::Mat& noise, const cv::Scalar& base, float amplitude) {
  cv::Mat out(noise.size(), CV_8UC3);
  for (int y = 0; y < noise.rows; ++y) {
    const float* n = noise.ptr<float>(y);
    uint8_t* o = out.ptr<uint8_t>(y);
    for (int x = 0; x < noise.cols; ++x)
      for (int c = 0; c < 3; ++c)
        o[3 * x + c] = cv::saturate_cast<uint8_t>(base[c] + amplitude * n[x]);
  }
  return out;
}

void addNoise(cv::Mat& img, float cell, float amplitude, Rng& rng) {
  cv::Mat n = fractalNoise(img.size(), cell, 3, rng);
  cv::Mat n3;
  cv::merge(std::vector<cv::Mat>{n, n, n}, n3);
  cv::Mat f;
  img.convertTo(f, CV_32FC3);
  f += n3 * amplitude;
  f.convertTo(img, CV_8UC3);
}

void speckle(cv::Mat& img, int count, int max_radius, Rng& rng) {
  for (int i = 0; i < count; ++i) {
    const cv::Point c(rng.uniformInt(0, img.cols - 1), rng.uniformInt(0, img.rows - 1));
    const int shade = rng.chance(0.5) ? rng.uniformInt(0, 60) : rng.uniformInt(190, 255);
    cv::circle(img, c, rng.uniformInt(1, max_radius), cv::Scalar::all(shade), cv::FILLED,
               cv::LINE_AA);
  }
}
}  // namespace

cv::Mat plaster(cv::Size size, Rng& rng) {
  const cv::Scalar base(rng.uniformInt(120, 210), rng.uniformInt(120, 210),
                        rng.uniformInt(120, 210));
  cv::Mat img = tinted(fractalNoise(size, 120.0f, 5, rng), base, 45.0f);
  speckle(img, size.area() / 4000, 3, rng);
  return img;
}

cv::Mat bricks(cv::Size size, float tpm, Rng& rng) {
  const int bw = std::max(8, int(0.24f * tpm)), bh = std::max(4, int(0.075f * tpm));
  const int mortar = std::max(1, int(0.012f * tpm));
  cv::Mat img(size, CV_8UC3, cv::Scalar(175, 180, 185));
  const cv::Scalar brick_base(rng.uniformInt(30, 70), rng.uniformInt(50, 90),
                              rng.uniformInt(110, 170));
  for (int row = 0, y = 0; y < size.height; ++row, y += bh + mortar) {
    const int shift = (row % 2) * (bw + mortar) / 2;
    for (int x = -shift; x < size.width; x += bw + mortar) {
      const cv::Scalar c =
          brick_base + cv::Scalar::all(rng.uniform(-35, 35)) +
          cv::Scalar(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-15, 15));
      cv::rectangle(img, cv::Rect(x, y, bw, bh), c, cv::FILLED);
    }
  }
  addNoise(img, 12.0f, 22.0f, rng);
  speckle(img, size.area() / 3000, 2, rng);
  return img;
}

cv::Mat woodPlanks(cv::Size size, float tpm, Rng& rng) {
  const int plank = std::max(8, int(rng.uniform(0.12, 0.2) * tpm));
  const cv::Scalar base(rng.uniformInt(40, 80), rng.uniformInt(80, 120), rng.uniformInt(120, 170));
  cv::Mat warp = fractalNoise(size, 60.0f, 3, rng);
  cv::Mat img(size, CV_8UC3);
  for (int x0 = 0; x0 < size.width; x0 += plank) {
    const double phase = rng.uniform(0, 100), period = rng.uniform(5, 11);
    const cv::Scalar c = base + cv::Scalar::all(rng.uniform(-30, 30));
    const int joint = rng.uniformInt(0, size.height - 1);
    for (int y = 0; y < size.height; ++y) {
      uint8_t* o = img.ptr<uint8_t>(y);
      const float* w = warp.ptr<float>(y);
      for (int x = x0; x < std::min(size.width, x0 + plank); ++x) {
        const double g = std::sin((x + phase + 25.0 * w[x]) / period * 2.0) * 0.5 + 0.5;
        const double k = (x == x0 || std::abs(y - joint) < 1) ? 0.35 : 0.8 + 0.3 * g;
        for (int ch = 0; ch < 3; ++ch) o[3 * x + ch] = cv::saturate_cast<uint8_t>(c[ch] * k);
      }
    }
  }
  return img;
}

cv::Mat floorTiles(cv::Size size, float tpm, Rng& rng) {
  const int tile = std::max(8, int(rng.uniform(0.3, 0.5) * tpm));
  cv::Mat img(size, CV_8UC3, cv::Scalar(90, 90, 95));
  const cv::Scalar a = randomColour(rng, 90, 220), b = randomColour(rng, 40, 160);
  for (int y = 0; y < size.height; y += tile)
    for (int x = 0; x < size.width; x += tile) {
      const double t = rng.uniform();
      const cv::Scalar c = a * t + b * (1 - t) + cv::Scalar::all(rng.uniform(-20, 20));
      cv::rectangle(img, cv::Rect(x + 1, y + 1, tile - 2, tile - 2), c, cv::FILLED);
    }
  addNoise(img, 20.0f, 25.0f, rng);
  speckle(img, size.area() / 1500, 3, rng);
  return img;
}

cv::Mat carpet(cv::Size size, Rng& rng) {
  cv::Mat img = tinted(fractalNoise(size, 40.0f, 5, rng), randomColour(rng, 60, 140), 70.0f);
  for (int i = 0; i < size.area() / 6000; ++i) {  // woven motifs
    const cv::Point c(rng.uniformInt(0, size.width), rng.uniformInt(0, size.height));
    const int r = rng.uniformInt(6, 30);
    cv::rectangle(img, c - cv::Point(r, r), c + cv::Point(r, r), randomColour(rng), 2);
    cv::circle(img, c, r / 2, randomColour(rng), cv::FILLED);
  }
  speckle(img, size.area() / 800, 2, rng);
  return img;
}

cv::Mat ceilingTiles(cv::Size size, float tpm, Rng& rng) {
  const int tile = std::max(8, int(0.6f * tpm));
  cv::Mat img = tinted(fractalNoise(size, 30.0f, 4, rng), cv::Scalar(215, 218, 220), 25.0f);
  speckle(img, size.area() / 500, 1, rng);
  for (int y = 0; y < size.height; y += tile)
    for (int x = 0; x < size.width; x += tile) {
      cv::rectangle(img, cv::Rect(x, y, tile, tile), cv::Scalar(120, 125, 130), 2);
      if (rng.chance(0.15))
        cv::rectangle(img, cv::Rect(x + 4, y + 4, tile - 8, tile - 8), cv::Scalar(250, 252, 255),
                      cv::FILLED);
    }
  return img;
}

cv::Mat fabric(cv::Size size, Rng& rng) {
  const cv::Scalar a = randomColour(rng, 20, 220), b = randomColour(rng, 20, 220);
  cv::Mat img(size, CV_8UC3, a);
  const int kind = rng.uniformInt(0, 3);
  const int step = rng.uniformInt(6, 18);
  if (kind == 0) {  // stripes
    for (int y = 0; y < size.height; y += 2 * step)
      cv::rectangle(img, cv::Rect(0, y, size.width, step), b, cv::FILLED);
  } else if (kind == 1) {  // plaid
    for (int y = 0; y < size.height; y += 3 * step)
      cv::rectangle(img, cv::Rect(0, y, size.width, step), b, cv::FILLED);
    for (int x = 0; x < size.width; x += 3 * step)
      cv::rectangle(img, cv::Rect(x, 0, step / 2 + 1, size.height), b * 0.6, cv::FILLED);
  } else if (kind == 2) {  // dots
    for (int y = step; y < size.height; y += 2 * step)
      for (int x = step + (y / step % 2) * step; x < size.width; x += 3 * step)
        cv::circle(img, {x, y}, step / 2 + 1, b, cv::FILLED, cv::LINE_AA);
  }
  // A printed logo or slogan: big, high contrast, different on every garment.
  const std::string letters = "ABCDEFGHKMNPRSTUWXYZ0123456789";
  std::string text;
  for (int i = 0; i < 4; ++i) text += letters[size_t(rng.uniformInt(0, int(letters.size()) - 1))];
  cv::putText(img, text, {size.width / 8, size.height / 2}, cv::FONT_HERSHEY_DUPLEX,
              size.width / 120.0, randomColour(rng), 3, cv::LINE_AA);
  addNoise(img, 8.0f, 18.0f, rng);
  return img;
}

cv::Mat cardboard(cv::Size size, Rng& rng) {
  cv::Mat img = tinted(fractalNoise(size, 25.0f, 4, rng), cv::Scalar(80, 135, 185), 25.0f);
  const int tape = size.height / 8;
  cv::rectangle(img, cv::Rect(0, size.height / 2 - tape / 2, size.width, tape),
                cv::Scalar(70, 180, 210), cv::FILLED);
  cv::rectangle(img, cv::Rect(size.width / 10, size.height / 8, size.width / 3, size.height / 4),
                cv::Scalar(245, 245, 245), cv::FILLED);
  for (int i = 0; i < 3; ++i)
    cv::putText(img, "FRAGILE " + std::to_string(rng.uniformInt(100, 999)),
                {size.width / 9, size.height / 8 + (i + 1) * size.height / 16},
                cv::FONT_HERSHEY_PLAIN, size.width / 400.0, cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
  cv::arrowedLine(img, {size.width * 3 / 4, size.height * 7 / 8},
                  {size.width * 3 / 4, size.height * 5 / 8}, cv::Scalar(30, 30, 30), 4);
  speckle(img, size.area() / 2000, 2, rng);
  return img;
}

}  // namespace dynanav::sim
