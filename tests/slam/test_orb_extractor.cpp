// ORB extraction: pyramid scales, the quadtree spread, orientation, descriptors, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "slam/orb_extractor.hpp"
#include "slam/orb_orientation.hpp"
#include "slam/orb_quadtree.hpp"
#include "test_orb_images.hpp"

namespace dynanav {
namespace {

using test::texturedImage;

TEST(OrbExtractor, LevelsAndScalesFollowTheConfig) {
  OrbExtractor extractor{OrbConfig{}};
  ASSERT_EQ(extractor.levels(), 8);
  ASSERT_EQ(extractor.scaleFactors().size(), 8u);
  EXPECT_FLOAT_EQ(extractor.scaleFactors()[0], 1.0f);
  int total = 0;
  for (int i = 0; i < 8; ++i) {
    const float s = static_cast<float>(std::pow(1.2, i));
    EXPECT_NEAR(extractor.scaleFactors()[i], s, 1e-5f * s);
    EXPECT_NEAR(extractor.invScaleFactors()[i], 1.0f / s, 1e-6f);
    EXPECT_NEAR(extractor.levelSigma2()[i], s * s, 1e-4f * s * s);
    EXPECT_NEAR(extractor.invLevelSigma2()[i] * extractor.levelSigma2()[i], 1.0f, 1e-6f);
    if (i > 0 && i < 7) {
      EXPECT_LT(extractor.featuresPerLevel()[i], extractor.featuresPerLevel()[i - 1]);
    }
    total += extractor.featuresPerLevel()[i];
  }
  EXPECT_EQ(total, 1000);
  EXPECT_NEAR(extractor.featuresPerLevel()[0], 217, 1);  // 1000 * (1 - 1/1.2) / (1 - 1.2^-8)
}

TEST(OrbExtractor, QuadtreeSpreadsFeaturesOverTheImage) {
  const cv::Mat image = texturedImage(640, 480, 7);
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor.extract(image, keypoints, descriptors);
  EXPECT_GE(keypoints.size(), 950u);
  EXPECT_LE(keypoints.size(), 1000u);
  ASSERT_EQ(descriptors.rows, static_cast<int>(keypoints.size()));
  EXPECT_EQ(descriptors.cols, 32);
  EXPECT_EQ(descriptors.type(), CV_8U);

  int grid[4][4] = {};
  std::vector<int> per_level(8, 0);
  int last_level = 0;
  for (const auto& kp : keypoints) {
    ASSERT_GE(kp.pt.x, 0.0f);
    ASSERT_GE(kp.pt.y, 0.0f);
    ASSERT_LT(kp.pt.x, 640.0f);
    ASSERT_LT(kp.pt.y, 480.0f);
    ASSERT_GE(kp.octave, last_level) << "keypoints are ordered by level";
    last_level = kp.octave;
    ++grid[static_cast<int>(kp.pt.y / 120)][static_cast<int>(kp.pt.x / 160)];
    ++per_level[kp.octave];
    EXPECT_GE(kp.angle, 0.0f);
    EXPECT_LT(kp.angle, 360.0f);
    EXPECT_NEAR(kp.size, 31.0f * extractor.scaleFactors()[kp.octave], 1e-3f);
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      // Uniform would be 1000/16 = 62; a clustered detector leaves cells nearly empty.
      EXPECT_GE(grid[r][c], 30) << "cell " << r << "," << c;
      EXPECT_LE(grid[r][c], 110) << "cell " << r << "," << c;
    }
  for (int l = 0; l < 8; ++l) EXPECT_GE(per_level[l], extractor.featuresPerLevel()[l] * 8 / 10);
}

TEST(OrbExtractor, QuadtreeTakesTheStrongestPerRegionNotTheDensestRegion) {
  // 900 strong corners packed in one corner, 100 weak ones spread over a grid.
  std::vector<cv::KeyPoint> candidates;
  for (int i = 0; i < 900; ++i)
    candidates.emplace_back(cv::Point2f(static_cast<float>(i % 30), static_cast<float>(i / 30)), 7.f, -1.f,
                            100.0f + static_cast<float>(i % 7));
  for (int i = 0; i < 100; ++i)
    candidates.emplace_back(cv::Point2f(50.0f + 60.0f * static_cast<float>(i % 10),
                                        50.0f + 40.0f * static_cast<float>(i / 10)),
                            7.f, -1.f, 10.0f);
  const auto kept = distributeQuadtree(candidates, 0, 640, 0, 480, 200);
  EXPECT_LE(kept.size(), 200u);
  EXPECT_GE(kept.size(), 190u);
  const auto weak = std::count_if(kept.begin(), kept.end(), [](const cv::KeyPoint& k) { return k.response < 50; });
  EXPECT_GE(weak, 90) << "the sparse region must not be starved";
  EXPECT_TRUE(distributeQuadtree({}, 0, 640, 0, 480, 10).empty());
  // A wide region gets several side-by-side roots; every third of it still gets its share.
  std::vector<cv::KeyPoint> wide;
  for (int i = 0; i < 3000; ++i)
    wide.emplace_back(cv::Point2f(static_cast<float>((i * 37) % 1200), static_cast<float>((i * 53) % 400)),
                      7.f, -1.f, static_cast<float>(i % 11));
  const auto spread = distributeQuadtree(wide, 0, 1200, 0, 400, 300);
  EXPECT_GE(spread.size(), 290u);
  EXPECT_LE(spread.size(), 300u);
  int thirds[3] = {};
  for (const auto& k : spread) ++thirds[static_cast<int>(k.pt.x / 400)];
  for (int t : thirds) EXPECT_GE(t, 80);
  // Identical coordinates cannot be separated: the loop must still end.
  std::vector<cv::KeyPoint> same(50, cv::KeyPoint(cv::Point2f(10, 10), 7.f, -1.f, 1.f));
  EXPECT_EQ(distributeQuadtree(same, 0, 640, 0, 480, 10).size(), 1u);
}

double angleDifference(double a, double b) {
  double d = std::fmod(a - b + 540.0, 360.0) - 180.0;
  return d;
}

TEST(OrbOrientation, AngleRotatesWithThePatch) {
  // Smooth random intensities: a clear, off-centre intensity centroid.
  cv::Mat noise(101, 101, CV_32F), image;
  cv::RNG(3).fill(noise, cv::RNG::UNIFORM, 0.0, 255.0);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 6.0);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  noise.convertTo(image, CV_8U);
  const auto disc = orientationDisc(15);
  ASSERT_EQ(disc.size(), 16u);
  EXPECT_EQ(disc[0], 15);
  EXPECT_EQ(disc[15], 3);  // 3^2 + 15^2 <= 240 < 4^2 + 15^2
  const cv::Point center(50, 50);
  const float angle = intensityCentroidAngle(image, center, disc);

