#include "io/events_jsonl.hpp"

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "io/text_lines.hpp"

namespace dynanav {
namespace {

double round6(double v) {
  return std::round(v * 1e6) / 1e6 + 0.0;  // + 0.0: no "-0.0" in files
}
/// null for "none" (negative) values.
nlohmann::json orNull(double v) {
  return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(round6(v));
}
double fromNullable(const nlohmann::json& j) {
  return j.is_null() ? -1.0 : j.get<double>();
}

}  // namespace

const char* priorityName(FeedbackPriority priority) {
  switch (priority) {
    case FeedbackPriority::kUrgent:
      return "urgent";
    case FeedbackPriority::kAdvisory:
      return "advisory";
    case FeedbackPriority::kInfo:
      break;
  }
  return "info";
}

FeedbackPriority priorityFromName(const std::string& name) {
  if (name == "urgent") return FeedbackPriority::kUrgent;
  if (name == "advisory") return FeedbackPriority::kAdvisory;
  if (name == "info") return FeedbackPriority::kInfo;
  throw std::invalid_argument("priority must be urgent, advisory or info, got '" + name + "'");
}

nlohmann::json toJson(const FeedbackEvent& e) {
  return {{"t", round6(e.stamp_s)},
          {"priority", priorityName(e.priority)},
          {"kind", e.kind},
          {"text", e.text},
          {"object_id", e.object_id},
          {"bearing_deg", round6(e.bearing_deg)},
          {"distance", round6(e.distance_m)},
          {"ttc", orNull(e.ttc_s)},
          {"audio_start", orNull(e.audio_start_s)},
          {"clock", e.clock},
          {"closest", orNull(e.closest_m)},
          {"user_related", e.user_related},
          {"interrupts", e.interrupts},
          {"spoken_s", round6(e.spoken_s)},
          {"position_world", {round6(e.p_world.x()), round6(e.p_world.y()), round6(e.p_world.z())}},
          {"language", e.language}};
}

FeedbackEvent feedbackEventFromJson(const nlohmann::json& j) {
  FeedbackEvent e;
  e.stamp_s = j.at("t").get<double>();
  e.priority = priorityFromName(j.at("priority").get<std::string>());
  e.kind = j.at("kind").get<std::string>();
  e.text = j.at("text").get<std::string>();
  e.object_id = j.at("object_id").get<uint64_t>();
  e.bearing_deg = j.at("bearing_deg").get<double>();
  e.distance_m = j.at("distance").get<double>();
  e.ttc_s = fromNullable(j.at("ttc"));
  e.audio_start_s = fromNullable(j.at("audio_start"));
  e.clock = j.value("clock", 12);
  e.closest_m = j.contains("closest") ? fromNullable(j.at("closest")) : -1.0;
  e.user_related = j.value("user_related", false);
  e.interrupts = j.value("interrupts", false);
  e.spoken_s = j.value("spoken_s", 0.0);
  if (j.contains("position_world")) {
    const auto& p = j.at("position_world");
    e.p_world = {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()};
  }
  e.language = j.value("language", std::string("en"));
  return e;
}

std::vector<FeedbackEvent> readEventsJsonl(const std::filesystem::path& path) {
  std::vector<FeedbackEvent> events;
  for (const auto& line : readContentLines(path)) {
    try {
      events.push_back(feedbackEventFromJson(nlohmann::json::parse(line.text)));
    } catch (const std::exception& e) {
      throw InputError(where(path, line.number),
                       std::string("not an events.jsonl message: ") + e.what());
    }
  }
  return events;
}

}  // namespace dynanav
