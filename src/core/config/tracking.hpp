#pragma once
// Config section `tracking` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Camera-tracking thresholds.
struct TrackingConfig {
  double depth_max_m = 8.0;  // depths beyond this are treated as invalid
  template <class V> void visit(V&& v) {
    v("depth_max_m", depth_max_m, "depth samples beyond this distance (m) are ignored");
  }
};

}  // namespace dynanav
