// `dynanav run openni://[URI]` and `dynanav run FILE.oni` without a camera: no device is exit 2
// with what was looked for; a missing recording is exit 2 naming it; an .oni recorded by
// OpenNI2 from its DummyDevice driver is played by the real OpenNI2 adapter: every recorded
// frame, in order, with its recorded timestamp, the same run to run (and the calibration
// rules); a recording OpenNI2 2.2 cannot play is exit 2 saying why.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

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
/// A recording made with OpenNI2's own Recorder from its DummyDevice driver (320x240, 30
/// frames/s), at least `frames` frames of each stream; `extra` = "--as-recorded" keeps it as
/// OpenNI2 wrote it (no cropping property, colour a ball on black; see the fixture). Returns
/// the file and the number of colour/depth pairs it holds (the smaller stream's count).
std::pair<fs::path, int> dummyRecording(const fs::path& dir, int frames,
                                        const std::string& extra = "") {
  const fs::path oni = dir / "dummy.oni";
  const std::string cmd = "timeout -s KILL 20 \"" DYNANAV_ONI_RECORDER "\" " + oni.string() + " " +
                          std::to_string(frames) + " " + extra;
  std::string printed;
  int status = -1;
  if (FILE* pipe = popen(cmd.c_str(), "r")) {
    std::array<char, 256> line{};
    while (fgets(line.data(), int(line.size()), pipe)) printed += line.data();
    status = pclose(pipe);
  }
  EXPECT_EQ(status, 0) << cmd << "\n" << printed;
  int pairs = -1;  // "node ID: N frames", one line per stream
  std::istringstream lines(printed);
  for (std::string line; std::getline(lines, line);) {
    const auto colon = line.find(": ");
    if (line.rfind("node ", 0) != 0 || colon == std::string::npos) continue;
    const int n = std::stoi(line.substr(colon + 2));
    pairs = pairs < 0 ? n : std::min(pairs, n);
  }
  EXPECT_GE(pairs, frames) << printed;
  return {oni, pairs};
}

void writeCamera320(const fs::path& path) {
  test::writeText(path, "width: 320\nheight: 240\nfx: 285.0\nfy: 285.0\ncx: 159.5\ncy: 119.5\n");
}

nlohmann::json statsOf(const fs::path& out) {
  return nlohmann::json::parse(test::readFile(out / "stats.json"));
}

/// The "t" of every objects.jsonl line: one line per processed frame.
std::vector<double> frameStamps(const fs::path& out) {
  std::vector<double> stamps;
  std::istringstream lines(test::readFile(out / "objects.jsonl"));
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) stamps.push_back(nlohmann::json::parse(line).at("t").get<double>());
  return stamps;
}
#endif

TEST(DeviceCli, OniWithoutFieldOfViewOrCalibrationAsksForCamera) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  const fs::path dir = test::scratchDir("device_oni_fov");
  const fs::path oni = dummyRecording(dir, 3).first;
  const auto r = runCliTimed("run " + oni.string() + " --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;  // the DummyDevice reports no field of view
  EXPECT_TRUE(contains(r.output, oni.string())) << r.output;
  EXPECT_TRUE(contains(r.output, "--camera")) << r.output;
  // A camera.yaml beside the recording is its calibration, as in a sequence folder.
  writeCamera320(dir / "camera.yaml");
  const auto beside = runCliTimed("run " + oni.string() + " --out " + (dir / "out").string(), 60);
  EXPECT_TRUE(contains(beside.output, "camera fx 285.0")) << beside.output;
  EXPECT_TRUE(contains(beside.output, (dir / "camera.yaml").string())) << beside.output;
  EXPECT_GT(statsOf(dir / "out").at("frames").get<int>(), 0) << beside.output;
#endif
}

TEST(DeviceCli, OniPlaybackDeliversEveryRecordedFrameInOrder) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  const fs::path dir = test::scratchDir("device_oni_play");
  const auto [oni, pairs] = dummyRecording(dir, 15);
  writeCamera320(dir / "camera.yaml");
  const fs::path out = dir / "out";
  const auto r = runCliTimed("run " + oni.string() + " --out " + out.string(), 120);
  // The DummyDevice's depth is a ball and one row at 2 m: every frame is read, but there are
  // too few depth points for tracking to start (exit 3, outputs written).
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_TRUE(contains(r.output, std::to_string(pairs) + " frames recorded")) << r.output;
  const nlohmann::json stats = statsOf(out);
  EXPECT_EQ(stats.at("frames").get<int>(), pairs) << r.output;
  EXPECT_EQ(stats.at("skipped_corrupt").get<int>(), 0) << r.output;
  EXPECT_EQ(stats.at("source_failure").get<std::string>(), "") << r.output;
  // The recorder stores each stream's time from its first frame; the DummyDevice stamps a
  // frame every 33 ms, so frame k is at exactly k * 0.033 s.
  const std::vector<double> stamps = frameStamps(out);
  ASSERT_EQ(int(stamps.size()), pairs);
  for (int k = 0; k < pairs; ++k) EXPECT_NEAR(stamps[size_t(k)], 0.033 * k, 1e-9) << k;
  // Deterministic: a second run gives the same frames, byte for byte.
  const fs::path again = dir / "again";
  const auto r2 = runCliTimed("run " + oni.string() + " --out " + again.string(), 120);
  EXPECT_EQ(r2.code, r.code) << r2.output;
  EXPECT_EQ(test::readFile(again / "objects.jsonl"), test::readFile(out / "objects.jsonl"));
#endif
}

TEST(DeviceCli, OniRealtimePlaybackOffersEveryRecordedFrame) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  const fs::path dir = test::scratchDir("device_oni_realtime");
  const auto [oni, pairs] = dummyRecording(dir, 15);
  writeCamera320(dir / "camera.yaml");
  const fs::path out = dir / "out";
  const auto r = runCliTimed("run " + oni.string() + " --realtime --out " + out.string(), 120);
  EXPECT_EQ(r.code, 3) << r.output;
  // Paced at the recorded rate by the real-time runner: a frame is processed or dropped (a
  // slow machine), never lost in the source.
  const nlohmann::json stats = statsOf(out);
  EXPECT_EQ(stats.at("frames").get<int>() + stats.at("dropped").get<int>(), pairs) << r.output;
#endif
}

TEST(DeviceCli, OniWithoutCroppingPropertyIsExitTwoSayingWhy) {
#ifndef DYNANAV_ONI_RECORDER
  GTEST_SKIP() << "built without OpenNI2: no recording can be made";
#else
  // As OpenNI2 records the DummyDevice: no xnCropping, which OpenNI2 2.2's player needs to
  // deliver any frame. Said at open, instead of a wait that times out.
  const fs::path dir = test::scratchDir("device_oni_no_cropping");
  const fs::path oni = dummyRecording(dir, 3, "--as-recorded").first;
  writeCamera320(dir / "camera.yaml");
  const auto r = runCliTimed("run " + oni.string() + " --out " + (dir / "out").string(), 60);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, oni.string())) << r.output;
  EXPECT_TRUE(contains(r.output, "no cropping property")) << r.output;
#endif
}

}  // namespace
}  // namespace dynanav
