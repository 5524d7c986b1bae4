// Speech through the espeak-ng library and the earcons (issue 14).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assist/earcon.hpp"
#include "assist/speech_synth.hpp"
#include "core/error.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

double rms(const std::vector<int16_t>& s) {
  double sum = 0;
  for (int16_t v : s) sum += double(v) * v;
  return s.empty() ? 0.0 : std::sqrt(sum / double(s.size()));
}

TEST(SpeechSynth, EnglishAndGermanGiveSpeechAtEspeaksRate) {
  SpeechSynth en({"en", 190});
  SpeechSynth de({"de", 190});
  const SpeechPcm a = en.speak("Person, 2 o'clock, 3 metres, approaching fast");
  const SpeechPcm b = de.speak("Person, 2 Uhr, 3 Meter, kommt schnell näher");
  for (const SpeechPcm* pcm : {&a, &b}) {
    EXPECT_EQ(pcm->rate_hz, 22050);
    EXPECT_GT(pcm->durationS(), 1.0);  // a six-word message
    EXPECT_LT(pcm->durationS(), 6.0);
    EXPECT_GT(rms(pcm->samples), 300.0);  // speech, not silence
  }
  EXPECT_NE(a.samples, b.samples);
}

TEST(SpeechSynth, SilenceAroundTheWordsIsTrimmed) {
  SpeechSynth en({"en", 190});
  const SpeechPcm pcm = en.speak("Chair");
  ASSERT_FALSE(pcm.samples.empty());
  const size_t edge = size_t(0.05 * pcm.rate_hz);  // within 50 ms of each end there is sound
  auto loud = [](int16_t v) { return std::abs(int(v)) >= 64; };
  EXPECT_TRUE(std::any_of(pcm.samples.begin(), pcm.samples.begin() + edge, loud));
  EXPECT_TRUE(std::any_of(pcm.samples.end() - edge, pcm.samples.end(), loud));
}

TEST(SpeechSynth, TheSameTextGivesTheSamePcm) {
  SpeechSynth en({"en", 190});
  const SpeechPcm first = en.speak("Person ahead");
  (void)en.speak("Something else in between");
  EXPECT_EQ(en.speak("Person ahead").samples, first.samples);
}

TEST(SpeechSynth, FasterRateGivesShorterSpeech) {
  SpeechSynth slow({"en", 120});
  SpeechSynth fast({"en", 300});
  const std::string text = "Person at ten o'clock, two metres";
  EXPECT_GT(slow.speak(text).durationS(), 1.5 * fast.speak(text).durationS());
}

TEST(SpeechSynth, UnknownVoiceIsBadInputNamingTheKey) {
  const std::string message = test::errorOf([] { SpeechSynth({"xx-nosuchvoice", 190}); });
  EXPECT_NE(message.find("audio.voice"), std::string::npos) << message;
  EXPECT_NE(message.find("xx-nosuchvoice"), std::string::npos) << message;
}

TEST(SpeechSynth, VoiceFollowsTheLanguageUnlessConfigured) {
  EXPECT_EQ(speechVoice("auto", "en"), "en");
  EXPECT_EQ(speechVoice("auto", "de"), "de");
  EXPECT_EQ(speechVoice("en-us", "de"), "en-us");
  EXPECT_NE(test::errorOf([] { (void)speechVoice("auto", "fr"); }).find("audio.voice"),
            std::string::npos);
}

TEST(Earcon, PitchAndRhythmRiseWithUrgency) {
  const EarconPattern info = earconPattern(FeedbackPriority::kInfo);
  const EarconPattern advisory = earconPattern(FeedbackPriority::kAdvisory);
  const EarconPattern urgent = earconPattern(FeedbackPriority::kUrgent);
  EXPECT_LT(info.pitch_hz, advisory.pitch_hz);
  EXPECT_LT(advisory.pitch_hz, urgent.pitch_hz);
  EXPECT_LT(info.beeps, advisory.beeps);
  EXPECT_LT(advisory.beeps, urgent.beeps);
  EXPECT_LT(urgent.beep_s + urgent.pause_s, advisory.beep_s + advisory.pause_s);  // faster
  for (const EarconPattern& p : {info, advisory, urgent}) EXPECT_LE(p.durationS(), 0.4);
}

TEST(Earcon, SamplesFollowThePatternWithoutClicks) {
  const int rate = 48000;
  for (const auto priority :
       {FeedbackPriority::kInfo, FeedbackPriority::kAdvisory, FeedbackPriority::kUrgent}) {
    const std::vector<float> s = synthesiseEarcon(priority, rate, 0.5);
    const EarconPattern p = earconPattern(priority);
    EXPECT_NEAR(double(s.size()) / rate, p.durationS(), 2.0 / rate);
    float peak = 0;
    for (float v : s) peak = std::max(peak, std::abs(v));
    EXPECT_LE(peak, 0.5f + 1e-6f);
    EXPECT_GT(peak, 0.3f);
    EXPECT_LT(std::abs(s.front()), 1e-3f);  // ramps in and out
    EXPECT_LT(std::abs(s.back()), 1e-3f);
    // Beeps: runs of sound separated by silent pauses.
    int onsets = 0;
    bool sounding = false;
    size_t quiet = 0;
    for (float v : s) {
      if (std::abs(v) > 0.01f) {
        if (!sounding && (onsets == 0 || quiet > size_t(0.02 * rate))) ++onsets;
        sounding = true;
        quiet = 0;
      } else if (++quiet > size_t(0.005 * rate)) {
        sounding = false;
      }
    }
    EXPECT_EQ(onsets, p.beeps);
  }
}

}  // namespace
}  // namespace dynanav
