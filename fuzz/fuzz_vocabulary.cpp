// The ORB vocabulary file (Vocabulary::load, docs/orb_vocabulary.md); a vocabulary that loads
// must transform descriptors without going out of bounds.
#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "slam/vocabulary/vocabulary.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "vocabulary.dnvoc");
  try {
    const dynanav::Vocabulary vocabulary = dynanav::Vocabulary::load(path.string());
    cv::Mat descriptors(4, 32, CV_8U);
    cv::randu(descriptors, 0, 256);
    dynanav::BowVector bow;
    vocabulary.transform(descriptors, bow, nullptr, 2);
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
