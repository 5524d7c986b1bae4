#pragma once
// Real-time wiring (DESIGN.md §1, data flow and threads): the source in its own thread delivers
// frames at their timestamps' pace, as a camera would, into a bounded queue that drops its oldest
// frame rather than block the newest when the system is behind; the calling thread runs the same
// System::process() as deterministic mode and feeds the sinks. Segmentation, local mapping and
// loop closing have their own threads inside System (asynchronous segmenter, mapping stage,
// global BA).
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

#include "pipeline/frame_source.hpp"
#include "pipeline/sinks.hpp"

namespace dynanav {

/// A step between the pipeline and the sinks (the audio stage stamps its messages' starts).
using BeforeSinks = std::function<void(FrameResult&)>;

struct RealtimeOptions {
  bool paced = true;        ///< false (--unpaced): deliver as fast as processed, nothing dropped
  size_t queue_frames = 2;  ///< frames that may wait for processing before the oldest is dropped
  /// The origin of FrameResult::arrival_s (shared with the audio stage's clock).
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  BeforeSinks before_sinks = {};  ///< runs on each result after arrival_s is set (may be empty)
};

/// The stage the frames go through (System::process in a run; a fake in tests).
using ProcessFrame = std::function<FrameResult(const RgbdFrame&)>;

/// Runs the whole source through `process` and the sinks; fills `summary` (dropped included).
/// FrameResult::arrival_s and latency_ms are set here: from the frame's delivery to its result.
void runRealtime(FrameSource& source, const ProcessFrame& process,
                 const std::vector<FrameSink*>& sinks, RunSummary& summary,
                 const RealtimeOptions& options);

}  // namespace dynanav
