#pragma once
// Per-stage timing that feeds stats.json (STYLE.md habit 10), the one timing mechanism of a run:
// wall time per sample, and for scoped timers the CPU time of the timing thread (what the stage
// cost the machine; work a stage hands to OpenCV's or Ceres's own threads is not in it). Thread-
// safe: stages that run in other threads (local mapping, segmentation) record into the same table.
#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace dynanav {

struct TimingSummary {
  double mean_ms = 0.0;
  double p95_ms = 0.0;
  double max_ms = 0.0;
  double total_ms = 0.0;
  size_t count = 0;
  double cpu_mean_ms = 0.0;  ///< mean CPU time of the timing thread (0 where not measured)
};

/// Summary of a list of samples (p95 by nearest rank).
TimingSummary summarize(std::vector<double> samples_ms);

class StageTimers {
 public:
  /// One sample; `cpu_ms` < 0 = not measured.
  void add(const std::string& stage, double ms, double cpu_ms = -1.0);
  [[nodiscard]] std::map<std::string, TimingSummary> summary() const;
  [[nodiscard]] std::vector<double> samples(const std::string& stage) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::vector<double>> samples_ms_;
  std::map<std::string, std::pair<double, size_t>> cpu_ms_;  // sum and count per stage
};

/// CPU time this thread has used (ms).
double threadCpuMs();

/// Records the time from construction to destruction (or stop()) under `stage`.
class ScopedTimer {
 public:
  ScopedTimer(StageTimers& timers, std::string stage)
      : timers_(&timers),
        stage_(std::move(stage)),
        start_(Clock::now()),
        cpu_start_ms_(threadCpuMs()) {}
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;
  ~ScopedTimer() { stop(); }
  /// Records now; later calls do nothing. Returns the elapsed milliseconds.
  double stop();

 private:
  using Clock = std::chrono::steady_clock;
  StageTimers* timers_;
  std::string stage_;
  Clock::time_point start_;
  double cpu_start_ms_;
  bool stopped_ = false;
};

/// Milliseconds since a steady-clock point.
inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

/// Peak resident set size of this process in MiB (Linux; 0 where unknown).
double peakRssMb();
/// Resident set size of this process now, in MiB (Linux; 0 where unknown).
double currentRssMb();

}  // namespace dynanav
