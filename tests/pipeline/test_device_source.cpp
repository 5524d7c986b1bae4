// The device source's contract with a fake RgbdDevice (no camera needed): frames in order,
// timestamps from the device converted to seconds and strictly increasing, depth in metres,
// registration and sync asked for, the end of a recording ends the frames, bad frames counted,
// a device error reported (failure()) instead of thrown, and where the intrinsics come from.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "pipeline/device_source.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

/// What the fake device does on each read().
struct Step {
  uint64_t colour_stamp_us = 0;
  uint16_t depth_raw = 1500;
  bool black = false;
  bool fail = false;  ///< throw DeviceError instead of a frame
};

/// Frames of textured noise (so no bad-frame check refuses them) with a constant raw depth.
class FakeDevice final : public RgbdDevice {
 public:
  FakeDevice(RgbdDeviceInfo info, std::vector<Step> steps)
      : info_(std::move(info)), steps_(std::move(steps)) {}
  [[nodiscard]] const RgbdDeviceInfo& info() const override { return info_; }
  std::optional<RawRgbdFrame> read() override {
    if (next_ >= steps_.size()) return std::nullopt;  // the end of the recording
    const Step& step = steps_[next_++];
    if (step.fail) throw DeviceError("openni://fake: the device was unplugged");
    RawRgbdFrame frame;
    frame.bgr = cv::Mat(info_.height, info_.width, CV_8UC3);
    cv::RNG rng(next_);
    rng.fill(frame.bgr, cv::RNG::UNIFORM, 0, 256);
    if (step.black) frame.bgr.setTo(cv::Scalar::all(0));
    frame.depth_raw = cv::Mat(info_.height, info_.width, CV_16U, cv::Scalar(step.depth_raw));
    frame.colour_stamp_us = step.colour_stamp_us;
    frame.depth_stamp_us = step.colour_stamp_us + 1000;
    return frame;
  }

 private:
  RgbdDeviceInfo info_;
  std::vector<Step> steps_;
  size_t next_ = 0;
};

RgbdDeviceInfo fakeInfo(int recorded_frames = 0) {
  RgbdDeviceInfo info;
  info.uri = "fake";
  info.name = "Fake RGB-D";
  info.is_file = recorded_frames > 0;
  info.frames = recorded_frames;
  info.width = 64;
  info.height = 48;
  info.fps = 30;
  info.horizontal_fov_rad = 1.0225;  // 58.6°, a PrimeSense colour camera
  info.vertical_fov_rad = 0.7946;
  info.depth_unit_m = 0.001;
  return info;
}

/// A source over a fake device; `request` receives what the source asked the device for.
DeviceSource makeSource(RgbdDeviceInfo info, std::vector<Step> steps,
                        DeviceSourceOptions options = {}, RgbdDeviceRequest* request = nullptr) {
  return DeviceSource(options, [&](const RgbdDeviceRequest& asked) {
    if (request) *request = asked;
    return std::make_unique<FakeDevice>(info, steps);
  });
}

