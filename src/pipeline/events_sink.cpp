#include "pipeline/events_sink.hpp"

namespace dynanav {

void EventsSink::consume(const RgbdFrame& /*frame*/, const FrameResult& result) {
  for (const FeedbackEvent& event : result.events) writer_.write(event);
}

void EventsSink::finish(const RunEnd& /*end*/) {}

}  // namespace dynanav
