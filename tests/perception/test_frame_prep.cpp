#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "perception/frame_prep.hpp"

using namespace dynanav;

namespace {
constexpr int kWidth = 640, kHeight = 480;
const cv::Rect kBody(260, 120, 120, 240);  // a smooth-clothed walker, full-size pixels

/// Grey frame: a fine-textured still background and a smooth (heavily blurred) body shifted
/// `dx_px` to the right.
RgbdFrame frameWithBodyAt(double dx_px) {
  cv::Mat background(kHeight, kWidth, CV_8U), body(kHeight, kWidth, CV_8U);
  cv::theRNG().state = 11;
  cv::randu(background, 0, 255);
  cv::GaussianBlur(background, background, cv::Size(5, 5), 1.5);
  cv::randu(body, 0, 255);
  cv::GaussianBlur(body, body, cv::Size(0, 0), 12.0);
  cv::normalize(body, body, 60, 200, cv::NORM_MINMAX);
  const cv::Mat A = (cv::Mat_<double>(2, 3) << 1, 0, dx_px, 0, 1, 0);
  cv::Mat moved;
  cv::warpAffine(body, moved, A, body.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  const cv::Rect at = kBody + cv::Point(int(dx_px), 0);
  moved(at).copyTo(background(at));
  RgbdFrame frame;
  cv::cvtColor(background, frame.bgr, cv::COLOR_GRAY2BGR);
  frame.depth_m = cv::Mat(kHeight, kWidth, CV_32F, cv::Scalar(2.f));
  return frame;
}

/// Mean horizontal flow (full-size px) over the body's inner part when it moves `dx_px`.
double bodyShiftRead(int refinement_iterations, double dx_px) {
  FramePrep prep({.half = true,
                  .flow = true,
                  .flow_finest_scale = 1,
                  .flow_refinement_iterations = refinement_iterations});
  prep.prepare(frameWithBodyAt(0.0));
  const PreparedFrame out = prep.prepare(frameWithBodyAt(dx_px));
  const cv::Rect inner_half(kBody.x / 2 + 8, kBody.y / 2 + 8, kBody.width / 2 - 16,
                            kBody.height / 2 - 16);
  std::vector<cv::Mat> uv;
  cv::split(out.flow_half(inner_half), uv);
  return 2.0 * cv::mean(uv[0])[0];
}
}  // namespace

TEST(FramePrep, VariationalRefinementReadsASmoothBodysShiftMoreFully) {
  // The patch search alone under-reads a low-texture surface's motion (the tracker's speeds of
  // smoothly clothed walkers read low); objects.flow_refinement_iterations fills it in.
  const double shift_px = 8.0;
  const double error_without = std::abs(bodyShiftRead(0, shift_px) - shift_px);
  const double error_with = std::abs(bodyShiftRead(5, shift_px) - shift_px);
  // Measured: 0.29 px short without, 0.17 with (4-16 px shifts: 0.22-0.29 against 0.14-0.17).
  EXPECT_LT(error_with, 0.8 * error_without);
}