  // A 90-degree turn clockwise on screen (y down) adds 90 degrees, exactly: the disc is symmetric.
  cv::Mat turned;
  cv::rotate(image, turned, cv::ROTATE_90_CLOCKWISE);
  EXPECT_NEAR(angleDifference(intensityCentroidAngle(turned, center, disc), angle), 90.0, 0.5);

  // Any angle: warpAffine turns counter-clockwise on screen for positive angles.
  for (double degrees : {25.0, 60.0, 135.0, -40.0}) {
    cv::Mat warped;
    cv::warpAffine(image, warped, cv::getRotationMatrix2D(cv::Point2f(50, 50), degrees, 1.0),
                   image.size(), cv::INTER_LINEAR);
    EXPECT_NEAR(angleDifference(intensityCentroidAngle(warped, center, disc), angle), -degrees, 4.0)
        << degrees;
  }
}

TEST(OrbExtractor, DescriptorsAreDeterministicAndRotationInvariant) {
  const cv::Mat image = texturedImage(640, 480, 11);
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps_a, kps_b;
  cv::Mat desc_a, desc_b;
  extractor.extract(image, kps_a, desc_a);
  extractor.extract(image.clone(), kps_b, desc_b);
  ASSERT_EQ(kps_a.size(), kps_b.size());
  for (size_t i = 0; i < kps_a.size(); ++i) {
    EXPECT_EQ(kps_a[i].pt, kps_b[i].pt);
    EXPECT_EQ(kps_a[i].angle, kps_b[i].angle);
    EXPECT_EQ(descriptorDistance(desc_a.row(static_cast<int>(i)), desc_b.row(static_cast<int>(i))), 0);
  }

  // State kept between calls (pyramid, scratch) must not leak into the next frame, whatever its size.
  std::vector<cv::KeyPoint> kps_other;
  cv::Mat desc_other, desc_again;
  extractor.extract(texturedImage(320, 240, 12), kps_other, desc_other);
  extractor.extract(image, kps_b, desc_again);
  EXPECT_EQ(cv::norm(desc_a, desc_again, cv::NORM_HAMMING), 0.0);
  OrbExtractor fresh{OrbConfig{}};
  fresh.extract(image, kps_b, desc_again);
  EXPECT_EQ(cv::norm(desc_a, desc_again, cv::NORM_HAMMING), 0.0);

  // The same scene turned by 90 degrees: level-0 corners reappear at the turned position with the
  // angle advanced by 90 degrees and (nearly) the same descriptor.
  cv::Mat turned;
  cv::rotate(image, turned, cv::ROTATE_90_CLOCKWISE);
  std::vector<cv::KeyPoint> kps_t;
  cv::Mat desc_t;
  extractor.extract(turned, kps_t, desc_t);
  int matched = 0, close = 0;
  for (size_t i = 0; i < kps_a.size(); ++i) {
    if (kps_a[i].octave != 0) continue;
    const cv::Point2f expected(479.0f - kps_a[i].pt.y, kps_a[i].pt.x);
    for (size_t j = 0; j < kps_t.size(); ++j) {
      if (kps_t[j].octave != 0 || cv::norm(kps_t[j].pt - expected) > 0.5) continue;
      ++matched;
      EXPECT_NEAR(angleDifference(kps_t[j].angle, kps_a[i].angle), 90.0, 1.0);
      if (descriptorDistance(desc_a.row(static_cast<int>(i)), desc_t.row(static_cast<int>(j))) <= 30) ++close;
    }
  }
  EXPECT_GE(matched, 50);
  EXPECT_GE(close, matched * 8 / 10);
}

TEST(OrbExtractor, MaskKeepsFeaturesOutAndTheBudgetInTheRest) {
  const cv::Mat image = texturedImage(640, 480, 21);
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(255));
  mask(cv::Rect(0, 0, 320, 480)).setTo(0);      // a person filling the left half
  mask(cv::Rect(400, 100, 100, 100)).setTo(0);  // and something else
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps, unmasked;
  cv::Mat desc, desc_unmasked;
  extractor.extract(image, mask, kps, desc);
  EXPECT_GE(kps.size(), 900u) << "the budget moves to the allowed half";
  EXPECT_EQ(desc.rows, static_cast<int>(kps.size()));
  for (const auto& kp : kps) {
    // Nearest-neighbour masks per level: allow the level's pixel size in level-0 pixels.
    const float slack = extractor.scaleFactors()[kp.octave];
    ASSERT_GE(kp.pt.x, 320.0f - slack);
    ASSERT_FALSE(kp.pt.x > 400 + slack && kp.pt.x < 500 - slack && kp.pt.y > 100 + slack && kp.pt.y < 200 - slack)
        << kp.pt;
  }
  // The mask is per call: the next call without one covers the whole image again.
  extractor.extract(image, unmasked, desc_unmasked);
  EXPECT_GT(std::count_if(unmasked.begin(), unmasked.end(), [](const cv::KeyPoint& k) { return k.pt.x < 300; }), 300);
  EXPECT_THROW(extractor.extract(image, cv::Mat(10, 10, CV_8UC1), kps, desc), std::invalid_argument);
}

