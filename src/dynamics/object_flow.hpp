#pragma once
// One object's own optical flow: the shared dense flow (FramePrep) averages each point with the
// image content its patches cover, and beside a walker that is mostly the background, which
// moves with the camera: it under-read a side-on walker's image motion by about a quarter
// (docs/tracking.md "Session 33"). Here every pixel outside the object's mask, in both frames,
// is set to one flat grey before DIS runs on a crop around it, so the patches see only the
// object's own texture and its outline, which move with it.
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>
#include <vector>

namespace dynanav {

/// The object in one frame: half-size grey image, full-size labels and its label there, and
/// full-size depth with the depth nearer than which a surface hides it.
struct ObjectView {
  const cv::Mat& grey_half;  ///< CV_8U, half size
  const cv::Mat& labels;     ///< CV_16U, full size
  uint16_t label = 0;
  const cv::Mat& depth_m;  ///< CV_32F, full size (empty: none)
  double nearer_than_m = 0.0;
};

/// A flow field over part of the half-size image: half-size pixel (x + origin_half.x,
/// y + origin_half.y) of the previous frame moved by flow_half(y, x) + shift_half.
struct CroppedFlow {
  cv::Mat flow_half;  ///< CV_32FC2, half-size pixels; empty when not computed
  cv::Point origin_half;
  cv::Point shift_half;  ///< where the current frame's crop lies against the previous one's
};

/// The flow of the object from `previous` to `current`. The previous frame's crop is `box`
/// (full-size pixels, grown by `margin_px` on each side); the current frame's is the same crop
/// moved by `shift_half` (half-size pixels: where the object roughly went, so that DIS's pyramid
/// on a small crop need only find the rest: a head turning at 150 degrees/s moves the image
/// 40 px per frame at half size, beyond what a crop's few levels reach); both clipped to the
/// image. Both crops have every pixel off the object's mask set to a grey `fill_offset` away from
/// the object's mean brightness in the previous frame (so its outline shows), then `dis` (its
/// settings are the caller's) runs on them. A surface nearer than the object (depth below
/// nearer_than_m) keeps its own image: it truly hides the object there, and the edge it makes
/// moves as it does, not as the object's outline (a flat grey there made an outline that stood
/// still while the object came out from behind it). Empty when the object is narrower than one
/// of DIS's patches in either crop (or absent), or the crop is smaller than a patch at DIS's
/// finest level.
CroppedFlow objectFlow(const ObjectView& previous, const ObjectView& current, cv::Rect box,
                       cv::Point shift_half, int margin_px, int fill_offset,
                       cv::DISOpticalFlow& dis);

/// The half-size crop `crop_half` of `view` as objectFlow gives it to DIS: every pixel that is
/// neither the object's nor a nearer surface's set to `fill` (a half-size pixel is judged by
/// the full-size pixel at its top-left).
cv::Mat objectCrop(const ObjectView& view, cv::Rect crop_half, uint8_t fill);

/// The median motion of `pixels` (full size) along the shared half-size flow, rounded to whole
/// half-size pixels ((0, 0) without flow or without a pixel it carries).
cv::Point medianShiftHalf(const cv::Mat& flow_half, cv::Size image_size,
                          const std::vector<cv::Point2f>& pixels);

/// Where `pixel` (full size) of the previous frame is in this one, by `flow` (as carryByFlow
/// does with the whole half-size field); false when it lies outside the crop or the image.
bool carryByCroppedFlow(const CroppedFlow& flow, cv::Size image_size, cv::Point2f& pixel);

}  // namespace dynanav
