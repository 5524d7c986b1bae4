// Things on walls and floors: posters, whiteboards, book spines, screens, doors, papers.
#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>

#include "sim/patterns.hpp"

namespace dynanav::sim {

namespace {
std::string randomWord(Rng& rng, int min_len, int max_len) {
  static const std::string kLetters =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::string w;
  const int n = rng.uniformInt(min_len, max_len);
  for (int i = 0; i < n; ++i) w += kLetters[size_t(rng.uniformInt(0, int(kLetters.size()) - 1))];
  return w;
}

const int kFonts[] = {cv::FONT_HERSHEY_SIMPLEX, cv::FONT_HERSHEY_DUPLEX, cv::FONT_HERSHEY_COMPLEX,
                      cv::FONT_HERSHEY_TRIPLEX, cv::FONT_HERSHEY_PLAIN};

/// Lines of random text filling a region: text is full of corners at many scales.
void textBlock(cv::Mat& img, const cv::Rect& area, double scale, const cv::Scalar& colour,
               Rng& rng) {
  const int font = kFonts[rng.uniformInt(0, 4)];
  int baseline = 0;
  const int line_h = cv::getTextSize("Ag", font, scale, 1, &baseline).height * 2;
  for (int y = area.y + line_h; y < area.br().y; y += line_h) {
    int x = area.x;
    while (x < area.br().x) {
      const std::string w = randomWord(rng, 2, 8);
      const int width = cv::getTextSize(w, font, scale, 1, &baseline).width;
      if (x + width > area.br().x) break;
      cv::putText(img, w, {x, y}, font, scale, colour, std::max(1, int(scale * 1.5)), cv::LINE_AA);
      x += width + line_h / 2;
    }
  }
}

void shapes(cv::Mat& img, int count, Rng& rng) {
  for (int i = 0; i < count; ++i) {
    const cv::Point c(rng.uniformInt(0, img.cols), rng.uniformInt(0, img.rows));
    const int r = rng.uniformInt(img.cols / 20 + 2, img.cols / 5 + 3);
    const cv::Scalar col = randomColour(rng, 0, 255);
    switch (rng.uniformInt(0, 3)) {
      case 0:
        cv::circle(img, c, r, col, cv::FILLED, cv::LINE_AA);
        break;
      case 1:
        cv::rectangle(img, c, c + cv::Point(r, r * 2 / 3), col, cv::FILLED);
        break;
      case 2: {
        std::vector<cv::Point> tri{c, c + cv::Point(r, rng.uniformInt(-r, r)),
                                   c + cv::Point(rng.uniformInt(-r, r), r)};
        cv::fillConvexPoly(img, tri, col, cv::LINE_AA);
        break;
      }
      default:
        cv::line(img, c,
                 c + cv::Point(rng.uniformInt(-2 * r, 2 * r), rng.uniformInt(-2 * r, 2 * r)), col,
                 rng.uniformInt(2, 6), cv::LINE_AA);
    }
  }
}

void paste(cv::Mat& dst, const cv::Mat& src, cv::Point at) {
  const cv::Rect r = cv::Rect(at, src.size()) & cv::Rect(0, 0, dst.cols, dst.rows);
  if (r.area() > 0) src(cv::Rect(r.tl() - at, r.size())).copyTo(dst(r));
}
}  // namespace

cv::Mat poster(cv::Size size, Rng& rng, const PhotoLibrary& photos) {
  cv::Mat img(size, CV_8UC3, randomColour(rng, 0, 255));
  if (!photos.empty() && rng.chance(0.6)) {
    cv::Mat photo;
    cv::resize(photos.pick(rng), photo, size, 0, 0, cv::INTER_AREA);
    return photo;
  }
  shapes(img, rng.uniformInt(6, 16), rng);
  const double scale = size.width / 180.0;
  cv::putText(img, randomWord(rng, 3, 7), {size.width / 12, size.height / 5},
              kFonts[rng.uniformInt(0, 3)], scale, randomColour(rng), std::max(1, int(scale * 2)),
              cv::LINE_AA);
  textBlock(img,
            cv::Rect(size.width / 12, size.height * 2 / 3, size.width * 5 / 6, size.height / 4),
            scale / 3, cv::Scalar::all(rng.chance(0.5) ? 10 : 245), rng);
  cv::rectangle(img, cv::Rect(0, 0, size.width, size.height), cv::Scalar::all(15),
                std::max(2, size.width / 60));
  return img;
}

cv::Mat whiteboard(cv::Size size, Rng& rng) {
  cv::Mat img(size, CV_8UC3, cv::Scalar(238, 240, 240));
  const cv::Scalar pens[] = {{20, 20, 20}, {180, 40, 30}, {30, 40, 190}, {40, 140, 40}};
  for (int i = 0; i < rng.uniformInt(4, 9); ++i) {  // scribbled diagrams
    std::vector<cv::Point> pts;
    cv::Point p(rng.uniformInt(0, size.width), rng.uniformInt(0, size.height));
    for (int k = 0; k < rng.uniformInt(3, 8); ++k) {
      p += cv::Point(rng.uniformInt(-size.width / 6, size.width / 6),
                     rng.uniformInt(-size.height / 5, size.height / 5));
      pts.push_back(p);
    }
    cv::polylines(img, pts, rng.chance(0.4), pens[rng.uniformInt(0, 3)], 3, cv::LINE_AA);
  }
  textBlock(img,
            cv::Rect(size.width / 20, size.height / 20, size.width * 9 / 10, size.height * 9 / 10),
            size.width / 500.0, pens[rng.uniformInt(0, 3)], rng);
  cv::rectangle(img, cv::Rect(0, 0, size.width, size.height), cv::Scalar(160, 160, 165),
                std::max(3, size.width / 80));
  return img;
}

cv::Mat pinboard(cv::Size size, float tpm, Rng& rng, const PhotoLibrary& photos) {
  cv::Mat img(size, CV_8UC3, cv::Scalar(60, 110, 160));
  for (int y = 0; y < size.height; ++y)  // cork grain
    for (int x = 0; x < size.width; ++x) {
      const int v = rng.uniformInt(-35, 35);
      img.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uint8_t>(60 + v), cv::saturate_cast<uint8_t>(110 + v),
                    cv::saturate_cast<uint8_t>(160 + v));
    }
  cv::GaussianBlur(img, img, {3, 3}, 0.8);
  const int count = int(float(size.area()) / (tpm * tpm) * 14.0f);
  for (int i = 0; i < count; ++i) {
    const cv::Size s(int(rng.uniform(0.08, 0.3) * tpm), int(rng.uniform(0.08, 0.3) * tpm));
    if (s.width < 6 || s.height < 6) continue;
    cv::Mat note;
    const int kind = rng.uniformInt(0, 3);
    if (kind == 0)
      note = poster(s, rng, photos);
    else {
      note =
          cv::Mat(s, CV_8UC3, kind == 1 ? randomColour(rng, 150, 255) : cv::Scalar(245, 245, 245));
      textBlock(note, cv::Rect(2, 2, s.width - 4, s.height - 4), s.width / 260.0,
                cv::Scalar::all(rng.uniformInt(0, 80)), rng);
    }
    const cv::Point at(rng.uniformInt(0, std::max(0, size.width - s.width)),
                       rng.uniformInt(0, std::max(0, size.height - s.height)));
    paste(img, note, at);
    cv::circle(img, at + cv::Point(s.width / 2, 3), 3, randomColour(rng), cv::FILLED,
               cv::LINE_AA);  // the pin
  }
  return img;
}

