#pragma once
// Config section `perception` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Segmentation and keypoints.
struct PerceptionConfig {
  template <class V> void visit(V&& /*v*/) {}
};

}  // namespace dynanav