std::vector<Step> steadySteps(int n) {
  std::vector<Step> steps;
  for (int i = 0; i < n; ++i) steps.push_back({uint64_t(5'000'000 + 33'333 * i)});
  return steps;
}

TEST(DeviceSource, AsksForRegisteredAndSyncedDepth) {
  RgbdDeviceRequest asked;
  asked.register_depth_to_colour = false;
  asked.sync_depth_and_colour = false;
  DeviceSourceOptions options;
  options.request = deviceRequestFor("openni://1d27/0601@2/3");
  makeSource(fakeInfo(), steadySteps(1), options, &asked);
  EXPECT_TRUE(asked.register_depth_to_colour);
  EXPECT_TRUE(asked.sync_depth_and_colour);
  EXPECT_FALSE(asked.is_file);
  EXPECT_EQ(asked.uri, "1d27/0601@2/3");
}

TEST(DeviceSource, FramesInOrderWithDeviceTimeInSecondsAndDepthInMetres) {
  DeviceSource source = makeSource(fakeInfo(), steadySteps(5));
  double last_stamp_s = -1.0;
  for (int i = 0; i < 5; ++i) {
    auto frame = source.next();
    ASSERT_TRUE(frame) << i;
    EXPECT_EQ(frame->index, i);
    EXPECT_DOUBLE_EQ(frame->stamp_s, 5.0 + 0.033333 * i);
    EXPECT_DOUBLE_EQ(frame->depth_stamp_s, frame->stamp_s + 0.001);
    EXPECT_GT(frame->stamp_s, last_stamp_s);
    last_stamp_s = frame->stamp_s;
    ASSERT_EQ(frame->depth_m.type(), CV_32F);
    EXPECT_FLOAT_EQ(frame->depth_m.at<float>(10, 10), 1.5f);  // 1500 mm
    EXPECT_EQ(frame->bgr.size(), cv::Size(64, 48));
  }
  EXPECT_FALSE(source.next());
  EXPECT_EQ(source.skipped(), 0);
  EXPECT_EQ(source.failure(), "");
}

TEST(DeviceSource, DepthUnitOfTheDeviceIsHonoured) {
  RgbdDeviceInfo info = fakeInfo();
  info.depth_unit_m = 0.0001;  // OpenNI2 DEPTH_100_UM
  DeviceSource source = makeSource(info, steadySteps(1));
  auto frame = source.next();
  ASSERT_TRUE(frame);
  EXPECT_FLOAT_EQ(frame->depth_m.at<float>(0, 0), 0.15f);
  EXPECT_DOUBLE_EQ(source.camera().depth_factor, 10000.0);
}

TEST(DeviceSource, TimestampThatDoesNotAdvanceIsSkippedAndCounted) {
  std::vector<Step> steps = steadySteps(4);
  steps[2].colour_stamp_us = steps[1].colour_stamp_us;      // repeated
  steps[3].colour_stamp_us = steps[0].colour_stamp_us - 1;  // went back
  steps.push_back({steps[1].colour_stamp_us + 66'666});
  DeviceSource source = makeSource(fakeInfo(), steps);
  std::vector<int> indices;
  for (auto f = source.next(); f; f = source.next()) indices.push_back(f->index);
  EXPECT_EQ(indices, (std::vector<int>{0, 1, 4}));
  EXPECT_EQ(source.skipped(), 2);
}

TEST(DeviceSource, BadFramesAreSkippedAndCounted) {
  std::vector<Step> steps = steadySteps(4);
  steps[1].black = true;
  steps[2].depth_raw = 0;  // no valid depth
  DeviceSource source = makeSource(fakeInfo(), steps);
  std::vector<int> indices;
  for (auto f = source.next(); f; f = source.next()) indices.push_back(f->index);
  EXPECT_EQ(indices, (std::vector<int>{0, 3}));
  EXPECT_EQ(source.skipped(), 2);
}

TEST(DeviceSource, EndOfRecordingEndsTheFrames) {
  DeviceSource source = makeSource(fakeInfo(3), steadySteps(3));
  EXPECT_EQ(source.expected(), 3u);
  int n = 0;
  while (source.next()) ++n;
  EXPECT_EQ(n, 3);
  EXPECT_FALSE(source.next());  // and stays ended
  EXPECT_EQ(source.failure(), "");
}

TEST(DeviceSource, MaxFramesStopsALiveDevice) {
  DeviceSourceOptions options;
  options.max_frames = 2;
  DeviceSource source = makeSource(fakeInfo(), steadySteps(10), options);
  EXPECT_EQ(source.expected(), 2u);
  int n = 0;
  while (source.next()) ++n;
  EXPECT_EQ(n, 2);
}

TEST(DeviceSource, DeviceErrorIsReportedNotThrown) {
  std::vector<Step> steps = steadySteps(3);
  steps[2].fail = true;
  DeviceSource source = makeSource(fakeInfo(), steps);
  EXPECT_TRUE(source.next());
  EXPECT_TRUE(source.next());
  std::optional<RgbdFrame> after;
  EXPECT_NO_THROW(after = source.next());
  EXPECT_FALSE(after);
  EXPECT_NE(source.failure().find("unplugged"), std::string::npos) << source.failure();
}

TEST(DeviceSource, IntrinsicsFromTheFieldOfViewWhenNoCalibrationIsGiven) {
  DeviceSource source = makeSource(fakeInfo(), steadySteps(1));
  const PinholeCamera& camera = source.camera();
  EXPECT_NEAR(camera.fx, 32.0 / std::tan(0.5 * 1.0225), 1e-9);
  EXPECT_NEAR(camera.fy, 24.0 / std::tan(0.5 * 0.7946), 1e-9);
  EXPECT_DOUBLE_EQ(camera.cx, 31.5);
  EXPECT_DOUBLE_EQ(camera.cy, 23.5);
  EXPECT_NE(source.cameraSource().find("field of view"), std::string::npos);
}

TEST(DeviceSource, GivenCalibrationWinsAndMustFitTheDevice) {
  DeviceSourceOptions options;
  options.camera = PinholeCamera{};
  options.camera->width = 64;
  options.camera->height = 48;
  options.camera->fx = 50.0;
  options.camera_origin = "my/camera.yaml";
  DeviceSource source = makeSource(fakeInfo(), steadySteps(1), options);
  EXPECT_DOUBLE_EQ(source.camera().fx, 50.0);
  EXPECT_EQ(source.cameraSource(), "my/camera.yaml");

  options.camera->width = 640;
  try {
    makeSource(fakeInfo(), steadySteps(1), options);
    FAIL() << "a 640-wide calibration for a 64-wide device was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("my/camera.yaml"), std::string::npos) << e.what();
  }
}

TEST(DeviceSource, NoFieldOfViewAndNoCalibrationAsksForOne) {
  RgbdDeviceInfo info = fakeInfo();
  info.horizontal_fov_rad = info.vertical_fov_rad = 0.0;  // OpenNI2's DummyDevice reports none
  try {
    makeSource(info, steadySteps(1));
    FAIL() << "a device without field of view gave intrinsics";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--camera"), std::string::npos) << e.what();
  }
}

TEST(DeviceInput, SchemeAndOniFilesAreDevicesFoldersAreNot) {
  EXPECT_TRUE(isDeviceInput("openni://"));
  EXPECT_TRUE(isDeviceInput("openni://1d27/0601@2/3"));
  EXPECT_TRUE(isDeviceInput("walk.oni"));
  EXPECT_TRUE(isDeviceInput("/data/WALK.ONI"));
  EXPECT_FALSE(isDeviceInput("../shared/data/rgbd_bonn_crowd"));
  EXPECT_FALSE(isDeviceInput("openni"));
  EXPECT_TRUE(deviceRequestFor("openni://").uri.empty());
}

TEST(DeviceInput, MissingOrSpecialOniFileIsAnInputErrorNamingIt) {
  const fs::path dir = fs::temp_directory_path() / ("dynanav_oni_" + std::to_string(getpid()));
  fs::create_directories(dir / "folder.oni");
  for (const fs::path& bad : {dir / "missing.oni", dir / "folder.oni"}) {
    try {
      (void)deviceRequestFor(bad.string());
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
  }
  std::ofstream(dir / "walk.oni") << "x";
  const RgbdDeviceRequest request = deviceRequestFor((dir / "walk.oni").string());
  EXPECT_TRUE(request.is_file);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace dynanav