TEST(OrbExtractor, DescriptorDistanceCountsBits) {
  cv::Mat a = cv::Mat::zeros(1, 32, CV_8U), b = cv::Mat::zeros(1, 32, CV_8U);
  EXPECT_EQ(descriptorDistance(a, b), 0);
  b.at<uchar>(0, 0) = 0xFF;
  b.at<uchar>(0, 31) = 0x01;
  EXPECT_EQ(descriptorDistance(a, b), 9);
  cv::Mat rows(3, 32, CV_8U, cv::Scalar(0xFF));
  EXPECT_EQ(descriptorDistance(rows.row(1), a), 256);
}

TEST(OrbExtractor, FlatImageGivesNoFeaturesAndTinyImagesDoNotCrash) {
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps;
  cv::Mat desc;
  extractor.extract(cv::Mat(480, 640, CV_8UC1, cv::Scalar(90)), kps, desc);
  EXPECT_TRUE(kps.empty());
  EXPECT_EQ(desc.rows, 0);
  extractor.extract(texturedImage(40, 30, 1), kps, desc);
  EXPECT_EQ(desc.rows, static_cast<int>(kps.size()));
  EXPECT_THROW(extractor.extract(cv::Mat(10, 10, CV_32F), kps, desc), std::invalid_argument);
}

}  // namespace
}  // namespace dynanav
