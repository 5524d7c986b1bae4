#pragma once
// A 256-bit ORB descriptor as four 64-bit words: Hamming distances are four popcounts, and the
// k-majority centre of a cluster is a per-bit vote.
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>

namespace dynanav {

struct Descriptor256 {
  std::array<uint64_t, 4> words{};

  static Descriptor256 fromRow(const uchar* row) {
    Descriptor256 d;
    std::memcpy(d.words.data(), row, 32);
    return d;
  }
  void toRow(uchar* row) const { std::memcpy(row, words.data(), 32); }
  [[nodiscard]] bool bit(int i) const { return (words[i >> 6] >> (i & 63)) & 1u; }
  bool operator==(const Descriptor256&) const = default;
};

inline int hamming(const Descriptor256& a, const Descriptor256& b) {
  return std::popcount(a.words[0] ^ b.words[0]) + std::popcount(a.words[1] ^ b.words[1]) +
         std::popcount(a.words[2] ^ b.words[2]) + std::popcount(a.words[3] ^ b.words[3]);
}

}  // namespace dynanav
