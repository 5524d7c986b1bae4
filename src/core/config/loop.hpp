#pragma once
// Config section `loop` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc") line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Place recognition, relocalisation and loop closing.
struct LoopConfig {
  std::string vocabulary;  // "" = $DYNANAV_VOCABULARY, then the file the build trained
  int direct_index_depth = 2;
  double min_common_words_ratio = 0.8;
  double min_accumulated_ratio = 0.75;
  template <class V> void visit(V&& v) {
    v("vocabulary", vocabulary,
      "ORB vocabulary file; empty: $DYNANAV_VOCABULARY, else <build>/share/dynanav/orb_vocabulary.dnvoc");
    v("direct_index_depth", direct_index_depth,
      "vocabulary depth whose nodes group features for guided matching (1 = root's children)");
    v("min_common_words_ratio", min_common_words_ratio,
      "place candidates share at least this fraction of the best candidate's shared words");
    v("min_accumulated_ratio", min_accumulated_ratio,
      "place candidates' covisibility-group score reaches this fraction of the best group's");
  }
};

}  // namespace dynanav
