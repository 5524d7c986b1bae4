#include "pipeline/realtime_runner.hpp"

#include <chrono>
#include <exception>
#include <thread>

#include "core/interrupt.hpp"
#include "pipeline/frame_queue.hpp"

namespace dynanav {
namespace {
using Clock = std::chrono::steady_clock;

struct Arrival {
  RgbdFrame frame;
  Clock::time_point arrival;
};
}  // namespace

void runRealtime(FrameSource& source, const ProcessFrame& process,
                 const std::vector<FrameSink*>& sinks, RunSummary& summary,
                 const RealtimeOptions& options) {
  FrameQueue<Arrival> queue(options.queue_frames,
                            options.paced ? QueueFullPolicy::kDropOldest : QueueFullPolicy::kBlock);
  const Clock::time_point start = options.start;
  std::exception_ptr source_error;
  std::thread camera([&] {
    try {
      double first_stamp_s = -1.0;
      for (auto frame = source.next(); frame && !queue.closed() && !interruptRequested();
           frame = source.next()) {
        if (options.paced) {  // a camera delivers at its frame times, whatever we do
          if (first_stamp_s < 0) first_stamp_s = frame->stamp_s;
          std::this_thread::sleep_until(
              start + std::chrono::duration_cast<Clock::duration>(
                          std::chrono::duration<double>(frame->stamp_s - first_stamp_s)));
        }
        queue.push({std::move(*frame), Clock::now()});
      }
    } catch (...) {
      source_error = std::current_exception();
    }
    queue.close();
  });
  try {
    while (auto item = queue.pop()) {
      FrameResult result = process(item->frame);
      result.arrival_s = std::chrono::duration<double>(item->arrival - start).count();
      result.latency_ms =
          std::chrono::duration<double, std::milli>(Clock::now() - item->arrival).count();
      if (options.before_sinks) options.before_sinks(result);
      summary.add(result);
      for (FrameSink* sink : sinks) sink->consume(item->frame, result);
    }
  } catch (...) {
    queue.close();  // the camera thread ends at its next frame
    camera.join();
    throw;
  }
  camera.join();
  if (source_error) std::rethrow_exception(source_error);
  summary.dropped = queue.dropped();
}

}  // namespace dynanav
