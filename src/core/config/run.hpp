#pragma once
// Config section `run` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Whole-run behaviour (what the CLI flags override).
struct RunConfig {
  bool dynamic = true;
  bool deterministic = true;
  std::string segmenter = "auto";
  int segment_every = 1;
  bool realtime = false;
  bool paced = true;
  int queue_frames = 2;
  int realtime_opencv_threads = 1;
  int max_frames = 0;
  template <class V>
  void visit(V&& v) {
    v("dynamic", dynamic, "handle moving objects (false = plain ORB-SLAM2-style baseline)");
    v("deterministic", deterministic, "single thread, identical results run to run");
    v("segmenter", segmenter, "auto | dnn | hog | masks | none",
      OneOf{"auto", "dnn", "hog", "masks", "none"});
    v("segment_every", segment_every, "run the segmenter every k-th frame, propagate between",
      Range{1, 1000});
    v("realtime", realtime,
      "real-time threads: segmentation, local mapping, loop closing beside tracking (--realtime; "
      "not bit-reproducible)");
    v("paced", paced,
      "real time: frames arrive at their timestamps' pace, as from a camera (false = --unpaced)");
    v("queue_frames", queue_frames,
      "real time: frames that may wait for processing; when full the oldest is dropped (paced) or "
      "the source waits (unpaced)",
      Range{1, 1000});
    v("realtime_opencv_threads", realtime_opencv_threads,
      "real time: OpenCV's worker threads (1 = none: every stage runs single-threaded in its own "
      "thread, no pool threads compete with tracking; 0 = OpenCV's default)",
      Range{0, 256});
    v("max_frames", max_frames, "process at most this many frames (0 = all)", Range{0, 2147483647});
  }
};

}  // namespace dynanav
