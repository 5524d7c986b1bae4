#pragma once
// Real-time wiring (DESIGN.md §1, data flow and threads): the source in its own thread delivers
// frames at their timestamps' pace, as a camera would, into a bounded queue that drops its oldest
// frame rather than block the newest when the system is behind; the calling thread runs the same
// System::process() as deterministic mode and feeds the sinks. Segmentation, local mapping and
// loop closing have their own threads inside System (asynchronous segmenter, mapping stage,
// global BA).
#include <cstddef>
#include <vector>

#include "pipeline/frame_source.hpp"
#include "pipeline/sinks.hpp"
#include "pipeline/system.hpp"

namespace dynanav {

struct RealtimeOptions {
  bool paced = true;        ///< false (--unpaced): deliver as fast as processed, nothing dropped
  size_t queue_frames = 2;  ///< frames that may wait for processing before the oldest is dropped
};

/// Runs the whole source; fills `summary` (dropped included).
void runRealtime(FrameSource& source, System& system, const std::vector<FrameSink*>& sinks,
                 RunSummary& summary, const RealtimeOptions& options);

}  // namespace dynanav
