#pragma once
// Colour and depth frames of an RGB-D device arrive on two streams (OpenNI2: one holder per
// stream, frames in the order the driver or the recording hands them over). This is the rule
// that pairs them, kept apart from OpenNI2 so it is tested without a device: the oldest frame
// of each stream pairs when their timestamps are within half a frame period; otherwise the
// older one has no partner (the other stream lost its frame) and is dropped.
#include <cstdint>

namespace dynanav {

enum class PairStep {
  kPair,        ///< the two oldest frames belong together
  kDropColour,  ///< the oldest colour frame is older than any depth frame still to come
  kDropDepth,   ///< the same for depth
};

/// Largest |colour - depth| timestamp difference (µs) of a pair at `fps` frames per second:
/// half a frame period (fps below 1 counts as 1).
int64_t pairingToleranceUs(double fps);

/// What to do with the oldest waiting colour and depth frames (timestamps in µs of one clock).
PairStep pairStep(uint64_t colour_stamp_us, uint64_t depth_stamp_us, double fps);

}  // namespace dynanav