cv::Mat wallpaper(cv::Size size, float tpm, Rng& rng) {
  cv::Mat img = plaster(size, rng);
  const int step = std::max(6, int(rng.uniform(0.12, 0.25) * tpm));
  const cv::Scalar ink = randomColour(rng, 0, 255);
  for (int y = step / 2; y < size.height; y += step)
    for (int x = step / 2; x < size.width; x += step) {
      const cv::Point c(x + rng.uniformInt(-step / 4, step / 4),
                        y + rng.uniformInt(-step / 4, step / 4));
      const cv::Scalar col = ink * rng.uniform(0.5, 1.2) + cv::Scalar::all(rng.uniform(-40, 40));
      const int r = step / 4 + rng.uniformInt(0, step / 6);
      switch (rng.uniformInt(0, 3)) {
        case 0:
          cv::circle(img, c, r, col, 2, cv::LINE_AA);
          break;
        case 1: {
          const cv::RotatedRect rr(c, cv::Size2f(float(r) * 2, float(r)),
                                   float(rng.uniform(0, 180)));
          cv::ellipse(img, rr, col, cv::FILLED, cv::LINE_AA);
          break;
        }
        case 2:
          cv::drawMarker(img, c, col, rng.uniformInt(0, 6), 2 * r, 2, cv::LINE_AA);
          break;
        default:
          cv::putText(img, std::string(1, char('A' + rng.uniformInt(0, 25))), c,
                      cv::FONT_HERSHEY_DUPLEX, r / 10.0, col, 2, cv::LINE_AA);
      }
    }
  return img;
}

