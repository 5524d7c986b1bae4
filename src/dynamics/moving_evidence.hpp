#pragma once
// A keypoint's depth test is one noisy vote; the map point it matched keeps the votes of every
// frame as the log-odds that it lies on something that moves (issue 18: "a point's verdict
// accumulated over frames, not a one-frame vote"). A background point checked static in many
// frames then survives one failure (a fast head turn's misregistration), while a point that
// failed before stays suspect in frames where the test cannot check it or it happens to pass
// (a person the detector missed, walking along the viewing ray).
//
// The stored value is the evidence only; the prior is added when deciding, so a changed prior
// applies to points already in the map. Applies to keypoints outside instance masks: inside a
// mask the instance's vote decides for all its keypoints (depth_difference.hpp).
#include <vector>

#include "core/config/dynamics.hpp"

namespace dynanav {

/// One frame's depth-test outcome for a keypoint matched to a map point.
enum class DepthVote { kNone, kStatic, kMoving };

/// Evidence after one more vote, clamped to [moving_evidence_min, moving_evidence_max].
float addMovingEvidence(float evidence, DepthVote vote, const DynamicsConfig& config);

/// Moving when prior plus evidence is positive (probability above one half).
bool movingByEvidence(float evidence, const DynamicsConfig& config);

/// Per keypoint: its vote this frame, and the evidence its map point carried (NaN = no map
/// point). Returns the evidence to store (NaN where there is no map point) and, in `moving`,
/// the decision per keypoint (keypoints without a map point: their vote alone).
std::vector<float> fuseMovingEvidence(const std::vector<DepthVote>& votes,
                                      const std::vector<float>& evidence_before,
                                      const DynamicsConfig& config, std::vector<bool>& moving);

}  // namespace dynanav
