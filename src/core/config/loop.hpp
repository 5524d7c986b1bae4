#pragma once
// Config section `loop` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Place recognition, relocalisation and loop closing.
struct LoopConfig {
  template <class V> void visit(V&& /*v*/) {}
};

}  // namespace dynanav
