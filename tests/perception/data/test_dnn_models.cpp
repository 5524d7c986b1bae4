// The dnn segmenter and keypoints on Debian's opencv-doc photo basketball1.png (two people
// indoors, MODELS.md "Test images"), with the shared models. Skips when either is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "perception/box_models.hpp"
#include "perception/segmenters.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using namespace dynanav;

namespace {

const fs::path kBasketball = "/usr/share/doc/opencv-doc/examples/data/basketball1.png";

class DnnOnBasketball : public ::testing::Test {
 protected:
  void SetUp() override {
    models_ = test::sharedModels();
    if (models_.empty()) GTEST_SKIP() << "../shared/models not found: skipped";
    if (!fs::is_regular_file(kBasketball)) GTEST_SKIP() << kBasketball << " not found (opencv-doc): skipped";
    frame_.bgr = cv::imread(kBasketball.string());
    ASSERT_FALSE(frame_.bgr.empty());
  }
  fs::path models_;
  RgbdFrame frame_;
};

TEST_F(DnnOnBasketball, FindsBothPeople) {
  PerceptionConfig config;
  YoloDetector detector(models_, config);
  int people = 0;
  for (const Detection& d : detector.detect(frame_.bgr))
    if (d.class_name == "person" && d.score > 0.5f) ++people;
  EXPECT_EQ(people, 2);
}

TEST_F(DnnOnBasketball, MasksLieInsideTheirBoxesAndCoverThePeople) {
  PerceptionConfig config;
  DnnSegmenter segmenter(models_, config);
  const Instances instances = segmenter.segment(frame_);  // no depth: selfie masks only
  ASSERT_EQ(instances.labels.type(), CV_16U);
  ASSERT_EQ(instances.labels.size(), frame_.bgr.size());
  ASSERT_EQ(instances.count("person"), 2);
  for (const Instance& item : instances.items) {
    if (item.class_name != "person") continue;
    const cv::Mat mask = instances.mask(item.id);
    const int inside = cv::countNonZero(mask(item.box));
    EXPECT_EQ(inside, cv::countNonZero(mask)) << "mask pixels outside box of instance " << item.id;
    // A person fills a good part of their box (silhouette, not a speck).
    EXPECT_GT(inside, 0.25 * item.box.area()) << "instance " << item.id;
    EXPECT_EQ(item.mask_source, "selfie");
  }
}

TEST_F(DnnOnBasketball, ShouldersAboveHips) {
  PerceptionConfig config;
  YoloDetector detector(models_, config);
  KeypointDetector keypoints(models_, config);
  int checked = 0;
  for (const Detection& d : detector.detect(frame_.bgr)) {
    if (d.class_name != "person" || d.score < 0.5f) continue;
    const BodyKeypoints k = keypoints.detect(frame_.bgr, d.box);
    const float shoulders_y = 0.5f * (k.at(BodyPart::kLeftShoulder).pixel.y + k.at(BodyPart::kRightShoulder).pixel.y);
    const float hips_y = 0.5f * (k.at(BodyPart::kLeftHip).pixel.y + k.at(BodyPart::kRightHip).pixel.y);
    EXPECT_LT(shoulders_y, hips_y) << "box " << d.box;
    // Keypoints lie in (or very near) the person's box.
    const cv::Rect near_box(d.box.x - 10, d.box.y - 10, d.box.width + 20, d.box.height + 20);
    for (BodyPart p : {BodyPart::kLeftShoulder, BodyPart::kRightShoulder, BodyPart::kLeftHip, BodyPart::kRightHip}) {
      EXPECT_TRUE(near_box.contains(cv::Point(k.at(p).pixel))) << "keypoint " << int(p) << " at " << k.at(p).pixel;
      EXPECT_GT(k.at(p).score, 0.2f) << "keypoint " << int(p);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

}  // namespace
