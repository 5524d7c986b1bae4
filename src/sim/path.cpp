#include "sim/path.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynanav::sim {

namespace {
double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
double headingOf(const Vec2& dir) {
  return std::atan2(dir.x(), dir.y());
}
double wrapAngle(double a) {
  return std::remainder(a, 2.0 * M_PI);
}
}  // namespace

SmoothPath::SmoothPath(const std::vector<Vec2>& pts, double corner_radius_m) {
  if (pts.size() < 2) throw std::invalid_argument("SmoothPath needs at least two waypoints");
  // Tangent length of each corner's fillet, limited to half of each adjacent segment.
  const size_t n = pts.size();
  std::vector<double> cut(n, 0.0), radius(n, 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const Vec2 a = (pts[i] - pts[i - 1]), b = (pts[i + 1] - pts[i]);
    const double turn = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
    if (turn < 1e-6) continue;
    const double max_cut = 0.5 * std::min(a.norm(), b.norm());
    cut[i] = std::min(corner_radius_m * std::tan(turn / 2.0), max_cut);
    radius[i] = cut[i] / std::tan(turn / 2.0);
  }
  auto addLine = [&](const Vec2& p0, const Vec2& p1) {
    const double len = (p1 - p0).norm();
    if (len < 1e-9) return;
    Segment s;
    s.s0 = length_;
    s.length = len;
    s.p0 = p0;
    s.dir = (p1 - p0) / len;
    segments_.push_back(s);
    length_ += len;
  };
  Vec2 cursor = pts[0];
  for (size_t i = 1; i < n; ++i) {
    const Vec2 din = (pts[i] - pts[i - 1]).normalized();
    const Vec2 t1 = pts[i] - din * cut[i];
    addLine(cursor, t1);
    cursor = t1;
    if (i + 1 < n && cut[i] > 0.0) {
      const Vec2 dout = (pts[i + 1] - pts[i]).normalized();
      Segment s;
      s.arc = true;
      s.turn = cross(din, dout) > 0 ? 1.0 : -1.0;
      const Vec2 normal = s.turn > 0 ? Vec2(-din.y(), din.x()) : Vec2(din.y(), -din.x());
      s.radius = radius[i];
      s.centre = t1 + normal * s.radius;
      const Vec2 r0 = t1 - s.centre;
      s.angle0 = std::atan2(r0.y(), r0.x());
      const double sweep = std::acos(std::clamp(din.dot(dout), -1.0, 1.0));
      s.s0 = length_;
      s.length = sweep * s.radius;
      segments_.push_back(s);
      length_ += s.length;
      cursor = pts[i] + dout * cut[i];
    }
  }
}

const SmoothPath::Segment& SmoothPath::find(double s) const {
  for (const Segment& seg : segments_)
    if (s <= seg.s0 + seg.length) return seg;
  return segments_.back();
}

Vec2 SmoothPath::point(double s) const {
  s = std::clamp(s, 0.0, length_);
  const Segment& seg = find(s);
  const double d = s - seg.s0;
  if (!seg.arc) return seg.p0 + seg.dir * d;
  const double a = seg.angle0 + seg.turn * d / seg.radius;
  return seg.centre + seg.radius * Vec2(std::cos(a), std::sin(a));
}

Vec2 SmoothPath::tangent(double s) const {
  s = std::clamp(s, 0.0, length_);
  const Segment& seg = find(s);
  if (!seg.arc) return seg.dir;
  const double a = seg.angle0 + seg.turn * (s - seg.s0) / seg.radius;
  return seg.turn * Vec2(-std::sin(a), std::cos(a));
}

Motion& Motion::wait(double seconds) {
  Leg leg;
  leg.t0 = endTime();
  leg.duration = seconds;
  leg.distance0 = legs_.empty() ? 0.0
                                : legs_.back().distance0 +
                                      (legs_.back().walking ? legs_.back().path.length() : 0.0);
  legs_.push_back(leg);
  return *this;
}

Motion& Motion::walk(const SmoothPath& path, double speed_mps, double ramp_s) {
  Leg leg;
  leg.t0 = endTime();
  leg.walking = true;
  leg.path = path;
  leg.speed = speed_mps;
  leg.ramp = std::min(ramp_s, path.length() / speed_mps);  // trapezoid needs L >= v * ramp
  leg.duration = path.length() / speed_mps + leg.ramp;
  leg.distance0 = legs_.empty() ? 0.0
                                : legs_.back().distance0 +
                                      (legs_.back().walking ? legs_.back().path.length() : 0.0);
  legs_.push_back(leg);
  return *this;
}

double Motion::endTime() const {
  return legs_.empty() ? 0.0 : legs_.back().t0 + legs_.back().duration;
}

const Motion::Leg* Motion::find(double t) const {
  const Leg* found = nullptr;
  for (const Leg& leg : legs_)
    if (t >= leg.t0) found = &leg;
  return found;
}

double Motion::scriptedSpeed(double t) const {
  const Leg* leg = find(t);
  return leg && leg->walking && t < leg->t0 + leg->duration ? leg->speed : 0.0;
}

MotionState Motion::at(double t) const {
  MotionState st;
  st.position = start_;
  st.heading_rad = heading0_;
  double prev_heading = heading0_;
  // Walk the legs up to t; positions and headings carry over from finished legs.
  for (const Leg& leg : legs_) {
    if (t < leg.t0) break;
    if (!leg.walking) {
      st.velocity.setZero();
      st.moving = false;
      continue;
    }
    const double tau = std::min(t - leg.t0, leg.duration);
    const double v = leg.speed, T = leg.duration, R = leg.ramp, L = leg.path.length();
    double s = 0.0, speed = 0.0;
    if (R <= 0.0) {
      s = v * tau;
      speed = v;
    } else if (tau < R) {
      s = v * tau * tau / (2.0 * R);
      speed = v * tau / R;
    } else if (tau <= T - R) {
      s = v * R / 2.0 + v * (tau - R);
      speed = v;
    } else {
      s = L - v * (T - tau) * (T - tau) / (2.0 * R);
      speed = v * (T - tau) / R;
    }
    const bool finished = t >= leg.t0 + leg.duration;
    if (finished) speed = 0.0;
    const Vec2 dir = leg.path.tangent(s);
    st.position = leg.path.point(s);
    st.velocity = dir * speed;
    st.distance_m = leg.distance0 + std::min(s, L);
    st.moving = speed > 0.0;
    // The body turns towards the new direction over turn_s_ (only how it looks).
    const double target = headingOf(dir);
    const double blend = std::clamp(tau / turn_s_, 0.0, 1.0);
    st.heading_rad = prev_heading + blend * wrapAngle(target - prev_heading);
    prev_heading = headingOf(leg.path.tangent(L));
  }
  return st;
}

}  // namespace dynanav::sim
