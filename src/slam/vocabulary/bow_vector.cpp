#include "slam/vocabulary/bow_vector.hpp"

#include <cmath>

namespace dynanav {

double l1Score(const BowVector& a, const BowVector& b) {
  double shared = 0.0;
  auto ia = a.entries.begin(), ib = b.entries.begin();
  while (ia != a.entries.end() && ib != b.entries.end()) {
    if (ia->first < ib->first) {
      ++ia;
    } else if (ib->first < ia->first) {
      ++ib;
    } else {
      const double va = ia->second, vb = ib->second;
      shared += std::abs(va) + std::abs(vb) - std::abs(va - vb);
      ++ia;
      ++ib;
    }
  }
  return 0.5 * shared;
}

int commonWords(const BowVector& a, const BowVector& b) {
  int n = 0;
  auto ia = a.entries.begin(), ib = b.entries.begin();
  while (ia != a.entries.end() && ib != b.entries.end()) {
    if (ia->first < ib->first) {
      ++ia;
    } else if (ib->first < ia->first) {
      ++ib;
    } else {
      ++n;
      ++ia;
      ++ib;
    }
  }
  return n;
}

}  // namespace dynanav
