// Model files are checked at load (issue 16): empty files and known files whose SHA-256 is not
// a pinned one (truncated, corrupted, another version) are InputErrors naming the file.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "core/error.hpp"
#include "perception/model_files.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

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
