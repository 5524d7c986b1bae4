// Listing and reading training images: folders, videos sampled every n-th frame, even thinning.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "core/error.hpp"
#include "slam/vocabulary/training_images.hpp"
#include "support/test_support.hpp"
#include "test_orb_images.hpp"

namespace dynanav {
namespace {

TEST(TrainingImages, FoldersVideosAndThinning) {
  const auto dir = test::scratchDir("training_images");
  cv::imwrite((dir / "b.png").string(), test::texturedImage(320, 240, 1));
  cv::imwrite((dir / "a.jpg").string(), test::texturedImage(1280, 960, 2));  // scaled to 640x480
  std::ofstream(dir / "notes.txt") << "ignored";
  const auto video_path = (dir / "clip.avi").string();
  {
    cv::VideoWriter video(video_path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(320, 240), false);
    if (!video.isOpened()) GTEST_SKIP() << "this OpenCV cannot write MJPG avi";
    for (int f = 0; f < 10; ++f) video.write(test::texturedImage(320, 240, 10 + f));
  }
  const auto listed = listTrainingImages({dir.string()}, 3);
  ASSERT_EQ(listed.size(), 6u);  // a.jpg, b.png, clip.avi frames 0, 3, 6, 9 (sorted by path)
  EXPECT_EQ(listed[0].path.filename(), "a.jpg");
  EXPECT_EQ(listed[1].path.filename(), "b.png");
  EXPECT_EQ(listed[2].frame, 0);
  EXPECT_EQ(listed[5].frame, 9);
  EXPECT_EQ(listed[5].label(), video_path + "#9");

  std::vector<cv::Size> sizes;
  const size_t used = forEachTrainingImage(listed, [&](const cv::Mat& gray, const TrainingImage&) {
    EXPECT_EQ(gray.type(), CV_8UC1);
    sizes.push_back(gray.size());
  });
  EXPECT_EQ(used, 6u);
  ASSERT_EQ(sizes.size(), 6u);
  EXPECT_EQ(sizes[0], cv::Size(640, 480));
  EXPECT_EQ(sizes[1], cv::Size(320, 240));
  EXPECT_EQ(sizes[4], cv::Size(320, 240));

  const auto thin = thinEvenly(listed, 3);
  ASSERT_EQ(thin.size(), 3u);
  EXPECT_EQ(thin[0].label(), listed[0].label());
  EXPECT_EQ(thin[1].label(), listed[2].label());
  EXPECT_EQ(thin[2].label(), listed[4].label());
  EXPECT_EQ(thinEvenly(listed, 0).size(), 6u);

  EXPECT_THROW(listTrainingImages({(dir / "missing").string()}, 1), InputError);
  EXPECT_THROW(listTrainingImages({(dir / "notes.txt").string()}, 1), InputError);
}

}  // namespace
}  // namespace dynanav
