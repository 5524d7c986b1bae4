#include "assist/body_frame.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav {
namespace {

/// Unit vector of `v`, or `fallback` when `v` is (nearly) zero.
Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > 1e-9 ? Vec3(v / n) : fallback;
}

}  // namespace

const BodyFrame& BodyFrameTracker::update(double stamp_s, const SE3& T_world_camera, bool tracked) {
  if (!tracked) return body_;
  const Vec3 origin = T_world_camera.translation();
  if (body_.valid) {
    const double dt = stamp_s - last_stamp_s_;
    if (dt > 0.0) {
      // Exponential smoothing with time constant tau: the weight of a new sample grows with the
      // time it covers, so the result does not depend on the frame rate.
      const Vec3 v_now = horizontal(origin - last_origin_world_) / dt;
      const double alpha = 1.0 - std::exp(-dt / config_.heading_smoothing_s);
      body_.velocity_world_mps += alpha * (v_now - body_.velocity_world_mps);
    }
  }
  last_stamp_s_ = stamp_s;
  last_origin_world_ = origin;
  body_.origin_world = origin;
  body_.walking = body_.velocity_world_mps.norm() >= config_.walking_speed_mps;
  const Vec3 camera_forward = horizontal(T_world_camera.rotation() * Vec3::UnitZ());
  const Vec3 facing = unitOr(camera_forward, body_.forward_world);
  body_.forward_world = body_.walking ? unitOr(body_.velocity_world_mps, facing) : facing;
  // Right = down x forward (camera convention: x = y x z with y down).
  body_.right_world = Vec3::UnitY().cross(body_.forward_world).normalized();
  body_.valid = true;
  return body_;
}

}  // namespace dynanav
