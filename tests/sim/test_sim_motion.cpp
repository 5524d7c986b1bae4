// Scripted motion: paths, speeds, the wearer's camera, and the ground truth built from them.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {
namespace {

SimOptions quick(const std::string& scenario) {
  SimOptions o;
  o.scenario = scenario;
  o.photos = false;
  o.texels_per_m = 40.0f;  // motion does not depend on textures: build fast
  return o;
}

TEST(SimPath, RoundedCornerHasArcLength) {
  // 4 m east, then 3 m north with a 1 m fillet: 4 + 3 - 2 * 1 + pi/2 * 1.
  const SmoothPath path({{0, 0}, {4, 0}, {4, 3}}, 1.0);
  EXPECT_NEAR(path.length(), 5.0 + M_PI / 2.0, 1e-9);
  EXPECT_NEAR((path.end() - Vec2(4, 3)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((path.point(3.0) - Vec2(3, 0)).norm(), 0.0, 1e-9);
  // Tangent continuous and unit everywhere; position derivative equals the tangent.
  for (double s = 0.01; s < path.length() - 0.01; s += 0.01) {
    const Vec2 fd = (path.point(s + 1e-6) - path.point(s - 1e-6)) / 2e-6;
    EXPECT_NEAR((fd - path.tangent(s)).norm(), 0.0, 1e-5) << s;
  }
}

TEST(SimPath, MotionRampsAndWaits) {
  Motion m({0, 0});
  m.wait(1.0).walk(SmoothPath({{0, 0}, {0, 4}}, 0.0), 1.0, 0.5);
  EXPECT_DOUBLE_EQ(m.endTime(), 1.0 + 4.0 + 0.5);
  EXPECT_EQ(m.at(0.5).velocity.norm(), 0.0);
  EXPECT_NEAR(m.at(1.25).velocity.norm(), 0.5, 1e-12);  // half way up the ramp
  EXPECT_NEAR(m.at(3.0).velocity.norm(), 1.0, 1e-12);
  EXPECT_NEAR(m.at(3.0).position.y(), 0.25 + 1.5, 1e-12);
  EXPECT_NEAR(m.at(9.0).position.y(), 4.0, 1e-12);
  EXPECT_FALSE(m.at(9.0).moving);
}

TEST(SimScenarios, VelocitiesAreDerivativesOfPositions) {
  for (const auto& info : scenarioList()) {
    Simulator sim(quick(info.name));
    const Scene& scene = sim.scene();
    for (const Mover& m : scene.movers) {
      int checked = 0, agree = 0;
      for (double t = 0.05; t < scene.duration_s; t += 0.05) {
        const Vec3 fd = (scene.moverCentre(m, t + 1e-5) - scene.moverCentre(m, t - 1e-5)) / 2e-5;
        ++checked;
        agree += (fd - scene.moverVelocity(m, t)).norm() < 1e-4;
      }
      // Only samples straddling a start or stop may differ.
      EXPECT_GE(agree, checked - 3) << info.name << " mover " << m.id;
    }
  }
}

TEST(SimScenarios, ObjectsGroundTruthSpeedsAreTheScriptedOnes) {
  Simulator crossing(quick("crossing"));
  int moving = 0;
  for (int i = 0; i < crossing.frameCount(); i += 10) {
    const auto frame = crossing.render(i);
    const auto& obj = frame.objects["objects"][0];
    if (obj["dynamic"].get<bool>()) {
      ++moving;
      EXPECT_NEAR(obj["speed"].get<double>(), script::kCrossingSpeedMps, 1e-6);
      const auto v = obj["velocity_world"];
      EXPECT_NEAR(std::hypot(double(v[0]), double(v[1]), double(v[2])), script::kCrossingSpeedMps,
                  1e-5);
    } else {
      EXPECT_EQ(obj["speed"].get<double>(), 0.0);
    }
  }
  EXPECT_GT(moving, 6);

  Simulator approach(quick("approach"));
  const auto mid = approach.render(90);
  EXPECT_NEAR(mid.objects["objects"][0]["speed"].get<double>(),
              approachScript(approach.options().seed).walker_speed_mps, 1e-6);
}

TEST(SimScenarios, CrossingPassesTwoMetresAhead) {
  // When the walker is on the wearer's line of travel, the wearer is kCrossingAheadM behind.
  Simulator sim(quick("crossing"));
  const Scene& scene = sim.scene();
  const Mover& walker = scene.movers.at(0);
  const double x_line = scene.wearer.at(0.0).position.x();
  double best = 1e9, t_cross = 0;
  for (double t = 0; t < scene.duration_s; t += 0.001) {
    const double dx = std::abs(walker.motion.at(t).position.x() - x_line);
    if (dx < best) best = dx, t_cross = t;
  }
  EXPECT_LT(best, 0.002);
  const double ahead =
      walker.motion.at(t_cross).position.y() - scene.wearer.at(t_cross).position.y();
  EXPECT_NEAR(ahead, script::kCrossingAheadM, 0.01);
  EXPECT_NEAR(walker.motion.scriptedSpeed(t_cross), script::kCrossingSpeedMps, 1e-12);
}

/// Closest ground distance (m) between the first mover and the wearer, and when (s).
std::pair<double, double> closestApproach(const Scene& scene) {
  const Mover& walker = scene.movers.at(0);
  double best = 1e9, t_best = 0.0;
  for (double t = 0; t < scene.duration_s; t += 0.005) {
    const double d = (walker.motion.at(t).position - scene.wearer.at(t).position).norm();
    if (d < best) best = d, t_best = t;
  }
  return {best, t_best};
}

TEST(SimScenarios, ApproachEncounterVariesWithTheSeed) {
  std::vector<double> speeds;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const ApproachScript a = approachScript(seed);
    EXPECT_GE(a.walker_speed_mps, 0.8);
    EXPECT_LE(a.walker_speed_mps, 1.2);
    EXPECT_GE(std::abs(a.offset_m), 0.2);
    EXPECT_LE(std::abs(a.offset_m), 0.6);
    speeds.push_back(a.walker_speed_mps);
    SimOptions o = quick("approach");
    o.seed = seed;
    Simulator sim(o);
    const auto [closest, at] = closestApproach(sim.scene());
    EXPECT_NEAR(closest, std::abs(a.offset_m), 0.01) << seed;  // head-on, offset aside
    EXPECT_GE(sim.scene().duration_s, at + 1.9) << "the scene covers the closest approach";
    EXPECT_EQ(approachScript(seed).walker_speed_mps, a.walker_speed_mps) << "deterministic";
  }
  std::sort(speeds.begin(), speeds.end());
  EXPECT_EQ(std::unique(speeds.begin(), speeds.end()), speeds.end()) << "ten different walkers";
}

TEST(SimScenarios, FeedbackEncounters) {
  {
    Simulator sim(quick("crossing-near"));
    EXPECT_LT(closestApproach(sim.scene()).first, 0.5);  // inside the 0.8 m corridor
    Simulator far(quick("crossing"));
    EXPECT_GT(closestApproach(far.scene()).first, 1.6);  // outside it
  }
  {
    Simulator sim(quick("parallel"));
    EXPECT_NEAR(closestApproach(sim.scene()).first, script::kParallelOffsetM, 0.01);
    EXPECT_GT(sim.scene().head.yaw_offset_rad, 0.5);  // looking towards the walker's side
  }
  {
    Simulator sim(quick("walking-away"));
    const Scene& scene = sim.scene();
    double last = 0.0;
    for (double t = 0; t < scene.duration_s; t += 0.01) {
      const double d =
          (scene.movers.at(0).motion.at(t).position - scene.wearer.at(t).position).norm();
      EXPECT_GE(d, last - 1e-9) << "never closer, t = " << t;
      last = d;
    }
  }
}

TEST(SimScenarios, PushedBoxMovesOneMetreAtPushSpeed) {
  Simulator sim(quick("pushed-box"));
  const Scene& scene = sim.scene();
  const Mover* box = nullptr;
  for (const Mover& m : scene.movers)
    if (m.cls == "box") box = &m;
  ASSERT_NE(box, nullptr);
  const Vec3 start = scene.moverCentre(*box, 0.0), end = scene.moverCentre(*box, scene.duration_s);
  EXPECT_NEAR((end - start).norm(), script::kPushDistanceM, 1e-9);
  double max_speed = 0.0;
  for (double t = 0; t < scene.duration_s; t += 0.01)
    max_speed = std::max(max_speed, scene.moverVelocity(*box, t).norm());
  EXPECT_NEAR(max_speed, script::kPushSpeedMps, 1e-12);
  EXPECT_EQ(sim.masksJson()["instances"]["2"]["class"], "box");
}

TEST(SimScenarios, LoopIsLongAndReturnsToTheStart) {
  Simulator sim(quick("loop"));
  const Motion& wearer = sim.scene().wearer;
  const MotionState end = wearer.at(wearer.endTime());
  EXPECT_GE(end.distance_m, script::kLoopMinLengthM);
  // The loop comes back onto its first straight, facing the same way: a place seen twice.
  double t_first = 0;
  while (wearer.at(t_first).position.x() < 4.5) t_first += 0.01;
  const MotionState first = wearer.at(t_first);
  double closest = 1e9, heading_diff = 0;
  for (double t = wearer.endTime() * 0.8; t <= wearer.endTime(); t += 0.01) {
    const MotionState st = wearer.at(t);
    if ((st.position - first.position).norm() < closest) {
      closest = (st.position - first.position).norm();
      heading_diff = std::abs(std::remainder(st.heading_rad - first.heading_rad, 2 * M_PI));
    }
  }
  EXPECT_LT(closest, 0.02);
  EXPECT_LT(heading_diff, 0.01);
}

/// The largest change of any walker's speed (not direction) between two frames 1/30 s apart, in
/// m/s^2.
double peakWalkerAccelMps2(const std::string& scenario) {
  Simulator sim(quick(scenario));
  const Scene& scene = sim.scene();
  const double dt = 1.0 / 30.0;
  double peak = 0.0;
  for (const Mover& m : scene.movers)
    for (double t = dt; t < scene.duration_s; t += dt)
      peak = std::max(
          peak,
          std::abs(scene.moverVelocity(m, t).norm() - scene.moverVelocity(m, t - dt).norm()) / dt);
  return peak;
}

TEST(SimScenarios, OfficeRampedWalkersStartAndStopOverTheRamp) {
  // office-ramped's fastest walker (1.2 m/s) changes speed by 1.2 / 0.6 = 2 m/s^2 at most.
  EXPECT_LT(peakWalkerAccelMps2("office-ramped"), 1.2 / script::kOfficeRampS + 1e-6);
  // office switches speed within a frame: 1.2 m/s in 1/30 s.
  EXPECT_GT(peakWalkerAccelMps2("office"), 30.0);
  // The same walks otherwise: each walker ends where it ends in office.
  Simulator snap(quick("office")), ramped(quick("office-ramped"));
  ASSERT_EQ(snap.scene().movers.size(), ramped.scene().movers.size());
  for (size_t i = 0; i < snap.scene().movers.size(); ++i) {
    const Vec3 a = snap.scene().moverCentre(snap.scene().movers[i], 9.9);
    const Vec3 b = ramped.scene().moverCentre(ramped.scene().movers[i], 9.9);
    EXPECT_LT((a - b).norm(), 1e-9) << "walker " << i;
  }
}

TEST(SimCamera, FirstPoseIsIdentityAndMotionIsTrackable) {
  for (const auto& info : scenarioList()) {
    Simulator sim(quick(info.name));
    const Scene& scene = sim.scene();
    const double dt = 1.0 / sim.options().fps;
    EXPECT_TRUE(
        (sim.T_world_room() * scene.T_room_camera(sim.stamp(0))).isApprox(SE3::Identity(), 1e-12));
    double max_speed = 0, max_rate_deg = 0;
    for (int i = 1; i < sim.frameCount(); ++i) {
      const SE3 a = scene.T_room_camera(sim.stamp(i - 1)), b = scene.T_room_camera(sim.stamp(i));
      max_speed = std::max(max_speed, (b.translation() - a.translation()).norm() / dt);
      max_rate_deg = std::max(
          max_rate_deg, rotationAngle(a.linear().transpose() * b.linear()) / dt * 180.0 / M_PI);
    }
    // A head-worn camera at walking pace: no jumps, turns a feature tracker can follow (the
    // head-turns scenarios turn fast on purpose: test_sim_head_turns.cpp bounds them).
    const bool fast_turns = info.name.rfind("head-turns", 0) == 0;
    EXPECT_LT(max_speed, 1.3) << info.name;
    EXPECT_LT(max_rate_deg, fast_turns ? 160.0 : 40.0) << info.name;
    EXPECT_GT(max_speed, fast_turns ? 0.3 : 0.5) << info.name << ": the wearer walks";
  }
}

TEST(SimScenarios, UnknownScenarioNamesTheChoices) {
  try {
    Simulator sim(quick("nope"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("office"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynanav::sim
