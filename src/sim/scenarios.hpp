#pragma once
// The named scenarios of `dynanav simulate` (issue 5). Each is deterministic for a seed: the
// seed draws textures, clothing and body sizes; the choreography itself is fixed, so tests can
// rely on the scripted speeds and distances listed here.
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
constexpr double kCrossingSpeedMps = 1.4;  ///< crossing: the walker's speed
constexpr double kCrossingAheadM = 2.0;    ///< crossing: wearer-to-path distance at the crossing
constexpr double kApproachSpeedMps = 1.0;  ///< approach: the walker's speed
constexpr double kPushSpeedMps = 0.5;      ///< pushed-box: the box's speed while pushed
constexpr double kPushDistanceM = 1.0;     ///< pushed-box: how far the box moves
constexpr double kLoopMinLengthM = 15.0;   ///< loop: the wearer's path is at least this long
}  // namespace script

}  // namespace dynanav::sim
