// Instance-mask PNGs (readMaskPng), through OpenCV's PNG decoder.
#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "perception/mask_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "mask.png");
  static const std::map<uint16_t, std::string> classes = {{1, "person"}, {2, "box"}};
  try {
    (void)dynanav::readMaskPng(path, classes);
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
