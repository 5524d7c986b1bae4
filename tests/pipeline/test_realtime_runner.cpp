// The real-time wiring with a fake camera and a fake stage: the queue drops the oldest frame
// and counts it when the stage is slow, never blocks the camera, and drops nothing unpaced.
#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <thread>

#include "pipeline/frame_queue.hpp"
#include "pipeline/realtime_runner.hpp"

namespace dynanav {
namespace {

using namespace std::chrono_literals;

/// Frames at `fps` with tiny images; records when each was handed out.
class FakeCamera final : public FrameSource {
 public:
  FakeCamera(int frames, double fps) : frames_(frames), fps_(fps) {}
  std::optional<RgbdFrame> next() override {
    if (next_ >= frames_) return std::nullopt;
    RgbdFrame f;
    f.index = next_;
    f.stamp_s = 100.0 + next_ / fps_;
    f.bgr = cv::Mat::zeros(4, 4, CV_8UC3);
    f.depth_m = cv::Mat::zeros(4, 4, CV_32F);
    ++next_;
    return f;
  }
  [[nodiscard]] size_t expected() const override { return size_t(frames_); }
  [[nodiscard]] int skipped() const override { return 0; }
  [[nodiscard]] const PinholeCamera& camera() const override { return camera_; }
  [[nodiscard]] std::string describe() const override { return "fake"; }

