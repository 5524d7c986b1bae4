#pragma once
// An articulated walker with human proportions: a head (face, hair), neck, shaped torso and
// pelvis, upper arms, forearms with hands, thighs, shins and feet, each a smooth lathe mesh
// (elliptic cross-sections, per-vertex normals) hinged at shoulders, elbows, hips and knees.
// The gait phase follows the distance walked, so feet keep pace with the ground whatever the
// speed; arms swing against the legs; standing still brings the limbs to rest.
#include <array>
#include <memory>
#include <vector>

#include "sim/mesh.hpp"
#include "sim/path.hpp"
#include "sim/world.hpp"

namespace dynanav::sim {

struct BodyPose {
  Vec2 position = Vec2::Zero();  ///< on the floor (room frame x, z)
  double heading_rad = 0.0;
  double distance_m = 0.0;  ///< walked so far: sets the gait phase
  double walking = 0.0;     ///< 0 standing .. 1 full stride
  bool pushing = false;     ///< arms held forward (pushing a box)
};

class Person {
 public:
  /// Builds the body parts with fresh skin, hair and clothing textures in `world`.
  Person(World& world, Rng& rng, float texels_per_m);

  /// The body's parts for one frame, tagged with `instance_id`.
  void draw(const BodyPose& pose, uint16_t instance_id, std::vector<DrawItem>& out) const;
  /// Height of the torso centre above the floor: the point objects_gt.jsonl reports.
  [[nodiscard]] double torsoCentreHeight() const { return 1.17 * scale_; }

 private:
  enum Part {
    kBody,  ///< torso, pelvis, neck and head: one rigid piece
    kUpperArmL,
    kUpperArmR,
    kForearmL,  ///< with the hand
    kForearmR,
    kThighL,
    kThighR,
    kShinL,
    kShinR,
    kFootL,
    kFootR,
    kParts
  };
  std::array<std::unique_ptr<Mesh>, kParts> parts_;
  double scale_ = 1.0;
};

}  // namespace dynanav::sim