cv::Mat bookshelfFront(cv::Size size, float tpm, Rng& rng) {
  cv::Mat img(size, CV_8UC3, cv::Scalar(40, 70, 110));
  const int board = std::max(3, int(0.025f * tpm)), shelf_h = std::max(10, int(0.38f * tpm));
  for (int y0 = board; y0 + shelf_h / 2 < size.height; y0 += shelf_h + board) {
    cv::rectangle(img, cv::Rect(0, y0 - board, size.width, board), cv::Scalar(60, 100, 150),
                  cv::FILLED);
    for (int x = board; x < size.width - board;) {
      const int w = std::max(3, int(rng.uniform(0.02, 0.06) * tpm));
      const int h = std::min(shelf_h, int(rng.uniform(0.6, 0.95) * shelf_h));
      if (rng.chance(0.08)) {
        x += w * 2;
        continue;
      }  // gaps
      const cv::Rect book(x, y0 + shelf_h - h, std::min(w, size.width - board - x), h);
      const cv::Scalar c = randomColour(rng, 10, 240);
      cv::rectangle(img, book, c, cv::FILLED);
      cv::rectangle(img, cv::Rect(book.x, book.y + h / 6, book.width, std::max(1, h / 12)),
                    c * 0.4 + cv::Scalar::all(140), cv::FILLED);
      cv::line(img, {book.x, book.y}, {book.x, book.br().y}, c * 0.5, 1);
      x += w;
    }
  }
  return img;
}

cv::Mat screen(cv::Size size, Rng& rng) {
  cv::Mat img(size, CV_8UC3, cv::Scalar(40, 30, 25));
  for (int i = 0; i < rng.uniformInt(2, 4); ++i) {  // windows with text
    const cv::Rect w(rng.uniformInt(0, size.width / 2), rng.uniformInt(0, size.height / 2),
                     rng.uniformInt(size.width / 3, size.width * 2 / 3),
                     rng.uniformInt(size.height / 3, size.height * 2 / 3));
    const cv::Rect r = w & cv::Rect(0, 0, size.width, size.height);
    cv::rectangle(img, r, cv::Scalar::all(rng.chance(0.5) ? 235 : 50), cv::FILLED);
    cv::rectangle(img, cv::Rect(r.x, r.y, r.width, std::max(4, r.height / 10)), randomColour(rng),
                  cv::FILLED);
    textBlock(img, cv::Rect(r.x + 4, r.y + r.height / 8, r.width - 8, r.height * 7 / 8),
              size.width / 700.0, randomColour(rng, 0, 255), rng);
  }
  return img;
}

cv::Mat doorPanel(cv::Size size, Rng& rng) {
  cv::Mat img = woodPlanks(size, float(size.width) / 0.9f, rng);
  const int m = size.width / 8;
  for (int k = 0; k < 2; ++k) {  // two raised panels
    const cv::Rect p(m, m + k * (size.height / 2), size.width - 2 * m, size.height / 2 - 2 * m);
    cv::rectangle(img, p, cv::Scalar(30, 50, 80), std::max(2, m / 5));
  }
  cv::rectangle(img, cv::Rect(size.width - 2 * m, size.height / 2 - m / 3, m + m / 2, m / 2),
                cv::Scalar(200, 200, 205), cv::FILLED);
  cv::putText(img, std::to_string(rng.uniformInt(100, 399)), {size.width / 3, m * 3 / 2 + m},
              cv::FONT_HERSHEY_DUPLEX, size.width / 160.0, cv::Scalar(230, 230, 230), 2,
              cv::LINE_AA);
  return img;
}

