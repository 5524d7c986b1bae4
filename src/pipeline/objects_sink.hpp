#pragma once
// OUT/objects.jsonl (DESIGN.md §2): one line per processed frame with its tracked objects
// (FrameResult::objects), flushed per line so an interrupted run keeps what it did.
#include <filesystem>

#include "io/objects_jsonl.hpp"
#include "pipeline/sinks.hpp"

namespace dynanav {

class ObjectsSink final : public FrameSink {
 public:
  explicit ObjectsSink(const std::filesystem::path& out_dir) : writer_(out_dir / "objects.jsonl") {}
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  ObjectsWriter writer_;
};

}  // namespace dynanav
