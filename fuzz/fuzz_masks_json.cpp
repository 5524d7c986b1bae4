// SEQ_DIR/masks.json (readMaskClasses).
#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "perception/mask_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "masks.json");
  try {
    (void)dynanav::readMaskClasses(path);
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