void decorateWall(cv::Mat& wall, float tpm, Rng& rng, const PhotoLibrary& photos) {
  // Items between 0.7 m and 2.1 m above the floor (v runs down from the ceiling at 2.8 m).
  const float wall_m = float(wall.cols) / tpm;
  const int count = int(wall_m * rng.uniform(1.8, 2.6));
  for (int i = 0; i < count; ++i) {
    const int kind = rng.uniformInt(0, 9);
    const float w_m = kind < 5   ? float(rng.uniform(0.35, 0.9))
                      : kind < 7 ? float(rng.uniform(0.9, 1.6))
                                 : float(rng.uniform(0.15, 0.3));
    const float h_m = kind < 5   ? w_m * float(rng.uniform(1.0, 1.5))
                      : kind < 7 ? float(rng.uniform(0.6, 0.9))
                                 : w_m * 1.3f;
    const cv::Size s(std::max(8, int(w_m * tpm)), std::max(8, int(h_m * tpm)));
    const int x = rng.uniformInt(0, std::max(0, wall.cols - s.width));
    const int top_px = int(0.7f * tpm), bottom_px = std::min(wall.rows, int(2.1f * tpm));
    const int y =
        rng.uniformInt(std::min(top_px, wall.rows - 1), std::max(top_px, bottom_px - s.height));
    cv::Mat item = kind < 5   ? poster(s, rng, photos)
                   : kind < 7 ? whiteboard(s, rng)
                              : cv::Mat(s, CV_8UC3, cv::Scalar(245, 245, 240));
    if (kind >= 7)
      textBlock(item, cv::Rect(4, 4, s.width - 8, s.height - 8), s.width / 350.0,
                cv::Scalar::all(20), rng);
    paste(wall, item, {x, y});
  }
  // A skirting board and a few sockets and switches near the floor and doors.
  const int skirting = std::max(2, int(0.08f * tpm));
  cv::rectangle(wall, cv::Rect(0, wall.rows - skirting, wall.cols, skirting),
                cv::Scalar::all(rng.uniformInt(20, 240)), cv::FILLED);
  for (int i = 0; i < int(wall_m / 2) + 1; ++i) {
    const int sx = rng.uniformInt(0, wall.cols - 1);
    const int sy = wall.rows - int(rng.chance(0.5) ? 0.3f * tpm : 1.1f * tpm);
    cv::rectangle(wall, cv::Rect(sx, sy, int(0.08f * tpm) + 2, int(0.08f * tpm) + 2),
                  cv::Scalar(235, 235, 235), cv::FILLED);
    cv::rectangle(wall, cv::Rect(sx, sy, int(0.08f * tpm) + 2, int(0.08f * tpm) + 2),
                  cv::Scalar(80, 80, 80), 1);
  }
}

void decorateFloor(cv::Mat& floor, float tpm, Rng& rng) {
  const float area_m2 = float(floor.total()) / (tpm * tpm);
  for (int i = 0; i < int(area_m2 / 12.0f) + 1; ++i) {  // rugs
    const cv::Size s(int(rng.uniform(1.0, 2.0) * tpm), int(rng.uniform(0.7, 1.4) * tpm));
    cv::Mat rug = carpet(s, rng);
    cv::rectangle(rug, cv::Rect(0, 0, s.width, s.height), randomColour(rng),
                  std::max(2, s.width / 25));
    paste(floor, rug,
          {rng.uniformInt(0, std::max(0, floor.cols - s.width)),
           rng.uniformInt(0, std::max(0, floor.rows - s.height))});
  }
  // Papers with print, stickers, tape crosses and stains: corners on the floor near the feet,
  // where the depth sensor always has returns.
  for (int i = 0; i < int(area_m2 * 3.0f); ++i) {
    const cv::Point c(rng.uniformInt(0, floor.cols - 1), rng.uniformInt(0, floor.rows - 1));
    const int kind = rng.uniformInt(0, 3);
    if (kind == 0) {
      const cv::Size s(int(rng.uniform(0.12, 0.3) * tpm), int(rng.uniform(0.1, 0.25) * tpm));
      if (s.width < 8 || s.height < 8) continue;
      cv::Mat paper(s, CV_8UC3,
                    rng.chance(0.6) ? cv::Scalar::all(rng.uniformInt(215, 255))
                                    : randomColour(rng, 120, 255));
      textBlock(paper, cv::Rect(2, 2, s.width - 4, s.height - 4), s.width / 250.0,
                cv::Scalar::all(rng.uniformInt(0, 60)), rng);
      if (rng.chance(0.5)) cv::rotate(paper, paper, cv::ROTATE_90_CLOCKWISE);
      paste(floor, paper, c);
    } else if (kind == 1) {
      const int r = int(rng.uniform(0.02, 0.06) * tpm) + 1;
      cv::circle(floor, c, r, randomColour(rng, 0, 255), cv::FILLED, cv::LINE_AA);
      cv::circle(floor, c, r / 2, randomColour(rng, 0, 255), cv::FILLED, cv::LINE_AA);
    } else if (kind == 2) {
      const int len = int(rng.uniform(0.05, 0.15) * tpm) + 2, w = std::max(2, int(0.02f * tpm));
      const cv::Scalar tape = rng.chance(0.5) ? cv::Scalar(0, 210, 255) : randomColour(rng, 0, 255);
      cv::line(floor, c - cv::Point(len, 0), c + cv::Point(len, 0), tape, w);
      cv::line(floor, c - cv::Point(0, len), c + cv::Point(0, len), tape, w);
    } else {
      const cv::Size axes(int(rng.uniform(0.02, 0.1) * tpm) + 1,
                          int(rng.uniform(0.02, 0.08) * tpm) + 1);
      cv::ellipse(floor, c, axes, rng.uniform(0, 180), 0, 360,
                  cv::Scalar::all(rng.uniformInt(10, 60)), cv::FILLED, cv::LINE_AA);
    }
  }
}

}  // namespace dynanav::sim
