#pragma once
// A scenario's world at any instant: the static rooms, the movers (people and pushed boxes)
// with their scripted motion, and the wearer's head-worn camera. All in the room frame
// (x, z floor, y up); the simulator turns it into the first-camera world frame.
#include <memory>
#include <string>
#include <vector>

#include "core/se3.hpp"
#include "sim/path.hpp"
#include "sim/person.hpp"
#include "sim/world.hpp"

namespace dynanav::sim {

/// A moving object with ground truth. Its instance id is stable over the sequence.
struct Mover {
  uint16_t id = 0;
  std::string cls;  ///< "person" or "box"
  Motion motion{Vec2::Zero()};
  const Person* person = nullptr;  ///< set for people
  const Mesh* mesh = nullptr;      ///< set for rigid objects (mesh origin on the floor)
  double centre_height_m = 0.0;    ///< reported centre above the floor (torso centre, box centre)
  double pushing_from = 1e9, pushing_to = -1e9;  ///< people: arms forward in this time window
};

/// A scripted head movement (issue 18): over [start_s, start_s + duration_s] the head turns by
/// yaw_rad (added to the heading, same sense) and pitches by pitch_rad (positive: up) with a
/// raised-cosine rate, angle(tau) = A (tau - sin(2 pi tau) / (2 pi)), tau = (t - start_s) /
/// duration_s: the rate starts and ends at zero (no jerk into a turn) and peaks at 2 A / duration_s
/// mid-way. After the movement the head keeps the new direction.
struct HeadTurn {
  double start_s = 0.0;
  double duration_s = 1.0;
  double yaw_rad = 0.0;
  double pitch_rad = 0.0;
};

/// Yaw and pitch (rad) that the turns have added by time t, summed over every turn.
struct HeadTurnAngles {
  double yaw_rad = 0.0;
  double pitch_rad = 0.0;
};
HeadTurnAngles headTurnAngles(const std::vector<HeadTurn>& turns, double t);
/// Peak rate (rad/s) of a turn of `angle_rad` over `duration_s` (2 A / D).
double headTurnPeakRate(double angle_rad, double duration_s);

/// How the wearer's head moves on top of the walked path.
struct HeadMotion {
  double eye_height_m = 1.6;
  double pitch_rad = -0.14;       ///< looking slightly down, as head-worn cameras do
  double bob_m = 0.02;            ///< vertical, twice per stride
  double sway_m = 0.015;          ///< lateral, once per stride
  double yaw_sway_rad = 0.015;    ///< once per stride
  double pitch_sway_rad = 0.012;  ///< twice per stride
  double roll_sway_rad = 0.012;   ///< once per stride
  double look_around_rad = 0.05;  ///< slow yaw wander (period look_period_s)
  double look_period_s = 7.0;
  double nominal_speed_mps = 1.0;  ///< speed at which the sway amplitudes apply in full
  double yaw_offset_rad = 0.0;     ///< the head turned this far right of the walking direction
  std::vector<HeadTurn> turns;     ///< fast head turns and nods on top of the sway (issue 18)
};

class Scene {
 public:
  World world;
  std::vector<std::unique_ptr<Person>> people;
  std::vector<std::unique_ptr<Mesh>> rigid_meshes;
  std::vector<Mover> movers;
  Motion wearer{Vec2::Zero()};
  HeadMotion head;
  double duration_s = 10.0;  ///< default length of the sequence

  /// Camera-to-room pose at time t (camera x right, y down, z forward).
  [[nodiscard]] SE3 T_room_camera(double t) const;
  /// Everything to draw at time t.
  void drawItems(double t, std::vector<DrawItem>& out) const;
  /// A mover's centre (room frame) and its velocity at t.
  [[nodiscard]] Vec3 moverCentre(const Mover& m, double t) const;
  [[nodiscard]] Vec3 moverVelocity(const Mover& m, double t) const;
};

/// Camera rotation (columns: camera x right, y down, z forward in the room frame) looking along
/// heading `yaw` (forward = (sin yaw, 0, cos yaw)) with `pitch` up and `roll` about the view axis.
Mat3 cameraRotation(double yaw_rad, double pitch_rad, double roll_rad);

}  // namespace dynanav::sim
