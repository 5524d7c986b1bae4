#pragma once
// Step 9 of the per-frame story (DESIGN.md §1), hazards -> messages: the wearer's body frame from
// the camera pose, each tracked object's hazard in it, and the message policy. Values in (the
// frame's stamp, camera pose and tracked objects), values out (the messages that start on this
// frame; the audio stage later fills their audio_start_s). Deterministic: no clocks, no threads.
#include <vector>

#include "assist/body_frame.hpp"
#include "assist/hazard.hpp"
#include "assist/message_policy.hpp"
#include "core/config/assist.hpp"
#include "core/feedback_event.hpp"
#include "core/tracked_object.hpp"

namespace dynanav {

struct FeedbackInput {
  double stamp_s = 0.0;
  const SE3& T_world_camera;
  bool tracked = false;  ///< pose valid: without it there is no body frame, so no hazards
  const std::vector<TrackedObject>& objects;
};

class FeedbackStage {
 public:
  /// InputError when config.language is not "en" or "de".
  explicit FeedbackStage(const AssistConfig& config);
  std::vector<FeedbackEvent> process(const FeedbackInput& input);
  /// This frame's hazards (for viz and tests).
  [[nodiscard]] const std::vector<Hazard>& hazards() const { return hazards_; }
  [[nodiscard]] const BodyFrame& body() const { return body_.current(); }

 private:
  AssistConfig config_;
  BodyFrameTracker body_;
  MotionHistory history_;
  MessagePolicy policy_;
  std::vector<Hazard> hazards_;
};

}  // namespace dynanav
