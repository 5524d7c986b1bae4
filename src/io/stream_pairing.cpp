#include "io/stream_pairing.hpp"

#include <algorithm>
#include <cstdlib>

namespace dynanav {

int64_t pairingToleranceUs(double fps) {
  return static_cast<int64_t>(0.5e6 / std::max(1.0, fps));
}

PairStep pairStep(uint64_t colour_stamp_us, uint64_t depth_stamp_us, double fps) {
  const int64_t gap = int64_t(colour_stamp_us) - int64_t(depth_stamp_us);
  if (std::abs(gap) <= pairingToleranceUs(fps)) return PairStep::kPair;
  // Each stream's frames come in time order, so the older frame can only pair with a frame
  // of the other stream that is older still, and those have gone.
  return gap < 0 ? PairStep::kDropColour : PairStep::kDropDepth;
}

}  // namespace dynanav
