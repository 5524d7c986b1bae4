#include "assist/templates.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace dynanav {

Language parseLanguage(const std::string& code, const std::string& key) {
  if (code == "en") return Language::kEnglish;
  if (code == "de") return Language::kGerman;
  throw InputError(key, "unknown language '" + code + "' (choose en or de)");
}

const char* languageCode(Language language) {
  return language == Language::kGerman ? "de" : "en";
}

MotionWord motionWordOf(bool person, bool moving, double closing_mps, const AssistConfig& config) {
  if (!moving) return person ? MotionWord::kStanding : MotionWord::kNone;
  if (closing_mps >= config.fast_closing_mps) return MotionWord::kApproachingFast;
  if (closing_mps >= config.moving_speed_mps) return MotionWord::kApproaching;
  if (closing_mps <= -config.moving_speed_mps) return MotionWord::kMovingAway;
  return MotionWord::kPassing;
}

double spokenDistanceM(double distance_m) {
  if (distance_m < 1.75) return std::max(0.5, std::round(distance_m * 2.0) / 2.0);
  return std::round(distance_m);
}

namespace {

std::string distanceWords(double spoken_m, Language language) {
  const bool whole = spoken_m == std::floor(spoken_m);
  if (language == Language::kGerman) {
    // German writes the decimal comma; "1 Meter" and "3 Meter" alike.
    std::string number = whole ? fmt::format("{}", int(spoken_m)) : fmt::format("{:.1f}", spoken_m);
    for (char& c : number)
      if (c == '.') c = ',';
    return number + " Meter";
  }
  if (whole) return fmt::format("{} {}", int(spoken_m), spoken_m == 1.0 ? "metre" : "metres");
  return fmt::format("{:.1f} metres", spoken_m);
}

const char* motionWords(MotionWord motion, Language language) {
  const bool de = language == Language::kGerman;
  switch (motion) {
    case MotionWord::kStanding:
      return de ? "steht" : "standing";
    case MotionWord::kPassing:
      return de ? "geht vorbei" : "passing";
    case MotionWord::kApproaching:
      return de ? "kommt näher" : "approaching";
    case MotionWord::kApproachingFast:
      return de ? "kommt schnell näher" : "approaching fast";
    case MotionWord::kMovingAway:
      return de ? "entfernt sich" : "moving away";
    case MotionWord::kNone:
      break;
  }
  return "";
}

}  // namespace

std::string phrase(const MessageContent& c, Language language) {
  const bool de = language == Language::kGerman;
  const char* what = c.person ? "Person" : (de ? "Hindernis" : "Obstacle");
  std::string text = fmt::format("{}, {} {}, {}", what, c.clock, de ? "Uhr" : "o'clock",
                                 distanceWords(spokenDistanceM(c.distance_m), language));
  const std::string motion = motionWords(c.motion, language);
  if (!motion.empty()) text += ", " + motion;
  return text;
}

double spokenDurationS(const std::string& text, const AssistConfig& config) {
  // Characters, not bytes: UTF-8 continuation bytes (the German umlauts) are not spoken twice.
  size_t chars = 0;
  for (const unsigned char c : text) chars += (c & 0xC0) != 0x80 ? 1 : 0;
  return config.earcon_s + double(chars) / config.speech_chars_per_s;
}

}  // namespace dynanav
