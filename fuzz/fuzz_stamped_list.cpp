// rgb.txt / depth.txt lines (readStampedFileList) and their association.
#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "io/sequence.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "rgb.txt");
  try {
    const auto files = dynanav::readStampedFileList(path);
    (void)dynanav::associate(files, files, 0.02);
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
