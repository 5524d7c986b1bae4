#pragma once
// Config section `audio` (see core/config.hpp for how sections are loaded and echoed): speech,
// earcons and where the mixed stream goes (issue 14; docs/audio.md).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit().
#include <string>

#include "core/config/range.hpp"

namespace dynanav {

/// The audio stage: scheduling of the messages the policy raises, and their rendering.
struct AudioConfig {
  std::string output = "none";
  std::string voice = "auto";
  int speech_rate_wpm = 190;
  double speech_gain = 1.0;
  double earcon_gain = 0.5;
  bool hrtf = true;
  double gap_s = 0.25;
  double stale_after_s = 1.0;
  int queue_messages = 16;
  double live_buffer_ms = 60.0;
  template <class V>
  void visit(V&& v) {
    v("output", output,
      "none | file (feedback.wav, --audio) | live (feedback.wav and the default sound device, "
      "--audio live; needs --realtime)",
      OneOf{"none", "file", "live"});
    v("voice", voice, "espeak-ng voice; auto = the voice of the messages' language (en, de)");
    v("speech_rate_wpm", speech_rate_wpm, "speaking rate (words per minute)", Range{80, 450});
    v("speech_gain", speech_gain, "speech level (1 = espeak-ng's own)", Range{0, 4});
    v("earcon_gain", earcon_gain, "earcon peak level (full scale = 1)", Range{0, 1});
    v("hrtf", hrtf, "place earcons with OpenAL-soft's HRTF (false = its plain stereo panning)");
    v("gap_s", gap_s, "silence between two messages (s); an urgent interruption skips it",
      Range{0, 10});
    v("stale_after_s", stale_after_s,
      "a message that cannot start within this time of its frame is dropped as stale (s)",
      Range{0, 60});
    v("queue_messages", queue_messages,
      "real time: messages waiting for the audio thread; when full a new one is dropped",
      Range{1, 10000});
    v("live_buffer_ms", live_buffer_ms,
      "--audio live: audio rendered ahead of the clock and queued on the device (ms)",
      Range{10, 2000});
  }
};

}  // namespace dynanav
