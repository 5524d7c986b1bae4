#pragma once
// The spoken messages (issue 14): short, in English or German, most important word first:
//   "Person, 2 o'clock, 3 metres, approaching fast" / "Person, 2 Uhr, 3 Meter, kommt schnell näher"
// What a message says (class, clock, spoken distance, motion word) is also what the policy
// compares to decide whether the situation changed.
#include <string>

#include "core/config/assist.hpp"

namespace dynanav {

enum class Language { kEnglish, kGerman };
/// "en" | "de"; InputError naming `key` otherwise.
Language parseLanguage(const std::string& code, const std::string& key = "--language");
const char* languageCode(Language language);

/// How an object moves relative to the wearer, as spoken.
enum class MotionWord { kNone, kStanding, kPassing, kApproaching, kApproachingFast, kMovingAway };

/// The motion word of an object: static obstacles none, people standing; movers by closing speed.
MotionWord motionWordOf(bool person, bool moving, double closing_mps, const AssistConfig& config);

/// Spoken distance: half metres below 2 m (0.5 at least), whole metres beyond. The class the
/// policy compares is this value (in metres).
double spokenDistanceM(double distance_m);

struct MessageContent {
  bool person = true;
  int clock = 12;
  double distance_m = 0.0;
  MotionWord motion = MotionWord::kNone;
};

std::string phrase(const MessageContent& content, Language language);

/// Estimated length (s) of the earcon and the spoken text (the audio stage times it exactly).
double spokenDurationS(const std::string& text, const AssistConfig& config);

}  // namespace dynanav
