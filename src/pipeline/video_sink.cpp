#include "pipeline/video_sink.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

#include "core/timer.hpp"
#include "viz/annotate.hpp"

namespace dynanav {

namespace {
constexpr double kMessageShownS = 3.0;  // about as long as a spoken message lasts
constexpr size_t kQueueFrames = 8;      // bounds memory; the tracker waits if drawing falls behind
}  // namespace

std::vector<InstanceStatus> instanceStatuses(const FrameResult& result) {
  std::vector<InstanceStatus> out;
  for (const InstanceVerdict& v : result.verdicts)
    out.push_back({v.id, v.moving            ? "moving"
                         : v.prior_dynamic   ? "prior"
                         : v.verified_static ? "static"
                                             : ""});
  return out;
}

VideoSink::VideoSink(std::filesystem::path out_dir, const PinholeCamera& camera,
                     const std::string& encoder_options, double fps)
    : camera_(camera),
      video_(std::move(out_dir), "annotated", fps, videoEncoderOptions(encoder_options)),
      worker_([this] { work(); }) {}

VideoSink::~VideoSink() {
  stop();
}

void VideoSink::consume(const RgbdFrame& frame, const FrameResult& result) {
  if (!result.events.empty()) message_ = result.events.back();
  Job job;
  FrameAnnotation& a = job.annotation;
  a.index = result.index;
  a.stamp_s = result.stamp_s;
  a.state = toString(result.state);
  a.keyframe = result.keyframe;
  a.T_world_camera = result.T_world_camera;
  a.statuses = instanceStatuses(result);
  a.objects = result.objects;
  if (message_ && result.stamp_s - message_->stamp_s <= kMessageShownS) a.message = message_;
  job.bgr = frame.bgr.clone();
  job.instances = result.instances;
  job.instances.labels = result.instances.labels.clone();
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return jobs_.size() < kQueueFrames; });
  jobs_.push_back(std::move(job));
  changed_.notify_all();
}

void VideoSink::work() {
  while (true) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return done_ || !jobs_.empty(); });
      if (jobs_.empty()) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
      changed_.notify_all();
    }
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0_ms = threadCpuMs();
    const Instances& instances =
        job.instances.labels.empty() ? Instances::none(job.bgr.size()) : job.instances;
    const cv::Mat annotated = annotateFrame(job.bgr, instances, camera_, job.annotation);
    const auto t1 = std::chrono::steady_clock::now();
    const double cpu1_ms = threadCpuMs();
    video_.write(annotated);  // x264 runs on this thread (threads=1 by default)
    draw_ms_ += std::chrono::duration<double, std::milli>(t1 - t0).count();
    encode_ms_ += msSince(t1);
    draw_cpu_ms_ += cpu1_ms - cpu0_ms;
    encode_cpu_ms_ += threadCpuMs() - cpu1_ms;
  }
}

void VideoSink::stop() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
  video_.close();
}

void VideoSink::finish(const RunEnd&) {
  stop();  // drains the queue first
  const auto perFrame = [this](double total_ms) { return total_ms / std::max(1, video_.frames()); };
  if (!video_.path().empty())
    spdlog::info(
        "video: {} ({} frames, fourcc {}); per frame {:.1f} ms drawing, {:.1f} ms encoding "
        "(CPU of the video thread: {:.1f} + {:.1f} ms)",
        video_.path().string(), video_.frames(), video_.fourcc(), perFrame(draw_ms_),
        perFrame(encode_ms_), perFrame(draw_cpu_ms_), perFrame(encode_cpu_ms_));
}

}  // namespace dynanav
