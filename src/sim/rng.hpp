#pragma once
// The simulator's random numbers: a small counter-free generator (SplitMix64) that is identical
// on every compiler and standard library, so a seed reproduces the same bytes everywhere
// (std::normal_distribution is implementation-defined). Seeded explicitly and passed in; never
// global.
#include <cmath>
#include <cstdint>

namespace dynanav::sim {

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}

  /// An independent stream for (seed, a, b, c), e.g. (seed, frame, row, purpose): the order in
  /// which threads consume streams then cannot change the output.
  static Rng stream(uint64_t seed, uint64_t a, uint64_t b = 0, uint64_t c = 0) {
    Rng r(seed);
    r.state_ ^= mix(a + 0x9E3779B97F4A7C15ULL);
    r.state_ ^= mix(b + 0xBF58476D1CE4E5B9ULL) * 3;
    r.state_ ^= mix(c + 0x94D049BB133111EBULL) * 5;
    r.next();
    return r;
  }

  uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    return mix(state_);
  }
  /// Uniform in [0, 1).
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [lo, hi] (inclusive); lo when the range is empty.
  int uniformInt(int lo, int hi) {
    return hi <= lo ? lo : lo + int(next() % uint64_t(hi - lo + 1));
  }
  bool chance(double p) { return uniform() < p; }
  /// Standard normal sample (Box–Muller; one of the pair is discarded for simplicity).
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  double normal(double mean, double sigma) { return mean + sigma * normal(); }

 private:
  static uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  uint64_t state_;
};

}  // namespace dynanav::sim
