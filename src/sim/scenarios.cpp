#include "sim/scenarios.hpp"

#include <cmath>
#include <functional>
#include <map>

#include "core/error.hpp"

namespace dynanav::sim {

namespace {
constexpr double kPi = M_PI;
constexpr double kNorth = 0.0, kEast = kPi / 2, kSouth = kPi, kWest = -kPi / 2;  // yaw of a front
// (In the room frame, yaw 0 faces +z and yaw +90 deg faces +x.)

SmoothPath line(const Vec2& a, const Vec2& b) {
  return SmoothPath({a, b}, 0.0);
}
double headingOf(const Vec2& d) {
  return std::atan2(d.x(), d.y());
}

/// Shared set-up: the scene, its world builder and the helpers that add movers.
struct Stage {
  std::unique_ptr<Scene> scene = std::make_unique<Scene>();
  Rng rng;
  WorldBuilder build;
  uint64_t seed;
  Stage(uint64_t seed_, const PhotoLibrary& photos, float tpm)
      : rng(seed_), build(scene->world, rng, photos, tpm), seed(seed_) {}

  Mover& person(uint16_t id, const Motion& motion) {
    scene->people.push_back(std::make_unique<Person>(scene->world, rng, build.texelsPerMetre()));
    Mover m;
    m.id = id;
    m.cls = "person";
    m.motion = motion;
    m.person = scene->people.back().get();
    m.centre_height_m = m.person->torsoCentreHeight();
    scene->movers.push_back(m);
    return scene->movers.back();
  }
  /// A carton (size: width, height, depth in metres) whose mesh stands on the floor.
  Mover& box(uint16_t id, const Motion& motion, const Vec3f& size_m) {
    auto mesh = std::make_unique<Mesh>();
    const float tpm = build.texelsPerMetre();
    const int tex =
        build.texture(cardboard(cv::Size(int(2 * size_m.x() * tpm), int(size_m.y() * tpm)), rng));
    mesh->addBox(Vec3f(0, size_m.y() / 2, 0), size_m, tex, tpm, 0.0f);
    Mover m;
    m.id = id;
    m.cls = "box";
    m.motion = motion;
    m.mesh = mesh.get();
    m.centre_height_m = size_m.y() / 2;
    scene->rigid_meshes.push_back(std::move(mesh));
    scene->movers.push_back(m);
    return scene->movers.back();
  }
  /// The wearer stands still for `wait_s` (so SLAM can initialise), then walks.
  void wearer(const std::vector<Vec2>& waypoints, double speed_mps, double corner_radius_m,
              double wait_s = 0.5) {
    const SmoothPath path(waypoints, corner_radius_m);
    scene->wearer = Motion(path.start(), headingOf(path.tangent(0.0)));
    scene->wearer.wait(wait_s).walk(path, speed_mps, 1.0);
  }
};

/// An office 7 x 9 m: desks behind cubicle partitions, shelves, a pillar, doors. Movers keep to
/// the aisles; enough surfaces stay within the depth sensor's 4.5 m wherever the wearer looks.
void furnishOffice(Stage& st, bool pillar = true) {
  WorldBuilder& b = st.build;
  b.room({0, 0}, {7, 8}, 2.8);
  b.partition({1.5, 2.0}, kEast, 1.6);
  b.desk({0.4, 2.0}, kEast);
  b.chair({1.0, 2.0}, kWest);
  b.partition({5.5, 1.6}, kWest, 1.6);
  b.desk({6.6, 1.6}, kWest);
  b.desk({0.4, 3.8}, kEast);
  b.chair({1.1, 3.7}, kWest + 0.3);
  if (pillar) b.pillar({4.9, 5.2}, 0.5);
  b.partition({1.3, 4.9}, kEast, 1.6);  // the aisle keeps near surfaces on both sides
  b.partition({5.5, 4.2}, kWest, 1.6);
  b.partition({3.2, 7.3}, kSouth, 1.6);
  b.cabinet({0.23, 6.0}, kEast);
  b.plant({0.6, 6.95});
  b.shelf({6.82, 3.6}, kWest, 1.0);
  b.closedDoor({7.0, 5.3}, kWest);
  b.desk({6.65, 7.35}, kWest);
  b.closedDoor({1.2, 8.0}, kSouth);
  b.shelf({4.8, 7.82}, kSouth, 1.4);
  b.closedDoor({1.5, 0.0}, kNorth);
  b.cabinet({4.5, 0.23}, kNorth);
}

/// The static room's furniture: a double bookcase across the middle, furniture along the walls.
void furnishStaticRoom(Stage& st) {
  WorldBuilder& b = st.build;
  // A 6 x 6.5 m room with a free-standing double bookcase across it: the wearer walks up to the
  // bookcase, turns right along it and walks on beside the west wall. Nearly everything in view
  // stays within the depth sensor's range.
  b.room({0, 0}, {6, 6.5}, 2.7);
  for (double x : {3.0, 4.2}) {
    b.shelf({x, 3.85}, kSouth, 1.2);
    b.shelf({x, 4.21}, kNorth, 1.2);
  }
  b.desk({0.4, 1.8}, kEast);
  b.chair({1.1, 1.8}, kWest);
  b.cabinet({0.23, 4.2}, kEast);
  b.shelf({0.18, 5.5}, kEast, 1.0);
  b.shelf({5.82, 1.8}, kWest, 1.2);
  b.plant({5.6, 3.1});
  b.cabinet({5.77, 5.3}, kWest);
  b.closedDoor({3.2, 6.5}, kSouth);
  b.desk({4.8, 6.1}, kSouth);
  b.closedDoor({1.2, 0.0}, kNorth);
  b.bin({2.2, 0.4});
  st.scene->duration_s = 10.0;
}

std::unique_ptr<Scene> staticRoom(Stage& st) {
  furnishStaticRoom(st);
  st.wearer({{3.6, 0.5}, {3.4, 1.6}, {1.6, 3.3}, {1.6, 5.0}}, 0.7, 1.6);
  return std::move(st.scene);
}

/// The head-turn walk: slowly and straight up the room west of the bookcase (its path does not
/// turn, so the camera's yaw rate is the head's), turning and nodding all the way.
void headTurnWalk(Stage& st) {
  st.wearer({{2.0, 0.5}, {2.0, 3.2}}, 0.35, 1.0);
  st.scene->head.turns = headTurnScript();
}

std::unique_ptr<Scene> headTurns(Stage& st) {
  furnishStaticRoom(st);
  headTurnWalk(st);
  return std::move(st.scene);
}

std::unique_ptr<Scene> headTurnsWalkers(Stage& st) {
  furnishStaticRoom(st);
  headTurnWalk(st);
  // One walker crosses the room in front of the bookcase and walks on beside it; the other
  // walks down the east side and comes back. Both stay clear of the wearer's walk.
  st.person(1, Motion({5.2, 3.2}, kWest)
                   .wait(1.0)
                   .walk(SmoothPath({{5.2, 3.2}, {2.3, 3.2}, {2.0, 5.8}, {3.6, 5.6}}, 0.6), 1.0));
  st.person(2, Motion({5.05, 5.4}, kSouth)
                   .wait(0.8)
                   .walk(SmoothPath({{5.05, 5.4}, {5.05, 1.2}, {4.4, 1.2}, {4.4, 2.8}}, 0.5), 1.1));
  return std::move(st.scene);
}

/// The hall of `approach` and the other straight-line encounters: 5 x 14 m, shelves and cabinets
/// along both walls, the wearer walking up its middle (x = 2.5) from z = 1.
void furnishHall(Stage& st) {
  WorldBuilder& b = st.build;
  b.room({0, 0}, {5, 14}, 2.7);
  for (int i = 0; i < 4; ++i) {
    b.shelf({0.18, 2.0 + 3.2 * i}, kEast, 1.0);
    b.cabinet({4.77, 1.5 + 3.1 * i}, kWest);
  }
  b.closedDoor({0.0, 3.6}, kEast);
  b.closedDoor({5.0, 6.2}, kWest);
  b.plant({0.5, 8.3});
  b.plant({4.5, 12.8});
  b.closedDoor({2.5, 14.0}, kSouth);
}

/// Ends the scene `after_s` after the walker's closest approach to the wearer (or at `max_s`).
void endAfterClosestApproach(Stage& st, const Motion& walker, double after_s, double max_s) {
  double best = 1e9, t_best = 0.0;
  for (double t = 0.0; t < max_s; t += 0.01) {
    const double d = (walker.at(t).position - st.scene->wearer.at(t).position).norm();
    if (d < best) best = d, t_best = t;
  }
  st.scene->duration_s = std::min(max_s, t_best + after_s);
}

std::unique_ptr<Scene> approach(Stage& st) {
  furnishHall(st);
  const ApproachScript a = approachScript(st.seed);
  st.wearer({{2.5, 1.0}, {2.5, 12.0}}, a.wearer_speed_mps, 1.0);
  const double x = 2.5 + a.offset_m;
  const Motion walker = Motion({x, 12.5}, kSouth)
                            .wait(a.walker_wait_s)
                            .walk(line({x, 12.5}, {x, 1.5}), a.walker_speed_mps);
  st.person(1, walker);
  endAfterClosestApproach(st, walker, 2.0, 12.0);
  return std::move(st.scene);
}

std::unique_ptr<Scene> parallel(Stage& st) {
  // A hall 7 m wide; the walker comes down a line kParallelOffsetM to the wearer's left (+x is
  // left of a wearer facing +z). The wearer looks 40 degrees to the left while walking straight
  // on (a 62-degree camera sees the walker only so, with depth within 4.5 m): the walker passes
  // at 10-11 o'clock of the walking direction, though nearly straight ahead of the head.
  st.scene->head.yaw_offset_rad = 40.0 * kPi / 180.0;
  WorldBuilder& b = st.build;
  b.room({0, 0}, {7, 14}, 2.7);
  for (int i = 0; i < 4; ++i) {
    b.shelf({0.18, 2.0 + 3.2 * i}, kEast, 1.0);
    b.cabinet({6.77, 1.5 + 3.1 * i}, kWest);
  }
  b.closedDoor({0.0, 3.6}, kEast);
  b.plant({0.5, 8.3});
  b.plant({6.5, 12.8});
  b.closedDoor({3.5, 14.0}, kSouth);
  st.wearer({{2.0, 1.0}, {2.0, 12.0}}, 0.8, 1.0);
  const double x = 2.0 + script::kParallelOffsetM;
  const Motion walker = Motion({x, 11.0}, kSouth).wait(0.5).walk(line({x, 11.0}, {x, 0.8}), 1.0);
  st.person(1, walker);
  endAfterClosestApproach(st, walker, 1.5, 12.0);
  return std::move(st.scene);
}

std::unique_ptr<Scene> walkingAway(Stage& st) {
  // A walker 1.8 m ahead (slightly to the left) sets off up the hall, faster than the wearer.
  furnishHall(st);
  st.wearer({{2.5, 1.0}, {2.5, 12.0}}, 0.8, 1.0);
  // The walker sets off before the wearer, so it is faster from the first step.
  st.person(1, Motion({2.2, 2.8}, kNorth)
                   .wait(0.3)
                   .walk(line({2.2, 2.8}, {2.2, 13.0}), script::kAwaySpeedMps, 0.5));
  st.scene->duration_s = 7.0;
  return std::move(st.scene);
}

std::unique_ptr<Scene> crossingAt(Stage& st, double ahead_m) {
  furnishOffice(st, /*pillar=*/false);  // the walker's line passes where the pillar stands
  // A double bookcase 0.6 m beyond the walker's line keeps the view ahead within depth range.
  for (double x : {2.9, 4.1}) {
    st.build.shelf({x, 6.2}, kSouth, 1.2);
    st.build.shelf({x, 6.56}, kNorth, 1.2);
  }
  const double v_wearer = 0.9, wait = 0.5, ramp = 1.0, x_w = 3.5, z_w0 = 1.8;
  st.wearer({{x_w, z_w0}, {x_w, 5.2}}, v_wearer, 1.0, wait);
  // The walker reaches the wearer's line (x = x_w) at t_c, when the wearer is ahead_m short of it.
  const double start_x = 6.3, t_c = 3.0;
  const double s_wearer =
      v_wearer * ramp / 2 + v_wearer * (t_c - wait - ramp);  // trapezoid, past the ramp
  const double z_c = z_w0 + s_wearer + ahead_m;
  const double t_start = t_c - (start_x - x_w) / script::kCrossingSpeedMps;
  st.person(1, Motion({start_x, z_c}, kWest)
                   .wait(t_start)
                   .walk(line({start_x, z_c}, {1.0, z_c}), script::kCrossingSpeedMps));
  st.scene->duration_s = 7.0;
  return std::move(st.scene);
}

std::unique_ptr<Scene> crossing(Stage& st) {
  return crossingAt(st, script::kCrossingAheadM);
}

std::unique_ptr<Scene> crossingNear(Stage& st) {
  return crossingAt(st, script::kNearCrossingAheadM);
}

/// `ramp_s`: how long each walker takes to reach its walking speed and to come to a halt (0: the
/// speed switches within a frame, as `office` has always been scripted).
std::unique_ptr<Scene> officeWith(Stage& st, double ramp_s) {
  furnishOffice(st);
  // The wearer first faces the desks behind the west partition (within depth range, for the
  // SLAM to start on), then turns up the aisle.
  st.wearer({{4.2, 0.6}, {2.6, 1.6}, {3.2, 3.8}, {4.4, 6.2}}, 0.7, 1.6);
  st.person(1, Motion({6.3, 5.8}, kWest)
                   .wait(1.0)
                   .walk(SmoothPath({{6.3, 5.8}, {2.0, 5.8}, {2.0, 4.9}}, 0.6), 1.2, ramp_s));
  st.person(2,
            Motion({2.2, 6.8}, kSouth).wait(0.5).walk(line({2.2, 6.8}, {2.4, 2.2}), 1.0, ramp_s));
  st.person(3, Motion({6.0, 2.9}, kNorth)
                   .walk(SmoothPath({{6.0, 2.9}, {6.0, 6.7}, {5.2, 6.9}}, 0.8), 0.7, ramp_s));
  st.scene->duration_s = 10.0;
  return std::move(st.scene);
}

std::unique_ptr<Scene> office(Stage& st) {
  return officeWith(st, 0.0);
}

/// People start and stop walking over about a step: a planned stop takes one to two steps
/// (0.5-1 s) and gait initiation about as long, so 0.6 s stands for both. The walking pose's
/// stride shrinks with the speed (Scene::drawItems), so the body comes to a standing pose smoothly
/// rather than jumping to it from mid-stride.
std::unique_ptr<Scene> officeRamped(Stage& st) {
  return officeWith(st, script::kOfficeRampS);
}

std::unique_ptr<Scene> pushedBox(Stage& st) {
  WorldBuilder& b = st.build;
  b.room({0, 0}, {7, 6.0}, 2.7);
  b.shelf({0.18, 2.0}, kEast, 1.2);
  b.desk({0.4, 3.8}, kEast);
  b.shelf({6.82, 2.5}, kWest, 1.2);
  b.cabinet({6.77, 4.2}, kWest);
  b.plant({6.5, 5.5});
  b.closedDoor({3.0, 6.0}, kSouth);
  b.shelf({5.0, 5.82}, kSouth, 1.0);
  st.wearer({{3.5, 1.6}, {3.5, 2.4}}, 0.8, 1.0);
  // The walker comes round to stand behind the box (hands on its back face), pushes it 1 m
  // along +x at kPushSpeedMps, then turns away.
  const Vec2 box_start(3.0, 4.5), push_dir(1.0, 0.0);
  // A tall carton (0.7 x 1.0 x 0.7 m): the walker's hands (0.45 m ahead of the body centre,
  // ~1 m above the floor) rest on its back face.
  const Vec3f box_size(0.7f, 1.0f, 0.7f);
  const double reach = 0.45;
  const Vec2 stand = box_start - push_dir * (box_size.x() / 2 + reach);
  Motion walker({0.9, 5.4}, kSouth);
  walker.wait(1.0).walk(SmoothPath({{0.9, 5.4}, {1.4, 4.5}, stand}, 0.5), 1.0);
  const double push_from = walker.endTime() + 0.3;
  walker.wait(0.3).walk(line(stand, stand + push_dir * script::kPushDistanceM),
                        script::kPushSpeedMps);
  const double push_to = walker.endTime();
  const Vec2 after = stand + push_dir * script::kPushDistanceM;
  walker.wait(0.5).walk(SmoothPath({after, after + Vec2(-0.3, 0.9), {1.0, 5.4}}, 0.6), 1.1);
  Mover& person = st.person(1, walker);
  person.pushing_from = push_from;
  person.pushing_to = push_to;
  st.box(2,
         Motion(box_start, kEast)
             .wait(push_from)
             .walk(line(box_start, box_start + push_dir * script::kPushDistanceM),
                   script::kPushSpeedMps),
         box_size);
  st.scene->duration_s = 10.0;
  return std::move(st.scene);
}

std::unique_ptr<Scene> loop(Stage& st) {
  WorldBuilder& b = st.build;
  // Two rooms side by side; the wearer leaves A through one doorway and comes back through the
  // other.
  b.room({0, 0}, {6, 6}, 2.7,
         {{Doorway::kEast, 1.0, 2.0, 2.1, true}, {Doorway::kEast, 4.0, 5.0, 2.1, true}});
  b.room({6.1, 0}, {12.1, 6}, 2.7,
         {{Doorway::kWest, 1.0, 2.0, 2.1, false}, {Doorway::kWest, 4.0, 5.0, 2.1, false}});
  b.shelf({0.18, 1.5}, kEast, 1.2);
  b.shelf({0.18, 4.5}, kEast, 1.2);
  b.desk({4.2, 3.0}, kSouth);
  b.chair({4.2, 2.25}, kNorth);
  b.plant({0.5, 3.0});
  b.cabinet({3.0, 5.77}, kSouth);
  b.closedDoor({1.5, 0.0}, kNorth);
  b.cabinet({3.5, 0.23}, kNorth);
  b.openDoor({6.1, 2.0}, kEast);  // hinged at the doorway's edge, swung flat against B's wall
  b.shelf({11.92, 1.5}, kWest, 1.2);
  b.shelf({11.92, 4.5}, kWest, 1.0);
  b.desk({9.0, 3.0}, kNorth);
  b.chair({9.0, 3.75}, kSouth);
  b.plant({11.6, 5.6});
  b.closedDoor({10.0, 6.0}, kSouth);
  b.cabinet({8.0, 0.23}, kNorth);
  b.bin({7.0, 5.6});
  st.wearer({{2.5, 1.5}, {9.6, 1.5}, {9.6, 4.5}, {2.5, 4.5}, {2.5, 1.5}, {5.0, 1.5}}, 0.6, 1.4);
  st.scene->duration_s = st.scene->wearer.endTime() + 0.5;
  return std::move(st.scene);
}

std::unique_ptr<Scene> standing(Stage& st) {
  WorldBuilder& b = st.build;
  b.room({0, 0}, {7, 6.0}, 2.8);
  b.shelf({0.18, 2.0}, kEast, 1.2);
  b.desk({0.4, 4.0}, kEast);
  b.chair({1.15, 4.0}, kWest);
  b.shelf({6.82, 4.9}, kWest, 1.2);
  b.cabinet({6.77, 1.2}, kWest);
  b.closedDoor({3.5, 6.0}, kSouth);
  b.shelf({5.3, 5.82}, kSouth, 1.2);
  b.plant({1.5, 5.5});
  st.wearer({{3.5, 1.4}, {3.5, 2.2}}, 0.8, 1.0);
  // Three people chat in a group; at t = 3 s the second walks off towards the east wall.
  st.person(1, Motion({2.8, 4.4}, kEast).wait(60.0));
  st.person(2, Motion({4.0, 4.2}, kWest)
                   .wait(3.0)
                   .walk(SmoothPath({{4.0, 4.2}, {5.6, 3.4}, {6.0, 1.8}}, 1.0), 1.1));
  st.person(3, Motion({3.5, 5.0}, kSouth).wait(60.0));
  st.scene->duration_s = 10.0;
  return std::move(st.scene);
}

using Factory = std::function<std::unique_ptr<Scene>(Stage&)>;
const std::vector<std::pair<ScenarioInfo, Factory>>& registry() {
  static const std::vector<std::pair<ScenarioInfo, Factory>> list{
      {{"static-room", "a furnished room, nobody else in it; the wearer walks a gentle curve"},
       staticRoom},
      {{"approach", "a person walks straight at the wearer down a long room at 1.0 m/s"}, approach},
      {{"crossing", "a person crosses the wearer's path 2 m ahead at 1.4 m/s"}, crossing},
      {{"crossing-near", "a person crosses the wearer's path 0.5 m ahead at 1.4 m/s (a near miss)"},
       crossingNear},
      {{"parallel", "a person walks towards the wearer on a line 3 m to the side"}, parallel},
      {{"walking-away", "a person 1.8 m ahead walks away from the wearer at 1.3 m/s"}, walkingAway},
      {{"office", "three people walk about an office while the wearer walks (demo default)"},
       office},
      {{"office-ramped",
        "office, but each walker speeds up and slows down over 0.6 s instead of within a frame"},
       officeRamped},
      {{"pushed-box", "a person pushes a box 1 m and walks away (a non-prior mover)"}, pushedBox},
      {{"loop", "the wearer walks a ~21 m loop through two rooms and back to the start"}, loop},
      {{"standing", "three people stand and talk; after 3 s one walks off"}, standing},
      {{"head-turns",
        "static-room's furniture; the wearer turns the head fast (150 deg/s) and nods"},
       headTurns},
      {{"head-turns-walkers", "head-turns with two people walking about the room"},
       headTurnsWalkers},
  };
  return list;
}
}  // namespace

ApproachScript approachScript(uint64_t seed) {
  Rng rng = Rng::stream(seed, 0x617070726f616368ULL);  // "approach"
  ApproachScript a;
  a.walker_speed_mps = rng.uniform(0.8, 1.2);
  a.wearer_speed_mps = rng.uniform(0.7, 0.9);
  a.offset_m = rng.uniform(0.2, 0.6) * (rng.chance(0.5) ? 1.0 : -1.0);
  a.walker_wait_s = rng.uniform(0.3, 1.2);
  return a;
}

std::vector<HeadTurn> headTurnScript() {
  const double deg = kPi / 180.0;
  // Each yaw turn of A over D peaks at 2 A / D: 60 deg in 0.8 s and 120 deg in 1.6 s reach
  // script::kHeadTurnPeakYawDegPs. Nods of 20 deg in 0.5 s peak at 80 deg/s.
  return {
      {1.5, 0.8, 60 * deg, 0.0},        // look aside (yaw in the heading's sense)
      {2.6, 0.5, 0.0, -20 * deg},       // nod down
      {3.2, 0.5, 0.0, 20 * deg},        // and up
      {3.9, 1.6, -120 * deg, 0.0},      // sweep across to the other side
      {6.0, 0.8, 60 * deg, 0.0},        // back to the walking direction
      {7.0, 0.6, 30 * deg, -15 * deg},  // glance down to one side
      {7.8, 0.6, -30 * deg, 15 * deg},  // and back
      {8.6, 0.4, 0.0, -20 * deg},       // quick nods: 100 deg/s
      {9.1, 0.4, 0.0, 20 * deg},
  };
}

const std::vector<ScenarioInfo>& scenarioList() {
  static const std::vector<ScenarioInfo> infos = [] {
    std::vector<ScenarioInfo> v;
    for (const auto& [info, factory] : registry()) v.push_back(info);
    return v;
  }();
  return infos;
}

std::unique_ptr<Scene> buildScenario(const std::string& name, uint64_t seed,
                                     const PhotoLibrary& photos, float texels_per_m) {
  for (const auto& [info, factory] : registry()) {
    if (info.name != name) continue;
    Stage stage(seed, photos, texels_per_m);
    return factory(stage);
  }
  std::string names;
  for (const auto& info : scenarioList()) names += (names.empty() ? "" : ", ") + info.name;
  throw InputError("--scenario", "unknown scenario '" + name + "' (choose one of: " + names + ")");
}

}  // namespace dynanav::sim
