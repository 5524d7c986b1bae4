#pragma once
// Scripted motion on the floor plane (room frame: x, z horizontal, y up). Paths are polylines
// whose corners are rounded by circular arcs, parameterised by arc length, so positions,
// velocities and headings are exact and smooth (yaw rate = speed / corner radius).
#include <Eigen/Core>
#include <vector>

namespace dynanav::sim {

using Vec2 = Eigen::Vector2d;  ///< (x, z) on the floor

class SmoothPath {
 public:
  SmoothPath() = default;
  /// Corners are rounded with `corner_radius_m`, reduced where segments are too short for it.
  SmoothPath(const std::vector<Vec2>& waypoints, double corner_radius_m);

  [[nodiscard]] double length() const { return length_; }
  [[nodiscard]] Vec2 point(double s) const;    ///< s clamped to [0, length]
  [[nodiscard]] Vec2 tangent(double s) const;  ///< unit direction of travel
  [[nodiscard]] Vec2 start() const { return point(0.0); }
  [[nodiscard]] Vec2 end() const { return point(length_); }

 private:
  struct Segment {
    bool arc = false;
    double s0 = 0.0, length = 0.0;
    Vec2 p0 = Vec2::Zero(), dir = Vec2::Zero();     // line
    Vec2 centre = Vec2::Zero();                     // arc
    double radius = 0.0, angle0 = 0.0, turn = 1.0;  // turn: +1 counter-clockwise in (x, z)
  };
  [[nodiscard]] const Segment& find(double s) const;
  std::vector<Segment> segments_;
  double length_ = 0.0;
};

/// Where an actor is and how it moves at one instant (room frame).
struct MotionState {
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();  ///< m/s, exact derivative of position
  double heading_rad = 0.0;      ///< facing direction: (sin h, cos h) in (x, z)
  double distance_m = 0.0;       ///< walked so far (drives the gait phase)
  bool moving = false;
};

/// A sequence of legs: wait, or walk along a path at a cruise speed with optional speed ramps.
class Motion {
 public:
  explicit Motion(const Vec2& start, double heading_rad = 0.0)
      : start_(start), heading0_(heading_rad) {}
  Motion& wait(double seconds);
  /// Walks `path` (which should start where the previous leg ended) at `speed_mps`; the speed
  /// ramps linearly up and down over `ramp_s` at both ends (0 = constant speed throughout).
  Motion& walk(const SmoothPath& path, double speed_mps, double ramp_s = 0.0);
  /// Turning the body towards a new direction takes this long (visual only: velocity is exact).
  Motion& turnTime(double seconds) {
    turn_s_ = seconds;
    return *this;
  }

  [[nodiscard]] MotionState at(double t) const;
  [[nodiscard]] double endTime() const;
  /// The cruise speed of the walk leg active at t (0 when waiting).
  [[nodiscard]] double scriptedSpeed(double t) const;

 private:
  struct Leg {
    double t0 = 0.0, duration = 0.0;
    bool walking = false;
    SmoothPath path;
    double speed = 0.0, ramp = 0.0;
    double distance0 = 0.0;
  };
  [[nodiscard]] const Leg* find(double t) const;
  Vec2 start_;
  double heading0_;
  double turn_s_ = 0.6;
  std::vector<Leg> legs_;
};

}  // namespace dynanav::sim
