#include "assist/feedback_stage.hpp"

#include <spdlog/spdlog.h>

namespace dynanav {

FeedbackStage::FeedbackStage(const AssistConfig& config)
    : config_(config),
      body_(config),
      history_(config),
      policy_(config, parseLanguage(config.language, "assist.language")) {}

std::vector<FeedbackEvent> FeedbackStage::process(const FeedbackInput& input) {
  const BodyFrame& body = body_.update(input.stamp_s, input.T_world_camera, input.tracked);
  hazards_.clear();
  // Lost tracking: object positions are not placed in the world; say nothing new until the pose
  // is back (waiting messages are dropped as their conditions no longer hold).
  if (input.tracked && body.valid) {
    const std::vector<GroundMotion> motions = history_.update(input.stamp_s, input.objects);
    for (size_t i = 0; i < input.objects.size(); ++i)
      hazards_.push_back(assessHazard(input.objects[i], motions[i], body, config_));
  }
  for (const Hazard& h : hazards_)  // SPDLOG_LEVEL=debug: why a message was (not) raised
    if (h.moving || h.distance_m <= config_.near_person_m)
      spdlog::debug(
          "t {:.3f} object {} {:.2f} m at {:.0f} deg, closing {:.2f} m/s, closest {:.2f} m "
          "(sigma {:.2f}, inside the corridor with p {:.2f}) in {:.2f} s, ttc {:.2f} / warn {:.2f} "
          "s, "
          "user-related {}",
          input.stamp_s, h.object_id, h.distance_m, h.bearing_deg, h.closing_mps, h.closest_m,
          h.closest_sigma_m, h.corridor_probability, h.t_closest_s, h.ttc_s, h.ttc_warn_s,
          h.user_related);
  return policy_.step(input.stamp_s, hazards_);
}

}  // namespace dynanav
