// Model files are checked at load (issue 16): empty files and known files whose SHA-256 is not
// a pinned one (truncated, corrupted, another version) are InputErrors naming the file.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "core/error.hpp"
#include "perception/mask_files.hpp"
#include "perception/model_files.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

using test::errorOf;

TEST(ModelFileCheck, EmptyOrWrongChecksumIsRefused) {
  const fs::path dir = test::scratchDir("model_check");
  fs::create_directories(dir / "yolo-fastest");
  std::ofstream(dir / model_files::kDetectorWeights, std::ios::binary) << "not the weights";
  std::ofstream(dir / model_files::kCocoNames).close();
  std::ofstream(dir / "other.bin", std::ios::binary) << "any bytes";
  const std::string wrong = errorOf([&] { requireModelFile(dir, model_files::kDetectorWeights); });
  EXPECT_NE(wrong.find("yolo-fastest-1.1-xl.weights"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("SHA-256"), std::string::npos) << wrong;
  EXPECT_NE(errorOf([&] { requireModelFile(dir, model_files::kCocoNames); }).find("empty"),
            std::string::npos);
  EXPECT_NO_THROW(requireModelFile(dir, "other.bin"));  // no pinned checksum: size only
}

}  // namespace
}  // namespace dynanav

namespace dynanav {
namespace {

// fuzz_mask_png's finding: a DICOM header in a file named .png made cv::imread hand it to GDCM,
// which aborted the process. Now it is refused before any decoder sees it.
TEST(MaskFileCheck, NonPngBytesNamedPngAreRefusedNotDecoded) {
  const fs::path dir = test::scratchDir("dicom_png");
  std::string bytes = "\x89PNG\r\n\x1a/";
  bytes.resize(128, '\0');
  bytes += "DICM";
  bytes.resize(135, '\x35');
  std::ofstream(dir / "mask.png", std::ios::binary) << bytes;
  const std::string what = errorOf([&] { readMaskPng(dir / "mask.png", {}); });
  EXPECT_NE(what.find("mask.png"), std::string::npos) << what;
  EXPECT_NE(what.find("not a PNG or JPEG"), std::string::npos) << what;
}

}  // namespace
}  // namespace dynanav
