#pragma once
// Config section `loop` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Place recognition, relocalisation and loop closing.
struct LoopConfig {
  std::string vocabulary;  // "" = $DYNANAV_VOCABULARY, then the file the build trained
  int direct_index_depth = 2;
  double min_common_words_ratio = 0.8;
  double min_accumulated_ratio = 0.75;
  bool relocalisation = true;
  bool loop_closing = true;
  int reloc_min_bow_matches = 15;
  int reloc_min_inliers = 50;
  int loop_min_keyframes = 10;
  int loop_consistency = 3;
  int loop_min_bow_matches = 20;
  int loop_min_ransac_inliers = 20;
  int loop_min_matches = 40;
  int essential_graph_min_weight = 100;
  int essential_graph_iterations = 20;
  bool global_ba = true;
  int global_ba_iterations = 10;
  template <class V>
  void visit(V&& v) {
    v("vocabulary", vocabulary,
      "ORB vocabulary file; empty: $DYNANAV_VOCABULARY, else "
      "<build>/share/dynanav/orb_vocabulary.dnvoc");
    v("direct_index_depth", direct_index_depth,
      "vocabulary depth whose nodes group features for guided matching (1 = root's children)",
      Range{1, 10});
    v("min_common_words_ratio", min_common_words_ratio,
      "place candidates share at least this fraction of the best candidate's shared words",
      Range{0, 1});
    v("min_accumulated_ratio", min_accumulated_ratio,
      "place candidates' covisibility-group score reaches this fraction of the best group's",
      Range{0, 1});
    v("relocalisation", relocalisation,
      "recover a lost camera by place recognition (needs the vocabulary)");
    v("loop_closing", loop_closing, "detect and close loops (needs the vocabulary)");
    v("reloc_min_bow_matches", reloc_min_bow_matches,
      "relocalisation: a candidate keyframe needs this many direct-index matches before EPnP",
      Range{1, 100000});
    v("reloc_min_inliers", reloc_min_inliers,
      "relocalisation: pose-optimisation inliers to accept a pose", Range{1, 100000});
    v("loop_min_keyframes", loop_min_keyframes,
      "no loop search while the map has fewer keyframes, nor within this many keyframes of the "
      "last loop",
      Range{1, 100000});
    v("loop_consistency", loop_consistency,
      "a loop candidate must be found again by this many consecutive keyframes (ORB-SLAM2: 3)",
      Range{1, 100});
    v("loop_min_bow_matches", loop_min_bow_matches,
      "loop: direct-index matches needed before the SE(3) RANSAC", Range{1, 100000});
    v("loop_min_ransac_inliers", loop_min_ransac_inliers, "loop: 3D-3D RANSAC inliers needed",
      Range{3, 100000});
    v("loop_min_matches", loop_min_matches,
      "loop: matches with the loop keyframe's covisible points after projection to accept the loop",
      Range{1, 100000});
    v("essential_graph_min_weight", essential_graph_min_weight,
      "covisibility edges with at least this many shared points enter the essential graph",
      Range{1, 100000});
    v("essential_graph_iterations", essential_graph_iterations,
      "Ceres iterations of the essential-graph optimisation", Range{1, 1000});
    v("global_ba", global_ba, "run a global bundle adjustment after a loop correction");
    v("global_ba_iterations", global_ba_iterations, "Ceres iterations per global BA pass",
      Range{1, 1000});
  }
};

}  // namespace dynanav
