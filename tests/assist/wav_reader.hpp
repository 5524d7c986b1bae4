#pragma once
// Reads feedback.wav back with libsndfile for the audio tests, and measures it.
#include <sndfile.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <vector>

namespace dynanav::test {

struct Wav {
  int rate_hz = 0;
  int channels = 0;
  int format = 0;
  std::vector<int16_t> samples;  // interleaved
  [[nodiscard]] size_t frames() const { return channels ? samples.size() / channels : 0; }
  [[nodiscard]] double durationS() const { return rate_hz ? double(frames()) / rate_hz : 0.0; }
  [[nodiscard]] size_t at(double t_s) const {
    return std::min(frames(), size_t(std::max(0.0, std::round(t_s * rate_hz))));
  }
  /// RMS of one channel over [t0, t1).
  [[nodiscard]] double rms(int channel, double t0_s, double t1_s) const {
    const size_t a = at(t0_s), b = at(t1_s);
    double sum = 0;
    for (size_t i = a; i < b; ++i) sum += std::pow(double(samples[channels * i + channel]), 2);
    return b > a ? std::sqrt(sum / double(b - a)) : 0.0;
  }
  /// Largest |sample| of both channels over [t0, t1).
  [[nodiscard]] int peak(double t0_s, double t1_s) const {
    int p = 0;
    for (size_t i = channels * at(t0_s); i < channels * at(t1_s); ++i)
      p = std::max(p, std::abs(int(samples[i])));
    return p;
  }
  /// The last time in [t0, t1) where |sample| >= level (t0 when none).
  [[nodiscard]] double lastSoundS(double t0_s, double t1_s, int level) const {
    for (size_t i = at(t1_s); i > at(t0_s); --i)
      for (int c = 0; c < channels; ++c)
        if (std::abs(int(samples[channels * (i - 1) + c])) >= level) return double(i) / rate_hz;
    return t0_s;
  }
  /// The first time in [t0, t1) where |sample| >= level (t1 when none).
  [[nodiscard]] double firstSoundS(double t0_s, double t1_s, int level) const {
    for (size_t i = at(t0_s); i < at(t1_s); ++i)
      for (int c = 0; c < channels; ++c)
        if (std::abs(int(samples[channels * i + c])) >= level) return double(i) / rate_hz;
    return t1_s;
  }
  /// Power at `hz` over [t0, t1) of the left channel (Goertzel), per sample.
  [[nodiscard]] double power(double hz, double t0_s, double t1_s) const {
    const double w = 2.0 * std::numbers::pi * hz / rate_hz;
    double s1 = 0, s2 = 0;
    const size_t a = at(t0_s), b = at(t1_s);
    for (size_t i = a; i < b; ++i) {
      const double s0 = samples[channels * i] + 2.0 * std::cos(w) * s1 - s2;
      s2 = s1;
      s1 = s0;
    }
    const double n = double(std::max<size_t>(1, b - a));
    return (s1 * s1 + s2 * s2 - 2.0 * std::cos(w) * s1 * s2) / (n * n);
  }
};

inline Wav readWav(const std::filesystem::path& path) {
  Wav wav;
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (!file) return wav;
  wav.rate_hz = info.samplerate;
  wav.channels = info.channels;
  wav.format = info.format;
  wav.samples.resize(size_t(info.frames) * size_t(info.channels));
  wav.samples.resize(size_t(sf_readf_short(file, wav.samples.data(), info.frames)) *
                     size_t(info.channels));
  sf_close(file);
  return wav;
}

}  // namespace dynanav::test
