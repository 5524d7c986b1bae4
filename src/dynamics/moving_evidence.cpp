#include "dynamics/moving_evidence.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {

float addMovingEvidence(float evidence, DepthVote vote, const DynamicsConfig& config) {
  double e = evidence;
  if (vote == DepthVote::kMoving) e += config.moving_vote_log_odds;
  if (vote == DepthVote::kStatic) e -= config.static_vote_log_odds;
  return static_cast<float>(std::clamp(e, config.moving_evidence_min, config.moving_evidence_max));
}

bool movingByEvidence(float evidence, const DynamicsConfig& config) {
  return config.moving_prior_log_odds + evidence > 0.0;
}

std::vector<float> fuseMovingEvidence(const std::vector<DepthVote>& votes,
                                      const std::vector<float>& evidence_before,
                                      const DynamicsConfig& config, std::vector<bool>& moving) {
  std::vector<float> evidence_after(votes.size(), std::nanf(""));
  moving.assign(votes.size(), false);
  for (size_t i = 0; i < votes.size(); ++i) {
    const bool mapped = i < evidence_before.size() && !std::isnan(evidence_before[i]);
    if (!mapped) {
      moving[i] = votes[i] == DepthVote::kMoving;
      continue;
    }
    evidence_after[i] = addMovingEvidence(evidence_before[i], votes[i], config);
    moving[i] = movingByEvidence(evidence_after[i], config);
  }
  return evidence_after;
}

}  // namespace dynanav
