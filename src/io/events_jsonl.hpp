#pragma once
// events.jsonl (DESIGN.md §2): one line per message, {"t", "priority", "kind", "text",
// "object_id", "bearing_deg", "distance", "ttc", "audio_start"}; "ttc" and "audio_start" are null
// when there is none (< 0 in FeedbackEvent). Keys beyond DESIGN.md's: "clock", "closest"
// (predicted closest-approach distance, null when not approaching), "user_related",
// "interrupts", "spoken_s" (estimated length), "position_world" (the object's centre) and
// "language". Numbers are rounded to 6 decimals (files compare byte for byte between runs).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/feedback_event.hpp"
#include "io/json_io.hpp"

namespace dynanav {

const char* priorityName(FeedbackPriority priority);
/// "urgent" | "advisory" | "info"; std::invalid_argument otherwise.
FeedbackPriority priorityFromName(const std::string& name);

nlohmann::json toJson(const FeedbackEvent& event);
/// Inverse of toJson; throws (nlohmann::json::exception, std::invalid_argument) on a missing
/// DESIGN.md key or a bad value. Extra keys are optional.
FeedbackEvent feedbackEventFromJson(const nlohmann::json& json);

/// Writes one line per message, flushed (an interrupted run leaves a valid file).
class EventsWriter {
 public:
  explicit EventsWriter(const std::filesystem::path& path) : lines_(path) {}
  void write(const FeedbackEvent& event) { lines_.write(toJson(event)); }

 private:
  JsonLinesWriter lines_;
};

/// Reads an events.jsonl; InputError naming file and line when malformed.
std::vector<FeedbackEvent> readEventsJsonl(const std::filesystem::path& path);

}  // namespace dynanav
