// Painting instance masks into one label image: occlusion order and depth-made masks.
#include <gtest/gtest.h>

#include "perception/segmenters.hpp"

using namespace dynanav;

namespace {

MaskedObject object(const std::string& cls, const std::string& source, cv::Rect box) {
  MaskedObject o;
  o.record.class_name = cls;
  o.record.mask_source = source;
  o.record.box = box;
  o.mask_in_box = cv::Mat(box.size(), CV_8U, cv::Scalar(255));
  return o;
}

TEST(PaintObjects, NearerPersonOccludesFartherPerson) {
  cv::Mat depth(100, 100, CV_32F, cv::Scalar(5.0f));
  depth(cv::Rect(10, 10, 40, 80)).setTo(3.0f);  // far person
  depth(cv::Rect(40, 10, 40, 80)).setTo(1.5f);  // near person, overlapping x 40..49
  const Instances out = paintObjects({object("person", "selfie", {40, 10, 40, 80}),
                                      object("person", "selfie", {10, 10, 40, 80})},
                                     depth, depth.size(), 0.05);
  ASSERT_EQ(out.items.size(), 2u);
  EXPECT_EQ(out.labels.at<uint16_t>(50, 45), 1);  // (row, col) in the overlap: the near one
  EXPECT_EQ(out.items[1].box, cv::Rect(10, 10, 30, 80));  // the far one lost the overlap
}

TEST(PaintObjects, ModelMaskWinsOverDepthMask) {
  // A chair's depth mask (nearer) overlaps a person's selfie mask: the person keeps its pixels.
  cv::Mat depth(100, 100, CV_32F, cv::Scalar(2.0f));
  depth(cv::Rect(50, 40, 40, 60)).setTo(1.8f);
  const Instances out = paintObjects({object("person", "selfie", {20, 10, 40, 90}),
                                      object("chair", "depth", {50, 40, 40, 60})},
                                     depth, depth.size(), 0.05);
  ASSERT_EQ(out.items.size(), 2u);
  EXPECT_EQ(out.labels.at<uint16_t>(60, 55), 1);
  EXPECT_EQ(out.area(1), 40 * 90);
  EXPECT_EQ(out.area(2), 40 * 60 - 10 * 60);
  // An object whose mask is fully covered disappears.
  const Instances covered = paintObjects({object("person", "selfie", {0, 0, 50, 50}),
                                          object("chair", "depth", {10, 10, 20, 20})},
                                         depth, depth.size(), 0.05);
  EXPECT_EQ(covered.items.size(), 1u);
}

}  // namespace
