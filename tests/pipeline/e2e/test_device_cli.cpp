// `dynanav run openni://[URI]` and `dynanav run FILE.oni` without a camera: no device is exit 2
// with what was looked for; a missing recording is exit 2 naming it; an .oni recorded from
// OpenNI2's DummyDevice driver is opened by the real OpenNI2 adapter (modes, frame count, the
// calibration rules). Reading frames from it does not work yet (README, live cameras).
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
  // OpenNI2 2.2's Recorder now and then deadlocks in its own threads (seen here in about one
  // run of four): a stuck recording is killed and made again.
  const std::string cmd = "timeout -s KILL 10 \"" DYNANAV_ONI_RECORDER "\" " + oni.string() + " " +
                          std::to_string(frames) + " 2>&1";
  int status = -1;
  for (int attempt = 0; attempt < 6 && status != 0; ++attempt) status = std::system(cmd.c_str());
  EXPECT_EQ(status, 0) << cmd;
  return oni;
}

void writeCamera320(const fs::path& path) {
  test::writeText(path, "width: 320\nheight: 240\nfx: 285.0\nfy: 285.0\ncx: 159.5\ncy: 119.5\n");
}
#endif

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
  EXPECT_TRUE(contains(beside.output, "camera fx 285.0")) << beside.output;
  EXPECT_TRUE(contains(beside.output, (dir / "camera.yaml").string())) << beside.output;
  EXPECT_EQ(beside.code, 2) << beside.output;  // no frame read: see README, live cameras
#endif
}

}  // namespace
}  // namespace dynanav
