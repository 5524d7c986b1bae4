#include "core/timer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>

#include <time.h>

namespace dynanav {

TimingSummary summarize(std::vector<double> samples_ms) {
  TimingSummary s;
  s.count = samples_ms.size();
  if (samples_ms.empty()) return s;
  std::sort(samples_ms.begin(), samples_ms.end());
  s.total_ms = std::accumulate(samples_ms.begin(), samples_ms.end(), 0.0);
  s.mean_ms = s.total_ms / double(s.count);
  const size_t rank = size_t(std::ceil(0.95 * double(s.count)));
  s.p95_ms = samples_ms[std::clamp<size_t>(rank, 1, s.count) - 1];
  s.max_ms = samples_ms.back();
  return s;
}

void StageTimers::add(const std::string& stage, double ms, double cpu_ms) {
  std::lock_guard lock(mutex_);
  samples_ms_[stage].push_back(ms);
  if (cpu_ms >= 0.0) {
    auto& [sum, count] = cpu_ms_[stage];
    sum += cpu_ms;
    ++count;
  }
}

std::map<std::string, TimingSummary> StageTimers::summary() const {
  std::lock_guard lock(mutex_);
  std::map<std::string, TimingSummary> out;
  for (const auto& [stage, samples] : samples_ms_) out[stage] = summarize(samples);
  for (const auto& [stage, cpu] : cpu_ms_)
    out[stage].cpu_mean_ms = cpu.second ? cpu.first / double(cpu.second) : 0.0;
  return out;
}

std::vector<double> StageTimers::samples(const std::string& stage) const {
  std::lock_guard lock(mutex_);
  const auto it = samples_ms_.find(stage);
  return it == samples_ms_.end() ? std::vector<double>{} : it->second;
}

double ScopedTimer::stop() {
  const double ms = msSince(start_);
  if (!stopped_) {
    timers_->add(stage_, ms, threadCpuMs() - cpu_start_ms_);
    stopped_ = true;
  }
  return ms;
}

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

namespace {
double statusMb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == field) {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
    std::string rest;
    std::getline(status, rest);
  }
  return 0.0;
}
}  // namespace

double peakRssMb() {
  return statusMb("VmHWM:");
}

double currentRssMb() {
  return statusMb("VmRSS:");
}

}  // namespace dynanav
