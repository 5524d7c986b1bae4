#include "dynamics/object_flow.hpp"

#include <algorithm>
#include <cmath>

#include "core/median.hpp"
#include "dynamics/object_points.hpp"

namespace dynanav {
namespace {

/// The object's half-size pixels inside `crop_half`: their mean grey and horizontal extent.
struct CropExtent {
  double mean_grey = -1.0;  ///< -1: none
  int width_half = 0;       ///< columns from its leftmost to its rightmost pixel
};

CropExtent objectExtent(const ObjectView& view, cv::Rect crop_half) {
  double sum = 0.0;
  int n = 0, left = crop_half.br().x, right = crop_half.x - 1;
  for (int y = crop_half.y; y < crop_half.br().y; ++y) {
    const uint16_t* label = view.labels.ptr<uint16_t>(std::min(2 * y, view.labels.rows - 1));
    const uint8_t* row = view.grey_half.ptr<uint8_t>(y);
    for (int x = crop_half.x; x < crop_half.br().x; ++x)
      if (label[std::min(2 * x, view.labels.cols - 1)] == view.label) {
        sum += row[x];
        ++n;
        left = std::min(left, x);
        right = std::max(right, x);
      }
  }
  if (n == 0) return {};
  return {sum / n, right - left + 1};
}

}  // namespace

cv::Mat objectCrop(const ObjectView& view, cv::Rect crop_half, uint8_t fill) {
  cv::Mat out = view.grey_half(crop_half).clone();
  const bool with_depth = view.depth_m.size() == view.labels.size() && view.nearer_than_m > 0.0;
  for (int y = 0; y < out.rows; ++y) {
    const int yf = std::min(2 * (y + crop_half.y), view.labels.rows - 1);
    const uint16_t* label = view.labels.ptr<uint16_t>(yf);
    const float* depth = with_depth ? view.depth_m.ptr<float>(yf) : nullptr;
    uint8_t* row = out.ptr<uint8_t>(y);
    for (int x = 0; x < out.cols; ++x) {
      const int xf = std::min(2 * (x + crop_half.x), view.labels.cols - 1);
      if (label[xf] == view.label) continue;
      if (depth && depth[xf] > 0.f && depth[xf] < view.nearer_than_m) continue;
      row[x] = fill;
    }
  }
  return out;
}

CroppedFlow objectFlow(const ObjectView& previous, const ObjectView& current, cv::Rect box,
                       cv::Point shift_half, int margin_px, int fill_offset,
                       cv::DISOpticalFlow& dis) {
  CroppedFlow out;
  if (previous.label == 0 || current.label == 0 ||
      previous.grey_half.size() != current.grey_half.size() ||
      previous.labels.size() != current.labels.size())
    return out;
  const cv::Rect half_image(0, 0, current.grey_half.cols, current.grey_half.rows);
  const cv::Rect grown(box.x - margin_px, box.y - margin_px, box.width + 2 * margin_px,
                       box.height + 2 * margin_px);
  // The previous crop, clipped so that it lies in the image moved by the shift as well.
  const cv::Rect crop_was =
      cv::Rect(grown.x / 2, grown.y / 2, (grown.width + 1) / 2, (grown.height + 1) / 2) &
      half_image & (half_image - shift_half);
  const cv::Rect crop_now = crop_was + shift_half;
  // DIS needs its patches to fit at least its finest level.
  const int min_side = dis.getPatchSize() << (dis.getFinestScale() + 1);
  if (crop_was.width < min_side || crop_was.height < min_side) return out;
  // An object narrower than one of DIS's patches (a sliver coming into view) has too little of
  // its own texture for a patch to match.
  const CropExtent was = objectExtent(previous, crop_was);
  const CropExtent now = objectExtent(current, crop_now);
  if (was.mean_grey < 0.0 || now.mean_grey < 0.0 || was.width_half < dis.getPatchSize() ||
      now.width_half < dis.getPatchSize())
    return out;
  // A grey that stands apart from the object, the same in both frames (brightness constancy).
  const double mean = was.mean_grey;
  const int fill = mean < 128.0 ? int(mean) + fill_offset : int(mean) - fill_offset;
  const auto fill_grey = uint8_t(std::clamp(fill, 0, 255));
  const cv::Mat a = objectCrop(previous, crop_was, fill_grey);
  const cv::Mat b = objectCrop(current, crop_now, fill_grey);
  dis.calc(a, b, out.flow_half);
  out.origin_half = crop_was.tl();
  out.shift_half = shift_half;
  return out;
}

cv::Point medianShiftHalf(const cv::Mat& flow_half, cv::Size image_size,
                          const std::vector<cv::Point2f>& pixels) {
  if (flow_half.empty()) return {0, 0};
  std::vector<float> dx, dy;
  for (const cv::Point2f& px : pixels) {
    cv::Point2f moved = px;
    if (!carryByFlow(flow_half, image_size, moved)) continue;
    dx.push_back(0.5f * (moved.x - px.x));
    dy.push_back(0.5f * (moved.y - px.y));
  }
  if (dx.empty()) return {0, 0};
  return {int(std::lround(medianInPlace(dx))), int(std::lround(medianInPlace(dy)))};
}

bool carryByCroppedFlow(const CroppedFlow& flow, cv::Size image_size, cv::Point2f& pixel) {
  if (flow.flow_half.empty()) return false;
  // Half-size pixel centres: (u + 0.5) / 2 - 0.5.
  const int xh = int(std::lround((pixel.x + 0.5f) * 0.5f - 0.5f)) - flow.origin_half.x;
  const int yh = int(std::lround((pixel.y + 0.5f) * 0.5f - 0.5f)) - flow.origin_half.y;
  if (xh < 0 || yh < 0 || xh >= flow.flow_half.cols || yh >= flow.flow_half.rows) return false;
  const cv::Point2f shift(float(flow.shift_half.x), float(flow.shift_half.y));
  pixel += 2.0f * (flow.flow_half.at<cv::Point2f>(yh, xh) + shift);
  return pixel.x >= 0.f && pixel.y >= 0.f && pixel.x <= float(image_size.width - 1) &&
         pixel.y <= float(image_size.height - 1);
}

}  // namespace dynanav
