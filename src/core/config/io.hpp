#pragma once
// Config section `io` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Reading sequences.
struct IoConfig {
  double max_association_dt_s = 0.02;  // colour/depth pairs further apart are not associated
  template <class V>
  void visit(V&& v) {
    v("max_association_dt_s", max_association_dt_s,
      "largest colour-depth timestamp gap accepted when associating (s), as TUM's associate.py",
      Range{0, 1, Range::kOpenLow});
  }
};

}  // namespace dynanav
