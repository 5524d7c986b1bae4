// Unit tests of viz/h264_file and the encoder chain of viz/video_writer (issue 15): the options
// reach x264 (OpenCV's writer dropped them), files play back frame for frame, a bad option falls
// back instead of writing nothing, and the same frames give the same bytes.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/config/outputs.hpp"
#include "core/error.hpp"
#include "support/test_support.hpp"
#include "viz/h264_file.hpp"
#include "viz/video_writer.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// A frame with structure (a gradient and a square that moves with I), so the encoder has work.
cv::Mat testFrame(cv::Size size, int i) {
  cv::Mat bgr(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(x * 255 / size.width), uchar(y * 255 / size.height),
                                          uchar((x + y + i) & 255));
  cv::rectangle(bgr, cv::Rect(10 + 3 * i, 20, 30, 30), cv::Scalar(0, 0, 255), cv::FILLED);
  return bgr;
}

struct ReadBack {
  int frames = 0;
  cv::Size size;
  std::string fourcc;
  double mean_abs_error = 0.0;  ///< against testFrame(size, i), over all frames and channels
};

ReadBack readBack(const fs::path& path) {
  ReadBack r;
  cv::VideoCapture read(path.string());
  if (!read.isOpened()) return r;
  const int tag = int(read.get(cv::CAP_PROP_FOURCC));
  r.fourcc = {char(tag & 255), char((tag >> 8) & 255), char((tag >> 16) & 255),
              char((tag >> 24) & 255)};
  double error = 0.0;
  for (cv::Mat f; read.read(f); ++r.frames) {
    r.size = f.size();
    const cv::Mat expected = testFrame(f.size(), r.frames);
    cv::Mat diff;
    cv::absdiff(f, expected, diff);
    const cv::Scalar m = cv::mean(diff);
    error += (m[0] + m[1] + m[2]) / 3;
  }
  r.mean_abs_error = r.frames ? error / r.frames : 0.0;
  return r;
}

std::string bytesOf(const fs::path& path) {
  return test::readFile(path);
}

TEST(EncoderOptions, ParsesCommaSeparatedKeyValuePairs) {
  const EncoderOptions o = parseEncoderOptions(" preset=ultrafast , threads=1,,crf = 28,");
  ASSERT_EQ(o.size(), 3u);
  EXPECT_EQ(o[0], std::make_pair(std::string("preset"), std::string("ultrafast")));
  EXPECT_EQ(o[1], std::make_pair(std::string("threads"), std::string("1")));
  EXPECT_EQ(o[2], std::make_pair(std::string("crf"), std::string("28")));
  // A value keeps its own '=' and ':' (x264-params is a list of its own).
  const EncoderOptions x = parseEncoderOptions("x264-params=keyint=60:bframes=0");
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(x[0].first, "x264-params");
  EXPECT_EQ(x[0].second, "keyint=60:bframes=0");
  EXPECT_TRUE(parseEncoderOptions("").empty());
  EXPECT_TRUE(parseEncoderOptions(" , ").empty());
}

TEST(EncoderOptions, RejectsAnItemWithoutNameOrValue) {
  EXPECT_THROW(parseEncoderOptions("preset"), std::invalid_argument);
  EXPECT_THROW(parseEncoderOptions("preset=fast,=1"), std::invalid_argument);
  // Through the config key, the error names it (the CLI exits with code 2).
  try {
    videoEncoderOptions("threads=1,ultrafast");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("outputs.video_encoder_options"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("ultrafast"), std::string::npos);
  }
}

