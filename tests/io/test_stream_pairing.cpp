// The colour/depth pairing rule of device streams (io/stream_pairing.hpp), without a device.
#include <gtest/gtest.h>

#include "io/stream_pairing.hpp"

namespace dynanav {
namespace {

TEST(StreamPairing, ToleranceIsHalfAFramePeriod) {
  EXPECT_EQ(pairingToleranceUs(30.0), 16666);
  EXPECT_EQ(pairingToleranceUs(25.0), 20000);
  EXPECT_EQ(pairingToleranceUs(0.0), 500000);  // an unknown rate counts as 1 frame/s
}

TEST(StreamPairing, SameOrCloseTimestampsPair) {
  EXPECT_EQ(pairStep(66000, 66000, 30.0), PairStep::kPair);
  EXPECT_EQ(pairStep(66000 + 16666, 66000, 30.0), PairStep::kPair);
  EXPECT_EQ(pairStep(66000, 66000 + 16666, 30.0), PairStep::kPair);
}

TEST(StreamPairing, TheOlderFrameWithoutPartnerIsDropped) {
  // Depth lost its frame at 33 ms: colour 33 ms waits against depth 66 ms and must go.
  EXPECT_EQ(pairStep(33000, 66000, 30.0), PairStep::kDropColour);
  EXPECT_EQ(pairStep(66000, 33000, 30.0), PairStep::kDropDepth);
  EXPECT_EQ(pairStep(66000 + 16667, 66000, 30.0), PairStep::kDropDepth);
}

TEST(StreamPairing, AStreamThatLostFramesResynchronises) {
  // Colour at every 33 ms; depth lost frames 1 and 2. Applying the rule as the adapter does
  // pairs 0-0 and 3-3 and drops colour 1 and 2.
  const std::vector<uint64_t> colour = {0, 33000, 66000, 99000};
  const std::vector<uint64_t> depth = {0, 99000};
  size_t c = 0, d = 0;
  std::vector<std::pair<uint64_t, uint64_t>> pairs;
  int colour_dropped = 0;
  while (c < colour.size() && d < depth.size()) {
    switch (pairStep(colour[c], depth[d], 30.0)) {
      case PairStep::kPair:
        pairs.emplace_back(colour[c++], depth[d++]);
        break;
      case PairStep::kDropColour:
        ++c, ++colour_dropped;
        break;
      case PairStep::kDropDepth:
        ++d;
        break;
    }
  }
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[1], std::make_pair(uint64_t(99000), uint64_t(99000)));
  EXPECT_EQ(colour_dropped, 2);
}

}  // namespace
}  // namespace dynanav
