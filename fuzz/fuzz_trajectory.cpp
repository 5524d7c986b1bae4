// TUM trajectories: groundtruth.txt and dynanav's own trajectory.txt (readTrajectory).
#include "core/error.hpp"
#include "fuzz/fuzz_input.hpp"
#include "io/trajectory.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = dynanav::fuzz::writeInput(data, size, "groundtruth.txt");
  try {
    for (const auto& pose : dynanav::readTrajectory(path)) (void)dynanav::formatTumLine(pose);
  } catch (const dynanav::InputError&) {
  }
  return 0;
}
