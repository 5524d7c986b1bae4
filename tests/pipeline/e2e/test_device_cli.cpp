// `dynanav run openni://[URI]` and `dynanav run FILE.oni` without a camera: no device is exit 2
// with what was looked for; a missing recording is exit 2 naming it; an .oni recorded from
// OpenNI2's DummyDevice driver plays through the real OpenNI2 adapter to its end.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "bad_input_support.hpp"
#include "io/rgbd_device.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;
using test::runCliTimed;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(DeviceCli, NoDeviceIsExitTwoSayingWhatWasLookedFor) {
  const fs::path dir = test::scratchDir("device_none");
  const auto r = runCliTimed("run openni:// --out " + (dir / "out").string(), 60);
  if (r.code == 0 || contains(r.output, "device(s) enumerated"))
    GTEST_SKIP() << "an OpenNI2 device is attached here; this case is for machines without one:\n"
                 << r.output;
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "openni://")) << r.output;
  if (haveOpenNi2()) {
    EXPECT_TRUE(contains(r.output, "no OpenNI2 device could be opened")) << r.output;
    EXPECT_TRUE(contains(r.output, "drivers in")) << r.output;
    EXPECT_TRUE(contains(r.output, "no device enumerated")) << r.output;
  } else {
    EXPECT_TRUE(contains(r.output, "no OpenNI2 support")) << r.output;
  }
}

TEST(DeviceCli, UnknownDeviceUriIsExitTwoNamingIt) {
  const fs::path dir = test::scratchDir("device_uri");
  const auto r = runCliTimed("run openni://no/such@device --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "openni://no/such@device")) << r.output;
}

TEST(DeviceCli, MissingOniFileIsExitTwoNamingIt) {
  const fs::path dir = test::scratchDir("device_missing_oni");
  const std::string oni = (dir / "walk.oni").string();
  const auto r = runCliTimed("run " + oni + " --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, oni)) << r.output;
  EXPECT_TRUE(contains(r.output, "not found")) << r.output;
}

TEST(DeviceCli, PassesOnADeviceIsExitTwo) {
  const fs::path dir = test::scratchDir("device_passes");
  const auto r = runCliTimed("run openni:// --passes 2 --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--passes")) << r.output;
}

#ifdef DYNANAV_ONI_RECORDER
/// An .oni of at least `frames` frames from OpenNI2's DummyDevice (320x240, a ball on black).
fs::path dummyRecording(const fs::path& dir, int frames) {
  const fs::path oni = dir / "dummy.oni";
  const std::string cmd = "timeout 60 \"" DYNANAV_ONI_RECORDER "\" " + oni.string() + " " +
                          std::to_string(frames) + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return oni;
}

void writeCamera320(const fs::path& path) {
  test::writeText(path, "width: 320\nheight: 240\nfx: 285.0\nfy: 285.0\ncx: 159.5\ncy: 119.5\n");
}
#endif

TEST(DeviceCli, OniPlaybackReadsEveryRecordedFrameToTheEnd) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  const fs::path dir = test::scratchDir("device_oni");
  const fs::path oni = dummyRecording(dir, 12);
  writeCamera320(dir / "cam.yaml");
  // The dummy's frames are black but for a small ball: each is read, converted and then skipped
  // as all black, counted; the end of the recording ends the run (no hang, no crash).
  const auto r = runCliTimed("run " + oni.string() + " --camera " + (dir / "cam.yaml").string() +
                                 " --out " + (dir / "out").string(),
                             120);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "no frame could be read")) << r.output;
  EXPECT_TRUE(contains(r.output, "all black")) << r.output;
  EXPECT_TRUE(contains(r.output, "camera fx 285.0")) << r.output;
  EXPECT_TRUE(contains(r.output, "cam.yaml")) << r.output;
  const auto stats = nlohmann::json::parse(test::readFile(dir / "out" / "stats.json"));
  EXPECT_GE(stats["skipped_corrupt"].get<int>(), 10) << r.output;
  EXPECT_EQ(stats["frames"], 0);
  EXPECT_EQ(stats["source_failure"], "");
#endif
}

TEST(DeviceCli, OniWithoutFieldOfViewOrCalibrationAsksForCamera) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  const fs::path dir = test::scratchDir("device_oni_fov");
  const fs::path oni = dummyRecording(dir, 3);
  const auto r = runCliTimed("run " + oni.string() + " --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;  // the DummyDevice reports no field of view
  EXPECT_TRUE(contains(r.output, oni.string())) << r.output;
  EXPECT_TRUE(contains(r.output, "--camera")) << r.output;
  // A camera.yaml beside the recording is its calibration, as in a sequence folder.
  writeCamera320(dir / "camera.yaml");
  const auto beside = runCliTimed("run " + oni.string() + " --out " + (dir / "out").string(), 60);
  EXPECT_TRUE(contains(beside.output, (dir / "camera.yaml").string())) << beside.output;
  EXPECT_TRUE(contains(beside.output, "no frame could be read")) << beside.output;
#endif
}

}  // namespace
}  // namespace dynanav
