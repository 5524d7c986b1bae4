#pragma once
// `--video` (issue 15): OUT/annotated.mp4 (H.264; .avi MJPG where no MP4 encoder opens), each
// frame drawn by viz/annotate from the frame and its FrameResult. Drawing and encoding run on a
// worker thread behind a short queue (the tracking thread only copies the frame), so the video
// costs little wall time where a second core is free; frames stay in order.
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "core/camera.hpp"
#include "pipeline/sinks.hpp"
#include "viz/annotate.hpp"
#include "viz/instance_drawing.hpp"
#include "viz/video_writer.hpp"

namespace dynanav {

/// Instance verdicts as the pictures name them.
std::vector<InstanceStatus> instanceStatuses(const FrameResult& result);

class VideoSink final : public FrameSink {
 public:
  /// ENCODER_OPTIONS: `outputs.video_encoder_options` (a ConfigError when it does not parse).
  VideoSink(std::filesystem::path out_dir, const PinholeCamera& camera,
            const std::string& encoder_options, double fps = 30.0);
  ~VideoSink() override;
  VideoSink(const VideoSink&) = delete;
  VideoSink& operator=(const VideoSink&) = delete;
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  struct Job {
    cv::Mat bgr;
    Instances instances;
    FrameAnnotation annotation;
  };
  void work();
  void stop();

  PinholeCamera camera_;
  VideoOutput video_;
  std::optional<FeedbackEvent> message_;            ///< the latest one, shown for a few seconds
  double draw_ms_ = 0.0, encode_ms_ = 0.0;          ///< wall time; worker thread only
  double draw_cpu_ms_ = 0.0, encode_cpu_ms_ = 0.0;  ///< the worker thread's CPU time
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  bool done_ = false;
  std::thread worker_;
};

}  // namespace dynanav
