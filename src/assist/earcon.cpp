#include "assist/earcon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dynanav {
namespace {

/// Raised-cosine attack and release: a tone switched on or off abruptly clicks.
constexpr double kRampS = 0.006;

}  // namespace

EarconPattern earconPattern(FeedbackPriority priority) {
  switch (priority) {
    case FeedbackPriority::kUrgent:
      return {3, 1320.0, 0.07, 0.045};
    case FeedbackPriority::kAdvisory:
      return {2, 880.0, 0.10, 0.08};
    case FeedbackPriority::kInfo:
      break;
  }
  return {1, 523.25, 0.16, 0.0};
}

std::vector<float> synthesiseEarcon(FeedbackPriority priority, int rate_hz, double gain) {
  const EarconPattern p = earconPattern(priority);
  const auto beep_samples = static_cast<size_t>(std::lround(p.beep_s * rate_hz));
  const auto pause_samples = static_cast<size_t>(std::lround(p.pause_s * rate_hz));
  const auto ramp_samples = static_cast<double>(std::lround(kRampS * rate_hz));
  std::vector<float> out;
  out.reserve(p.beeps * beep_samples + (p.beeps - 1) * pause_samples);
  // A pure sine localises poorly (little level difference between the ears at low pitch);
  // harmonics 2 and 3 give the HRTF spectral cues to work with. Weights sum to 1 (peak = gain).
  const double weights[] = {0.6, 0.25, 0.15};
  for (int b = 0; b < p.beeps; ++b) {
    for (size_t i = 0; i < beep_samples; ++i) {
      const double t = double(i) / rate_hz;
      double s = 0.0;
      for (int h = 0; h < 3; ++h)
        s += weights[h] * std::sin(2.0 * std::numbers::pi * p.pitch_hz * (h + 1) * t);
      const double edge = std::min<double>(i, beep_samples - 1 - i);
      const double envelope =
          edge >= ramp_samples ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * edge / ramp_samples);
      out.push_back(static_cast<float>(gain * envelope * s));
    }
    if (b + 1 < p.beeps) out.insert(out.end(), pause_samples, 0.0f);
  }
  return out;
}

}  // namespace dynanav
