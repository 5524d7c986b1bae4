#pragma once
// OUT/events.jsonl (DESIGN.md §2): one line per message the frame raised (FrameResult::events),
// flushed per line so an interrupted run keeps a valid file. Registered whenever object tracking
// is on, so a run that raised no message leaves an empty file (not a missing one). The audio stage
// fills audio_start_s before this sink sees a result.
#include <filesystem>

#include "io/events_jsonl.hpp"
#include "pipeline/sinks.hpp"

namespace dynanav {

class EventsSink final : public FrameSink {
 public:
  explicit EventsSink(const std::filesystem::path& out_dir) : writer_(out_dir / "events.jsonl") {}
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  EventsWriter writer_;
};

}  // namespace dynanav
