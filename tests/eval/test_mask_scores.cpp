// Person-mask scoring against the simulator's ground truth (dynanav eval-masks).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "eval/mask_scores.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

cv::Mat labels(std::initializer_list<std::pair<cv::Rect, uint16_t>> boxes) {
  cv::Mat m(100, 100, CV_16U, cv::Scalar(0));
  for (const auto& [box, id] : boxes) m(box).setTo(id);
  return m;
}

TEST(MaskScores, BestIouIsExactAndIgnoresOtherClasses) {
  cv::Mat truth(100, 100, CV_8U, cv::Scalar(0));
  truth(cv::Rect(0, 0, 20, 10)).setTo(255);  // 200 px
  // Instance 2 covers the right half of the truth and 100 px outside: IoU = 100 / 300.
  const cv::Mat seg = labels(
      {{cv::Rect(10, 0, 20, 10), 2}, {cv::Rect(0, 0, 10, 10), 5}, {cv::Rect(50, 50, 5, 5), 3}});
  EXPECT_DOUBLE_EQ(bestPersonIou(truth, seg, {2, 3}), 100.0 / 300.0);
  EXPECT_DOUBLE_EQ(bestPersonIou(truth, seg, {5}), 0.5);  // 100 / 200
  EXPECT_DOUBLE_EQ(bestPersonIou(truth, seg, {3}), 0.0);  // no overlap
  EXPECT_DOUBLE_EQ(bestPersonIou(truth, seg, {}), 0.0);
}

/// A simulated folder with two frames and a segmentation folder; person 1 is 120 rows tall.
void writeFolders(const fs::path& sim, const fs::path& seg, double in_view_second) {
  fs::create_directories(sim / "masks");
  fs::create_directories(seg / "masks");
  std::ofstream(sim / "masks.json")
      << R"({"instances":{"1":{"class":"person"},"2":{"class":"box"}}})";
  std::ofstream(seg / "masks.json")
      << R"({"instances":{"1":{"class":"chair"},"4":{"class":"person"}}})";
  std::ofstream(sim / "objects_gt.jsonl")
      << R"({"t":0.0,"objects":[{"id":1,"class":"person","points":2400,"in_view":1.0},)"
      << R"({"id":2,"class":"box","points":100,"in_view":1.0}]})"
      << "\n"
      << R"({"t":0.033333,"objects":[{"id":1,"class":"person","points":2400,"in_view":)"
      << in_view_second << R"(},{"id":2,"class":"box","points":0,"in_view":0}]})"
      << "\n";
  cv::Mat truth(200, 200, CV_16U, cv::Scalar(0));
  truth(cv::Rect(10, 10, 20, 120)).setTo(1);
  truth(cv::Rect(100, 10, 10, 10)).setTo(2);
  cv::imwrite((sim / "masks/0.000000.png").string(), truth);
  cv::imwrite((sim / "masks/0.033333.png").string(), truth);
  // Frame 0: the person found exactly; frame 1: only a chair on it, the person elsewhere.
  cv::Mat found(200, 200, CV_16U, cv::Scalar(0));
  found(cv::Rect(10, 10, 20, 120)).setTo(4);
  cv::Mat missed(200, 200, CV_16U, cv::Scalar(0));
  missed(cv::Rect(10, 10, 20, 120)).setTo(1);
  missed(cv::Rect(150, 10, 20, 120)).setTo(4);
  cv::imwrite((seg / "masks/0.000000.png").string(), found);
  cv::imwrite((seg / "masks/0.033333.png").string(), missed);
}

TEST(MaskScores, ScoresPeopleInViewAndTallEnough) {
  const fs::path dir = test::scratchDir("mask_scores");
  writeFolders(dir / "sim", dir / "seg", 0.5);
  const MaskScoreSummary s = scorePersonMasks(dir / "sim", dir / "seg");
  EXPECT_EQ(s.frames, 2);
  ASSERT_EQ(s.scored.size(), 2u);  // the box is never scored
  EXPECT_EQ(s.scored[0].height_px, 120);
  EXPECT_DOUBLE_EQ(s.scored[0].iou, 1.0);
  EXPECT_DOUBLE_EQ(s.scored[1].iou, 0.0);  // a chair on the person does not count
  EXPECT_EQ(s.found, 1);
  EXPECT_DOUBLE_EQ(s.recall(), 0.5);
  EXPECT_DOUBLE_EQ(s.median_iou_found, 1.0);
  EXPECT_DOUBLE_EQ(s.median_iou_all, 0.5);

  // Under 30 % in view, or shorter than the height limit: not scored.
  writeFolders(dir / "sim", dir / "seg", 0.29);
  EXPECT_EQ(scorePersonMasks(dir / "sim", dir / "seg").scored.size(), 1u);
  MaskScoreOptions tall;
  tall.min_height_px = 121;
  EXPECT_TRUE(scorePersonMasks(dir / "sim", dir / "seg", tall).scored.empty());
}

TEST(MaskScores, MissingSegmentationFrameIsAnInputError) {
  const fs::path dir = test::scratchDir("mask_scores_missing");
  writeFolders(dir / "sim", dir / "seg", 1.0);
  fs::remove(dir / "seg/masks/0.033333.png");
  EXPECT_THROW(scorePersonMasks(dir / "sim", dir / "seg"), InputError);
}

}  // namespace
}  // namespace dynanav
