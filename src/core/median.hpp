#pragma once
// The median the per-frame statistics use: the middle element found by partial sorting, no
// averaging of the two middle values for an even count (the upper one is taken), so a median of
// measurements is always one of them.
#include <algorithm>
#include <vector>

namespace dynanav {

/// The element that sorting would put at index size/2 (the upper median for an even count).
/// Reorders `values`; they must not be empty.
template <class T>
T medianInPlace(std::vector<T>& values) {
  const auto mid = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// medianInPlace of a copy, for callers that keep their order.
template <class T>
T medianOf(std::vector<T> values) {
  return medianInPlace(values);
}

}  // namespace dynanav
