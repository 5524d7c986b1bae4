#include "slam/vocabulary/bow_vector.hpp"

#include <cmath>

namespace dynanav {

namespace {
/// Calls f(weight_a, weight_b) for every word both vectors contain (a merge walk over the two
/// word-sorted entry lists).
template <class F>
void forEachSharedWord(const BowVector& a, const BowVector& b, F&& f) {
  auto ia = a.entries.begin(), ib = b.entries.begin();
  while (ia != a.entries.end() && ib != b.entries.end()) {
    if (ia->first < ib->first) {
      ++ia;
    } else if (ib->first < ia->first) {
      ++ib;
    } else {
      f(double(ia->second), double(ib->second));
      ++ia;
      ++ib;
    }
  }
}
}  // namespace

double l1Score(const BowVector& a, const BowVector& b) {
  double shared = 0.0;
  forEachSharedWord(a, b, [&](double va, double vb) {
    shared += std::abs(va) + std::abs(vb) - std::abs(va - vb);
  });
  return 0.5 * shared;
}

int commonWords(const BowVector& a, const BowVector& b) {
  int n = 0;
  forEachSharedWord(a, b, [&](double, double) { ++n; });
  return n;
}

}  // namespace dynanav
