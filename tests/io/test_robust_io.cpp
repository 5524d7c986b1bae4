// Issue 16 at the io level: every write is checked (a full disk is an error, /dev/full stands
// in for it), truncated and empty images are refused, unusable frames are named, camera.yaml
// keys have ranges and unknown ones are refused, model files are checked by SHA-256.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "io/file_digest.hpp"
#include "io/image_file.hpp"
#include "io/json_io.hpp"
#include "io/text_lines.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

using test::errorOf;

std::vector<unsigned char> encode(const std::string& ext, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(ext, image, bytes));
  return bytes;
}

cv::Mat texture() {
  cv::Mat m(48, 64, CV_8UC3);
  cv::RNG(7).fill(m, cv::RNG::UNIFORM, 0, 256);
  return m;
}

TEST(RobustIo, FullDiskIsAnErrorNamingTheFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full not available";
  // The header line fits in the stream buffer; the flush after it fails.
  EXPECT_NE(errorOf([] { TrajectoryWriter w("/dev/full"); }).find("/dev/full"), std::string::npos);
  EXPECT_NE(errorOf([] { writeTextFile("/dev/full", "some text\n"); }).find("disk full"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              JsonLinesWriter w("/dev/full");
              w.write({{"a", 1}});
            }).find("/dev/full"),
            std::string::npos);
}

TEST(RobustIo, JsonFileIsReplacedOnlyWhenComplete) {
  const fs::path dir = test::scratchDir("json_atomic");
  writeJsonFile(dir / "stats.json", {{"run", 1}});
  EXPECT_EQ(readJsonFile(dir / "stats.json")["run"], 1);
  // A folder where the temp file would go: the write fails and the old file stays.
  fs::create_directories(dir / "stats.json.tmp");
  EXPECT_NE(errorOf([&] {
              writeJsonFile(dir / "stats.json", {{"run", 2}});
            }).find("stats.json"),
            std::string::npos);
  EXPECT_EQ(readJsonFile(dir / "stats.json")["run"], 1);
}

TEST(RobustIo, AJpegDeclaringAHugeFrameIsRefusedBeforeDecoding) {
  // fuzz_mask_png's finding: 173 bytes that made libjpeg ask for 4 GB.
  std::vector<unsigned char> jpg = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 0x08, 0xFF,
                                    0xFF, 0xFF, 0xFF, 0x01, 0x01, 0x11, 0x00};
  jpg.insert(jpg.end(), {0xFF, 0xD9});
  EXPECT_NE(imageBytesProblem(jpg).find("65535x65535"), std::string::npos);
  const std::vector<unsigned char> no_markers = {0xFF, 0xD8, 'N', 'G', 0x0D, 0x0A, 0xFF, 0xD9};
  EXPECT_NE(imageBytesProblem(no_markers).find("malformed JPEG"), std::string::npos);
}

TEST(RobustIo, TruncatedAndEmptyImagesAreRefused) {
  const auto png = encode(".png", texture());
  const auto jpg = encode(".jpg", texture());
  EXPECT_EQ(imageBytesProblem(png), "");
  EXPECT_EQ(imageBytesProblem(jpg), "");
  EXPECT_EQ(imageBytesProblem({}), "zero bytes");
  // Other formats never reach OpenCV's decoders (a DICOM named .png aborted inside GDCM).
  auto dicom = std::vector<unsigned char>(128, 0);
  dicom.insert(dicom.end(), {'D', 'I', 'C', 'M'});
  EXPECT_EQ(imageBytesProblem(dicom), "not a PNG or JPEG image");
  EXPECT_EQ(imageBytesProblem(encode(".bmp", texture())), "not a PNG or JPEG image");
  EXPECT_NE(imageBytesProblem({png.begin(), png.begin() + png.size() / 2}).find("truncated PNG"),
            std::string::npos);
  EXPECT_NE(
      imageBytesProblem({jpg.begin(), jpg.begin() + jpg.size() * 3 / 5}).find("truncated JPEG"),
      std::string::npos);
  // A JPEG with a few bytes after its end marker (some cameras pad) is complete.
  auto padded = jpg;
  padded.insert(padded.end(), {0, 0, 0, 0});
  EXPECT_EQ(imageBytesProblem(padded), "");

  const fs::path dir = test::scratchDir("truncated_images");
  std::ofstream(dir / "half.jpg", std::ios::binary)
      .write(reinterpret_cast<const char*>(jpg.data()), std::streamsize(jpg.size() / 2));
  std::ofstream(dir / "empty.png").close();
  EXPECT_NE(errorOf([&] {
              readImageFile(dir / "half.jpg", cv::IMREAD_COLOR, "colour image");
            }).find("half.jpg: colour image: truncated JPEG"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              readImageFile(dir / "empty.png", cv::IMREAD_COLOR, "colour image");
            }).find("zero bytes"),
            std::string::npos);
  EXPECT_NE(
      errorOf([&] { readImageFile(dir, cv::IMREAD_COLOR, "colour image"); }).find("not a file"),
      std::string::npos);
}

