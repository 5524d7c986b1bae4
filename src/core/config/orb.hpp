#pragma once
// Config section `orb` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// ORB extraction (ORB-SLAM2 defaults for 640x480 RGB-D).
struct OrbConfig {
  int n_features = 1000;
  double scale_factor = 1.2;
  int n_levels = 8;
  int fast_threshold_initial = 20;
  int fast_threshold_min = 7;
  template <class V>
  void visit(V&& v) {
    v("n_features", n_features, "ORB features per frame", Range{1, 20000});
    v("scale_factor", scale_factor, "scale between pyramid levels", Range{1, 4, Range::kOpenLow});
    v("n_levels", n_levels, "pyramid levels", Range{1, 16});
    v("fast_threshold_initial", fast_threshold_initial, "FAST threshold tried first in each cell",
      Range{1, 254});
    v("fast_threshold_min", fast_threshold_min, "FAST threshold when a cell yields nothing",
      Range{1, 254});
  }
};

}  // namespace dynanav
