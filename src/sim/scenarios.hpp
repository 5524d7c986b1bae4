#pragma once
// The named scenarios of `dynanav simulate` (issue 5). Each is deterministic for a seed: the
// seed draws textures, clothing and body sizes; the choreography itself is fixed, so tests can
// rely on the scripted speeds and distances listed here. `approach` also draws its choreography
// from the seed (approachScript(): speeds, side offset, start), so seeds 1-10 are ten different
// encounters (issue 14's warning-time test).
#include <memory>
#include <string>
#include <vector>

#include "sim/scene.hpp"

namespace dynanav::sim {

struct ScenarioInfo {
  std::string name;
  std::string description;
};

/// All scenario names with a one-line description, in a fixed order.
const std::vector<ScenarioInfo>& scenarioList();

/// Builds a scenario; throws InputError naming the valid scenarios for an unknown name.
/// `texels_per_m` sets the texture resolution (lower builds faster; tests of motion use that).
std::unique_ptr<Scene> buildScenario(const std::string& name, uint64_t seed,
                                     const PhotoLibrary& photos, float texels_per_m = 200.0f);

/// Scripted figures the tests check the ground truth against.
namespace script {
constexpr double kCrossingSpeedMps = 1.4;    ///< crossing: the walker's speed
constexpr double kCrossingAheadM = 2.0;      ///< crossing: wearer-to-path distance at the crossing
constexpr double kApproachSpeedMps = 1.0;    ///< approach: the walker's mean speed over seeds
constexpr double kPushSpeedMps = 0.5;        ///< pushed-box: the box's speed while pushed
constexpr double kPushDistanceM = 1.0;       ///< pushed-box: how far the box moves
constexpr double kLoopMinLengthM = 15.0;     ///< loop: the wearer's path is at least this long
constexpr double kNearCrossingAheadM = 0.5;  ///< crossing-near: wearer-to-path distance then
constexpr double kParallelOffsetM = 3.0;     ///< parallel: lateral distance of the walker's line
constexpr double kAwaySpeedMps = 1.3;        ///< walking-away: the walker's speed
constexpr double kHeadTurnPeakYawDegPs = 150.0;  ///< head-turns: peak yaw rate of the turns
constexpr double kHeadNodPeakDegPs = 100.0;      ///< head-turns: peak pitch rate of the nods
constexpr double kOfficeRampS = 0.6;  ///< office-ramped: each walker's speed-up and slow-down
}  // namespace script

/// The head movements of `head-turns` and `head-turns-walkers` (issue 18): yaw turns of 60 and
/// 120 deg at up to kHeadTurnPeakYawDegPs, nods of 15-20 deg at up to kHeadNodPeakDegPs, from
/// t = 1.5 s (after the SLAM has started) to 9.5 s, on top of a slow straight walk (0.35 m/s)
/// through static-room's furniture.
std::vector<HeadTurn> headTurnScript();

/// The approach encounter a seed draws (an independent stream: textures do not change with it).
struct ApproachScript {
  double walker_speed_mps = 1.0;  ///< in [0.8, 1.2]
  double wearer_speed_mps = 0.8;  ///< in [0.7, 0.9]
  double offset_m = 0.5;       ///< walker's line beside the wearer's, in [-0.6, -0.2] or [0.2, 0.6]
  double walker_wait_s = 0.5;  ///< in [0.3, 1.2]
};
ApproachScript approachScript(uint64_t seed);

}  // namespace dynanav::sim