TEST(RobustIo, UnusableColourFramesAreNamed) {
  EXPECT_EQ(colourFrameProblem(texture()), "");
  EXPECT_EQ(colourFrameProblem(cv::Mat::zeros(48, 64, CV_8UC3)), "all black");
  EXPECT_EQ(colourFrameProblem(cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(255))),
            "saturated (all white)");
  EXPECT_NE(colourFrameProblem(cv::Mat(48, 64, CV_8UC3, cv::Scalar(90, 120, 30))).find("flat"),
            std::string::npos);
  // A dark but textured frame is kept.
  cv::Mat dark = texture() / 12;
  EXPECT_EQ(colourFrameProblem(dark), "");
}

TEST(RobustIo, CameraYamlRangesAndUnknownKeys) {
  const fs::path dir = test::scratchDir("camera_ranges");
  const std::string base = "width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\n";
  std::ofstream(dir / "ok.yaml") << base << "distortion: [0.1, -0.2, 0, 0, 0.01]\n";
  EXPECT_NO_THROW(loadCameraYaml(dir / "ok.yaml"));
  // Each case: a key's line replaced (or added when the base has no such key).
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"fx: .nan\n", "'fx'"},
      {"cy: .inf\n", "'cy'"},
      {"depth_factor: .inf\n", "'depth_factor'"},
      {"baseline_m: -1\n", "'baseline_m'"},
      {"rolling_shutter_readout_ms: -3\n", "'rolling_shutter"},
      {"k1: 0.1\n", "unknown key 'k1'"},
      {"distortion: [0, 0, 0]\n", "'distortion'"},
      {"distortion: [0, 0, 0, 0, 1e9]\n", "'distortion'"}};
  for (const auto& [extra, key] : bad) {
    std::string yaml = base;
    const std::string name = extra.substr(0, extra.find(':') + 1);
    if (const auto at = yaml.find(name); at != std::string::npos)
      yaml.erase(at, yaml.find('\n', at) - at + 1);
    std::ofstream(dir / "bad.yaml") << yaml << extra;
    const std::string what = errorOf([&] { loadCameraYaml(dir / "bad.yaml"); });
    EXPECT_NE(what.find(key), std::string::npos) << extra << " -> " << what;
    EXPECT_NE(what.find("bad.yaml"), std::string::npos) << what;
  }
}

TEST(RobustIo, TextReadersRefuseDevicesAndLoops) {
  const fs::path dir = test::scratchDir("text_devices");
  fs::create_symlink(dir / "b", dir / "a");
  fs::create_symlink(dir / "a", dir / "b");
  EXPECT_NE(errorOf([] { readContentLines("/dev/zero"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readContentLines(dir / "a"); }).find("symbolic links"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readTrajectory(dir); }).find("not a regular file"), std::string::npos);
}

TEST(RobustIo, Sha256OfKnownBytes) {
  const fs::path dir = test::scratchDir("sha");
  std::ofstream(dir / "abc.txt", std::ios::binary) << "abc";
  EXPECT_EQ(sha256Hex(dir / "abc.txt"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

}  // namespace
}  // namespace dynanav