TEST(H264File, TheOptionsReachX264AndTheFilePlaysFrameForFrame) {
  const fs::path path = test::scratchDir("h264_options") / "v.mp4";
  std::string why;
  auto file = H264File::open(path, {160, 120}, 30.0,
                             parseEncoderOptions("preset=ultrafast,threads=1,crf=18"), &why);
  ASSERT_TRUE(file) << why;
  EXPECT_EQ(file->encoderName(), "libx264");
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(file->write(testFrame({160, 120}, i)));
  file->close();
  // x264 writes its effective settings into the stream: ultrafast is subme=0 and no CABAC;
  // OpenCV's writer gave "cabac=1 ... subme=7 ... threads=3" whatever was asked.
  const std::string bytes = bytesOf(path);
  EXPECT_NE(bytes.find("cabac=0"), std::string::npos);
  EXPECT_NE(bytes.find("subme=0"), std::string::npos);
  EXPECT_NE(bytes.find(" threads=1 "), std::string::npos);
  EXPECT_NE(bytes.find("crf=18.0"), std::string::npos);
  const ReadBack r = readBack(path);
  EXPECT_EQ(r.fourcc, "avc1");
  EXPECT_EQ(r.frames, 20);
  EXPECT_EQ(r.size, cv::Size(160, 120));
  EXPECT_LT(r.mean_abs_error, 6.0);  // grey levels; a wrong colour order or offset is ~50+
}

TEST(H264File, SameFramesGiveTheSameBytes) {
  const fs::path dir = test::scratchDir("h264_same");
  for (const char* name : {"a.mp4", "b.mp4"}) {
    std::string why;
    auto file = H264File::open(dir / name, {96, 64}, 30.0,
                               parseEncoderOptions(OutputsConfig{}.video_encoder_options), &why);
    ASSERT_TRUE(file) << why;
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(file->write(testFrame({96, 64}, i)));
  }  // the destructor closes
  const std::string a = bytesOf(dir / "a.mp4");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, bytesOf(dir / "b.mp4"));
}

TEST(H264File, AnOddSizeLosesItsLastColumnAndRow) {
  const fs::path path = test::scratchDir("h264_odd") / "v.mp4";
  std::string why;
  auto file = H264File::open(path, {97, 65}, 25.0, {}, &why);
  ASSERT_TRUE(file) << why;
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(file->write(testFrame({97, 65}, i)));
  EXPECT_FALSE(file->write(testFrame({50, 40}, 0)));  // smaller than opened: refused
  file->close();
  const ReadBack r = readBack(path);
  EXPECT_EQ(r.frames, 5);
  EXPECT_EQ(r.size, cv::Size(96, 64));
}

TEST(H264File, AnOptionTheEncoderDoesNotKnowIsAnErrorNotIgnored) {
  const fs::path path = test::scratchDir("h264_unknown") / "v.mp4";
  std::string why;
  EXPECT_FALSE(H264File::open(path, {64, 48}, 30.0, parseEncoderOptions("presett=fast"), &why));
  EXPECT_NE(why.find("presett"), std::string::npos) << why;
  EXPECT_FALSE(H264File::open(path, {64, 48}, 30.0, parseEncoderOptions("preset=warp"), &why));
}

TEST(VideoOutput, WritesH264WithTheConfiguredOptions) {
  const auto dir = test::scratchDir("video");
  VideoOutput video(dir, "v", 30.0, videoEncoderOptions(OutputsConfig{}.video_encoder_options));
  for (int i = 0; i < 15; ++i) ASSERT_TRUE(video.write(testFrame({160, 120}, i)));
  video.write(testFrame({320, 240}, 15));  // a later size is resized to the first
  video.close();
  EXPECT_EQ(video.fourcc(), "avc1");
  EXPECT_EQ(video.path(), dir / "v.mp4");
  EXPECT_EQ(video.frames(), 16);
  const ReadBack r = readBack(video.path());
  EXPECT_EQ(r.fourcc, "avc1");
  EXPECT_EQ(r.frames, 16);
  EXPECT_NE(bytesOf(video.path()).find("subme=0"), std::string::npos);
}

TEST(VideoOutput, FallsBackToOpenCvsEncodersWhenH264DoesNotOpen) {
  const auto dir = test::scratchDir("video_fallback");
  VideoOutput video(dir, "v", 30.0, parseEncoderOptions("no-such-option=1"));
  for (int i = 0; i < 12; ++i) ASSERT_TRUE(video.write(testFrame({160, 120}, i)));
  video.close();
  ASSERT_FALSE(video.path().empty());
  EXPECT_NE(video.fourcc(), "avc1");
  std::printf("fall-back: fourcc %s -> %s\n", video.fourcc().c_str(),
              video.path().filename().c_str());
  EXPECT_EQ(readBack(video.path()).frames, 12);
}

}  // namespace
}  // namespace dynanav