 private:
  int frames_;
  double fps_;
  int next_ = 0;
  PinholeCamera camera_;
};

/// Remembers the indices it saw.
class IndexSink final : public FrameSink {
 public:
  void consume(const RgbdFrame& frame, const FrameResult& result) override {
    indices.push_back(frame.index);
    latency_ms.push_back(result.latency_ms);
  }
  void finish(const RunEnd&) override {}
  std::vector<int> indices;
  std::vector<double> latency_ms;
};

FrameResult slowStage(const RgbdFrame& f, std::chrono::milliseconds cost) {
  std::this_thread::sleep_for(cost);
  FrameResult r;
  r.index = f.index;
  r.stamp_s = f.stamp_s;
  r.tracked = true;
  r.state = TrackingState::kOk;
  return r;
}

TEST(FrameQueue, DropOldestNeverWaitsAndCounts) {
  FrameQueue<int> queue(2, QueueFullPolicy::kDropOldest);
  // Nobody pops: with a blocking push this would hang; the future's timeout catches that.
  auto pushes = std::async(std::launch::async, [&queue] {
    size_t dropped = 0;
    for (int i = 0; i < 10; ++i) dropped += queue.push(i);
    return dropped;
  });
  ASSERT_EQ(pushes.wait_for(5s), std::future_status::ready);
  EXPECT_EQ(pushes.get(), 8u);
  EXPECT_EQ(queue.dropped(), 8u);
  EXPECT_EQ(queue.pop(), 8);  // the newest two are left
  EXPECT_EQ(queue.pop(), 9);
  queue.close();
  EXPECT_EQ(queue.pop(), std::nullopt);
}

TEST(FrameQueue, BlockPolicyWaitsForRoomAndDropsNothing) {
  FrameQueue<int> queue(1, QueueFullPolicy::kBlock);
  queue.push(1);
  auto second = std::async(std::launch::async, [&queue] { return queue.push(2); });
  EXPECT_EQ(second.wait_for(100ms), std::future_status::timeout);  // full: waits
  EXPECT_EQ(queue.pop(), 1);
  ASSERT_EQ(second.wait_for(5s), std::future_status::ready);
  EXPECT_EQ(second.get(), 0u);
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_EQ(queue.dropped(), 0u);
}

TEST(FrameQueue, CloseReleasesABlockedPush) {
  FrameQueue<int> queue(1, QueueFullPolicy::kBlock);
  queue.push(1);
  auto blocked = std::async(std::launch::async, [&queue] { return queue.push(2); });
  queue.close();
  ASSERT_EQ(blocked.wait_for(5s), std::future_status::ready);
  EXPECT_EQ(queue.pop(), 1);  // what was queued is still delivered
  EXPECT_EQ(queue.pop(), std::nullopt);
}

TEST(RealtimeRunner, SlowStageMakesThePipelineDropAndCountNeverBlock) {
  // 60 frames at 100 Hz (0.6 s of camera) into a stage that needs 30 ms a frame: about a third
  // can be processed; the rest must be dropped, the newest frames kept, the camera never held up.
  FakeCamera camera(60, 100.0);
  IndexSink sink;
  RunSummary summary;
  const auto start = std::chrono::steady_clock::now();
  runRealtime(camera, [](const RgbdFrame& f) { return slowStage(f, 30ms); }, {&sink}, summary,
              {true, 1});
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(summary.frames + int(summary.dropped), 60);
  EXPECT_GT(summary.dropped, 20u);
  EXPECT_LT(summary.frames, 40);
  ASSERT_FALSE(sink.indices.empty());
  EXPECT_EQ(sink.indices.back(), 59);  // the newest frame is processed, not dropped
  for (size_t i = 1; i < sink.indices.size(); ++i) EXPECT_LT(sink.indices[i - 1], sink.indices[i]);
  // Camera time plus at most a couple of frames' processing: nothing waited for the stage.
  EXPECT_LT(wall_s, 0.6 + 0.9);  // a blocked camera would need 60 x 30 ms = 1.8 s
  // With one frame of queue a frame waits at most one processing time before its own.
  for (double ms : sink.latency_ms) EXPECT_LT(ms, 2 * 30.0 + 100.0);
}

TEST(RealtimeRunner, UnpacedProcessesEveryFrameInOrder) {
  FakeCamera camera(30, 30.0);
  IndexSink sink;
  RunSummary summary;
  runRealtime(camera, [](const RgbdFrame& f) { return slowStage(f, 1ms); }, {&sink}, summary,
              {false, 2});
  EXPECT_EQ(summary.frames, 30);
  EXPECT_EQ(summary.dropped, 0u);
  ASSERT_EQ(sink.indices.size(), 30u);
  for (int i = 0; i < 30; ++i) EXPECT_EQ(sink.indices[size_t(i)], i);
}

/// Records what the sinks see of each result's messages.
class EventSink final : public FrameSink {
 public:
  void consume(const RgbdFrame&, const FrameResult& result) override {
    for (const FeedbackEvent& e : result.events)
      seen.emplace_back(result.arrival_s, e.audio_start_s);
  }
  void finish(const RunEnd&) override {}
  std::vector<std::pair<double, double>> seen;  // (arrival_s, audio_start_s)
};

TEST(RealtimeRunner, BeforeSinksStampsEachResultBeforeTheSinksSeeIt) {
  // Issue 14: the audio stage sets each message's audio_start_s before events.jsonl's writer
  // consumes the result, on the clock of arrival_s (origin: RealtimeOptions::start).
  FakeCamera camera(20, 200.0);
  EventSink sink;
  RunSummary summary;
  RealtimeOptions options{false, 2};
  options.start = std::chrono::steady_clock::now() - 10s;  // the run's clock began earlier
  options.before_sinks = [](FrameResult& r) {
    for (FeedbackEvent& e : r.events) e.audio_start_s = r.arrival_s + 0.5;
  };
  runRealtime(
      camera,
      [](const RgbdFrame& f) {
        FrameResult r = slowStage(f, 0ms);
        r.events.emplace_back();
        return r;
      },
      {&sink}, summary, options);
  ASSERT_EQ(sink.seen.size(), 20u);
  for (const auto& [arrival_s, start_s] : sink.seen) {
    EXPECT_GE(arrival_s, 10.0);
    EXPECT_DOUBLE_EQ(start_s, arrival_s + 0.5);
  }
}

TEST(RealtimeRunner, AStageErrorEndsTheRunAndReachesTheCaller) {
  FakeCamera camera(1000, 1000.0);
  RunSummary summary;
  auto run = std::async(std::launch::async, [&] {
    runRealtime(camera,
                [](const RgbdFrame& f) -> FrameResult {
                  if (f.index >= 3) throw std::runtime_error("stage failed");
                  return slowStage(f, 0ms);
                },
                {}, summary, {true, 2});
  });
  ASSERT_EQ(run.wait_for(10s), std::future_status::ready);
  EXPECT_THROW(run.get(), std::runtime_error);
}

}  // namespace
}  // namespace dynanav
