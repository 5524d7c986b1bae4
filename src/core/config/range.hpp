#pragma once
// Valid values of a config key, given as the optional 4th argument of a section's visit() line:
//   v("n_levels", n_levels, "pyramid levels", Range{1, 16});
//   v("scale_factor", scale_factor, "scale between levels", Range{1.0, 4.0, Range::kOpenLow});
//   v("segmenter", segmenter, "which segmenter", OneOf{"auto", "dnn", "none"});
// The loader rejects values outside it (NaN and infinity are never inside a Range), naming the
// file and key; the echo in config_used.yaml shows it after the doc. Keys without a constraint
// (paths, booleans, class lists) accept any value of their type.
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>

namespace dynanav {

/// A closed interval [lo, hi], or (lo, hi] with kOpenLow (e.g. a scale factor > 1).
struct Range {
  static constexpr bool kOpenLow = true;
  double lo;
  double hi;
  bool open_low = false;

  template <class T>
  [[nodiscard]] bool contains(const T& value) const {
    const double v = static_cast<double>(value);
    if (!std::isfinite(v)) return false;
    return (open_low ? v > lo : v >= lo) && v <= hi;
  }
  [[nodiscard]] std::string describe() const {
    std::ostringstream s;
    s << (open_low ? "(" : "[") << lo << ", " << hi << "]";
    return s.str();
  }
};

/// One of a fixed set of words.
/// The words live as long as the visit() call that names them (a temporary array).
struct OneOf {
  OneOf(std::initializer_list<const char*> w) : words(w) {}
  std::initializer_list<const char*> words;

  [[nodiscard]] bool contains(const std::string& value) const {
    for (const char* w : words)
      if (value == w) return true;
    return false;
  }
  [[nodiscard]] std::string describe() const {
    std::string s;
    for (const char* w : words) s += (s.empty() ? "" : " | ") + std::string(w);
    return s;
  }
};

/// No constraint: any value of the key's type.
struct AnyValue {
  template <class T>
  [[nodiscard]] bool contains(const T&) const {
    return true;
  }
  [[nodiscard]] std::string describe() const { return {}; }
};

}  // namespace dynanav
