// Message templates in English and German: short, clock-face directions, spoken distances.
#include <gtest/gtest.h>

#include "assist/templates.hpp"
#include "core/error.hpp"

namespace dynanav {
namespace {

TEST(Templates, English) {
  EXPECT_EQ(phrase({true, 2, 3.2, MotionWord::kApproachingFast}, Language::kEnglish),
            "Person, 2 o'clock, 3 metres, approaching fast");
  EXPECT_EQ(phrase({true, 12, 1.1, MotionWord::kStanding}, Language::kEnglish),
            "Person, 12 o'clock, 1 metre, standing");
  EXPECT_EQ(phrase({true, 9, 1.4, MotionWord::kPassing}, Language::kEnglish),
            "Person, 9 o'clock, 1.5 metres, passing");
  EXPECT_EQ(phrase({true, 6, 4.0, MotionWord::kMovingAway}, Language::kEnglish),
            "Person, 6 o'clock, 4 metres, moving away");
  EXPECT_EQ(phrase({false, 11, 0.9, MotionWord::kNone}, Language::kEnglish),
            "Obstacle, 11 o'clock, 1 metre");
}

TEST(Templates, German) {
  EXPECT_EQ(phrase({true, 2, 3.2, MotionWord::kApproachingFast}, Language::kGerman),
            "Person, 2 Uhr, 3 Meter, kommt schnell näher");
  EXPECT_EQ(phrase({true, 12, 1.4, MotionWord::kApproaching}, Language::kGerman),
            "Person, 12 Uhr, 1,5 Meter, kommt näher");
  EXPECT_EQ(phrase({true, 3, 2.0, MotionWord::kStanding}, Language::kGerman),
            "Person, 3 Uhr, 2 Meter, steht");
  EXPECT_EQ(phrase({true, 4, 5.0, MotionWord::kMovingAway}, Language::kGerman),
            "Person, 4 Uhr, 5 Meter, entfernt sich");
  EXPECT_EQ(phrase({false, 1, 0.3, MotionWord::kNone}, Language::kGerman),
            "Hindernis, 1 Uhr, 0,5 Meter");
}

TEST(Templates, SpokenDistanceClasses) {
  EXPECT_EQ(spokenDistanceM(0.1), 0.5);
  EXPECT_EQ(spokenDistanceM(0.74), 0.5);
  EXPECT_EQ(spokenDistanceM(0.76), 1.0);
  EXPECT_EQ(spokenDistanceM(1.6), 1.5);
  EXPECT_EQ(spokenDistanceM(1.8), 2.0);
  EXPECT_EQ(spokenDistanceM(3.49), 3.0);
  EXPECT_EQ(spokenDistanceM(3.51), 4.0);
}

TEST(Templates, MotionWords) {
  const AssistConfig c;  // moving 0.3 m/s, fast 1.2 m/s
  EXPECT_EQ(motionWordOf(true, false, 0.0, c), MotionWord::kStanding);
  EXPECT_EQ(motionWordOf(false, false, 0.0, c), MotionWord::kNone);
  EXPECT_EQ(motionWordOf(true, true, 1.5, c), MotionWord::kApproachingFast);
  EXPECT_EQ(motionWordOf(true, true, 0.5, c), MotionWord::kApproaching);
  EXPECT_EQ(motionWordOf(true, true, 0.1, c), MotionWord::kPassing);
  EXPECT_EQ(motionWordOf(true, true, -0.5, c), MotionWord::kMovingAway);
}

TEST(Templates, SpokenDurationCountsCharactersNotBytes) {
  AssistConfig c;
  c.earcon_s = 0.25;
  c.speech_chars_per_s = 10.0;
  EXPECT_NEAR(spokenDurationS("0123456789", c), 1.25, 1e-12);
  EXPECT_NEAR(spokenDurationS("näher", c), 0.25 + 0.5, 1e-12);  // 5 characters, 6 bytes
}

TEST(Templates, Languages) {
  EXPECT_EQ(parseLanguage("en"), Language::kEnglish);
  EXPECT_EQ(parseLanguage("de"), Language::kGerman);
  EXPECT_STREQ(languageCode(Language::kGerman), "de");
  try {
    parseLanguage("fr", "assist.language");
    FAIL() << "no error for fr";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("assist.language"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynanav
