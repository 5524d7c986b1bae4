#include "pipeline/objects_sink.hpp"

namespace dynanav {

void ObjectsSink::consume(const RgbdFrame& /*frame*/, const FrameResult& result) {
  writer_.write(result.stamp_s, result.objects);
}

void ObjectsSink::finish(const RunEnd& /*end*/) {}

}  // namespace dynanav
