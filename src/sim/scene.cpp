#include "sim/scene.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav::sim {

Mat3 cameraRotation(double yaw, double pitch, double roll) {
  const Vec3 forward(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                     std::cos(yaw) * std::cos(pitch));
  const Vec3 right0 = forward.cross(Vec3::UnitY()).normalized();  // room y is up
  const Vec3 down0 = forward.cross(right0);
  // Roll turns the image clockwise for positive angles (right side dips).
  const Vec3 right = std::cos(roll) * right0 + std::sin(roll) * down0;
  const Vec3 down = -std::sin(roll) * right0 + std::cos(roll) * down0;
  Mat3 R;
  R << right, down, forward;
  return R;
}

HeadTurnAngles headTurnAngles(const std::vector<HeadTurn>& turns, double t) {
  HeadTurnAngles sum;
  for (const HeadTurn& turn : turns) {
    const double tau = std::clamp((t - turn.start_s) / turn.duration_s, 0.0, 1.0);
    const double share = tau - std::sin(2.0 * M_PI * tau) / (2.0 * M_PI);
    sum.yaw_rad += share * turn.yaw_rad;
    sum.pitch_rad += share * turn.pitch_rad;
  }
  return sum;
}

double headTurnPeakRate(double angle_rad, double duration_s) {
  return 2.0 * std::abs(angle_rad) / duration_s;
}

SE3 Scene::T_room_camera(double t) const {
  const MotionState st = wearer.at(t);
  const HeadMotion& h = head;
  // Sway grows with walking speed; the stride phase follows the distance walked (as for people).
  const double amount = std::min(1.0, st.velocity.norm() / h.nominal_speed_mps);
  const double phase = 2.0 * M_PI * st.distance_m / 1.4;
  const double look =
      h.look_around_rad * std::sin(2.0 * M_PI * t / h.look_period_s) +
      0.4 * h.look_around_rad * std::sin(2.0 * M_PI * t / (0.37 * h.look_period_s) + 1.0);
  const HeadTurnAngles turned = headTurnAngles(h.turns, t);
  const double yaw = st.heading_rad + h.yaw_offset_rad + turned.yaw_rad + look +
                     amount * h.yaw_sway_rad * std::sin(phase);
  const double pitch = h.pitch_rad + turned.pitch_rad +
                       amount * h.pitch_sway_rad * std::sin(2.0 * phase) +
                       0.3 * h.look_around_rad * std::sin(2.0 * M_PI * t / (1.3 * h.look_period_s));
  const double roll = amount * h.roll_sway_rad * std::sin(phase + 0.5);
  const Vec3 left_of_path(std::cos(st.heading_rad), 0.0, -std::sin(st.heading_rad));
  // Head breathing when standing keeps a little motion in every frame.
  const double breathe = 0.003 * std::sin(2.0 * M_PI * t / 4.0);
  SE3 T = SE3::Identity();
  T.linear() = cameraRotation(yaw, pitch, roll);
  T.translation() =
      Vec3(st.position.x(), h.eye_height_m + breathe + amount * h.bob_m * std::cos(2.0 * phase),
           st.position.y()) +
      left_of_path * (amount * h.sway_m * std::sin(phase));
  return T;
}

Vec3 Scene::moverCentre(const Mover& m, double t) const {
  const MotionState st = m.motion.at(t);
  return {st.position.x(), m.centre_height_m, st.position.y()};
}

Vec3 Scene::moverVelocity(const Mover& m, double t) const {
  const MotionState st = m.motion.at(t);
  return {st.velocity.x(), 0.0, st.velocity.y()};
}

void Scene::drawItems(double t, std::vector<DrawItem>& out) const {
  out.clear();
  out.push_back({&world.static_mesh, Pose3f::Identity(), 0});
  for (const Mover& m : movers) {
    const MotionState st = m.motion.at(t);
    if (m.person) {
      BodyPose pose;
      pose.position = st.position;
      pose.heading_rad = st.heading_rad;
      pose.distance_m = st.distance_m;
      pose.walking = std::min(1.0, st.velocity.norm() / 1.0);
      pose.pushing = t >= m.pushing_from && t <= m.pushing_to;
      m.person->draw(pose, m.id, out);
    } else if (m.mesh) {
      Pose3f T = Pose3f::Identity();
      T.linear() = Eigen::AngleAxisf(float(st.heading_rad), Vec3f::UnitY()).toRotationMatrix();
      T.translation() = Vec3f(float(st.position.x()), 0.0f, float(st.position.y()));
      out.push_back({m.mesh, T, m.id});
    }
  }
}

}  // namespace dynanav::sim
