#pragma once
// Every tunable of dynanav, with its default and a one-line doc (STYLE.md habit 4).
// One struct per module. Each struct's visit() lists its fields once; the YAML loader, the
// unknown-key check and the echo of the effective config (config_used.yaml) all come from it.
// To add a tunable: add the member with its default and one `v(...)` line in visit().
#include <string>
#include <vector>

namespace dynanav {

/// Reading sequences.
struct IoConfig {
  double max_association_dt_s = 0.02;  // colour/depth pairs further apart are not associated
  template <class V> void visit(V&& v) {
    v("max_association_dt_s", max_association_dt_s,
      "largest colour-depth timestamp gap accepted when associating (s), as TUM's associate.py");
  }
};

/// ORB extraction (ORB-SLAM2 defaults for 640x480 RGB-D).
struct OrbConfig {
  int n_features = 1000;
  double scale_factor = 1.2;
  int n_levels = 8;
  int fast_threshold_initial = 20;
  int fast_threshold_min = 7;
  template <class V> void visit(V&& v) {
    v("n_features", n_features, "ORB features per frame");
    v("scale_factor", scale_factor, "scale between pyramid levels");
    v("n_levels", n_levels, "pyramid levels");
    v("fast_threshold_initial", fast_threshold_initial, "FAST threshold tried first in each cell");
    v("fast_threshold_min", fast_threshold_min, "FAST threshold when a cell yields nothing");
  }
};

/// Camera-tracking thresholds.
struct TrackingConfig {
  double depth_max_m = 8.0;  // depths beyond this are treated as invalid
  template <class V> void visit(V&& v) {
    v("depth_max_m", depth_max_m, "depth samples beyond this distance (m) are ignored");
  }
};

/// Local mapping.
struct MappingConfig {
  template <class V> void visit(V&& /*v*/) {}
};

/// Place recognition, relocalisation and loop closing.
struct LoopConfig {
  template <class V> void visit(V&& /*v*/) {}
};

/// Segmentation and keypoints.
struct PerceptionConfig {
  template <class V> void visit(V&& /*v*/) {}
};

/// Dynamic-object handling (paper's values as defaults).
struct DynamicsConfig {
  template <class V> void visit(V&& /*v*/) {}
};

/// Whole-run behaviour (what the CLI flags override).
struct RunConfig {
  bool dynamic = true;
  bool deterministic = true;
  std::string segmenter = "auto";
  int segment_every = 1;
  template <class V> void visit(V&& v) {
    v("dynamic", dynamic, "handle moving objects (false = plain ORB-SLAM2-style baseline)");
    v("deterministic", deterministic, "single thread, identical results run to run");
    v("segmenter", segmenter, "auto | dnn | hog | masks | none");
    v("segment_every", segment_every, "run the segmenter every k-th frame, propagate between");
  }
};

}  // namespace dynanav
