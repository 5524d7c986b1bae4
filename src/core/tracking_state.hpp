#pragma once
// The tracking state every front end sees (FrameResult) and slam's tracker drives.
namespace dynanav {

enum class TrackingState { kNotInitialised, kOk, kLost };

inline const char* toString(TrackingState state) {
  switch (state) {
    case TrackingState::kNotInitialised:
      return "not_initialised";
    case TrackingState::kOk:
      return "ok";
    case TrackingState::kLost:
      return "lost";
  }
  return "?";
}

}  // namespace dynanav
