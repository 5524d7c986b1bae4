#pragma once
// Config section `io` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Reading sequences.
struct IoConfig {
  double max_association_dt_s = 0.02;  // colour/depth pairs further apart are not associated
  template <class V>
  void visit(V&& v) {
    v("max_association_dt_s", max_association_dt_s,
      "largest colour-depth timestamp gap accepted when associating (s), as TUM's associate.py");
  }
};

}  // namespace dynanav
