#include "sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace dynanav::sim {

namespace {
Vec3f at3(const Vec2& p, double y) {
  return Vec3f(float(p.x()), float(y), float(p.y()));
}
}  // namespace

cv::Size WorldBuilder::texels(double w_m, double h_m) const {
  return cv::Size(std::max(8, int(std::ceil(w_m * tpm_))), std::max(8, int(std::ceil(h_m * tpm_))));
}

void WorldBuilder::room(const Vec2& min, const Vec2& max, double height_m,
                        const std::vector<Doorway>& doorways) {
  const double W = max.x() - min.x(), D = max.y() - min.y();
  // Floor (seen from above: u = +x, v = +z) and ceiling (seen from below: u = +x, v = -z).
  const float floor_tpm = tpm_;
  const int kind = rng_.uniformInt(0, 2);
  cv::Mat floor = kind == 0   ? woodPlanks(texels(W, D), floor_tpm, rng_)
                  : kind == 1 ? floorTiles(texels(W, D), floor_tpm, rng_)
                              : carpet(texels(W, D), rng_);
  decorateFloor(floor, floor_tpm, rng_);
  world_.static_mesh.addQuad(at3(min, 0.0), Vec3f(float(W), 0, 0), Vec3f(0, 0, float(D)),
                             texture(floor), floor_tpm);
  const float ceiling_tpm = tpm_ / 2;  // seldom in view: half the texel density
  cv::Mat ceiling =
      ceilingTiles(cv::Size(int(W * ceiling_tpm) + 8, int(D * ceiling_tpm) + 8), ceiling_tpm, rng_);
  world_.static_mesh.addQuad(at3(Vec2(min.x(), max.y()), height_m), Vec3f(float(W), 0, 0),
                             Vec3f(0, 0, -float(D)), texture(ceiling), ceiling_tpm);
  // Walls, each from a to b with the room's interior on its visible side.
  struct Side {
    Doorway::Side side;
    Vec2 a, b;
  };
  const Side sides[] = {{Doorway::kSouth, {min.x(), min.y()}, {max.x(), min.y()}},
                        {Doorway::kNorth, {max.x(), max.y()}, {min.x(), max.y()}},
                        {Doorway::kWest, {min.x(), max.y()}, {min.x(), min.y()}},
                        {Doorway::kEast, {max.x(), min.y()}, {max.x(), max.y()}}};
  for (const Side& s : sides) {
    std::vector<Opening> openings;
    const Vec2 dir = (s.b - s.a).normalized();
    for (const Doorway& d : doorways) {
      if (d.side != s.side) continue;
      // Convert coordinates along the wall to arc length from a.
      const bool along_x = s.side == Doorway::kSouth || s.side == Doorway::kNorth;
      const double a_coord = along_x ? s.a.x() : s.a.y();
      const double sign = along_x ? dir.x() : dir.y();
      double s0 = (d.from - a_coord) * sign, s1 = (d.to - a_coord) * sign;
      if (s0 > s1) std::swap(s0, s1);
      openings.push_back({s0, s1, d.height_m, d.jambs});
    }
    wall(s.a, s.b, height_m, openings);
  }
}

void WorldBuilder::wall(const Vec2& a, const Vec2& b, double H, std::vector<Opening> openings) {
  const double L = (b - a).norm();
  const Vec2 dir = (b - a) / L;
  const double kind = rng_.uniform();
  cv::Mat tex = kind < 0.3   ? bricks(texels(L, H), tpm_, rng_)
                : kind < 0.6 ? wallpaper(texels(L, H), tpm_, rng_)
                             : plaster(texels(L, H), rng_);
  decorateWall(tex, tpm_, rng_, photos_);
  const int id = texture(tex);
  const Vec3f u(float(dir.x()), 0, float(dir.y())), down(0, -1, 0);
  // Outward (interior-facing) normal = down x u; the wall's thickness goes the other way.
  const Vec3f into_room = down.cross(u);
  const float thickness = 0.1f;
  std::sort(openings.begin(), openings.end(),
            [](const Opening& x, const Opening& y) { return x.s0 < y.s0; });
  auto piece = [&](double s0, double s1, double top, double bottom) {
    if (s1 - s0 < 1e-6 || top - bottom < 1e-6) return;
    const Vec3f origin = at3(a + dir * s0, top);
    world_.static_mesh.addQuad(origin, u * float(s1 - s0), down * float(top - bottom), id, tpm_,
                               Vec2f(float(s0) * tpm_, float(H - top) * tpm_));
  };
  const int jamb_tex = texture(plaster(texels(1.0, 2.2), rng_));
  double cursor = 0.0;
  for (const Opening& o : openings) {
    piece(cursor, o.s0, H, 0.0);
    piece(o.s0, o.s1, H, o.height_m);  // lintel
    cursor = o.s1;
    if (!o.jambs) continue;
    const float h = float(o.height_m);
    const Vec3f left = at3(a + dir * o.s0, o.height_m), right = at3(a + dir * o.s1, o.height_m);
    Mesh& m = world_.static_mesh;
    m.addQuad(left, -into_room * thickness, down * h, jamb_tex, tpm_);  // faces +u
    m.addQuad(right - into_room * thickness, into_room * thickness, down * h, jamb_tex,
              tpm_);                                                                  // faces -u
    m.addQuad(left, u * float(o.s1 - o.s0), -into_room * thickness, jamb_tex, tpm_);  // soffit
    const Vec3f sill = at3(a + dir * o.s0, 0.0) - into_room * thickness;              // threshold
    m.addQuad(sill, u * float(o.s1 - o.s0), into_room * thickness, jamb_tex, tpm_);
  }
  piece(cursor, L, H, 0.0);
}

void WorldBuilder::place(const Mesh& local, const Vec2& at, double yaw) {
  Pose3f T = Pose3f::Identity();
  T.linear() = Eigen::AngleAxisf(float(yaw), Vec3f::UnitY()).toRotationMatrix();
  T.translation() = at3(at, 0.0);
  world_.static_mesh.append(local, T);
}

void WorldBuilder::desk(const Vec2& at, double yaw) {
  Mesh m;
  const int wood = texture(woodPlanks(texels(1.6, 1.6), tpm_, rng_));
  const int metal = texture(plaster(texels(0.5, 0.5), rng_));
  m.addBox(Vec3f(0, 0.735f, 0), Vec3f(1.4f, 0.04f, 0.7f), wood, tpm_);
  for (float sx : {-0.65f, 0.65f})
    for (float sz : {-0.3f, 0.3f})
      m.addBox(Vec3f(sx, 0.357f, sz), Vec3f(0.05f, 0.715f, 0.05f), metal, tpm_);
  const int panel = texture(poster(texels(1.3, 0.4), rng_, photos_));
  m.addBox(Vec3f(0, 0.5f, -0.28f), Vec3f(1.3f, 0.4f, 0.02f), {wood, wood, wood, wood, wood, panel},
           tpm_);
  // Monitor on a stand, facing the chair side (+z), keyboard, papers, a mug and books.
  const int scr = texture(screen(texels(0.55, 0.34), rng_));
  m.addBox(Vec3f(0, 0.92f, -0.2f), Vec3f(0.06f, 0.34f, 0.06f), metal, tpm_);
  m.addBox(Vec3f(0, 1.08f, -0.17f), Vec3f(0.55f, 0.34f, 0.03f),
           {metal, metal, metal, metal, scr, metal}, tpm_);
  m.addBox(Vec3f(0, 0.765f, 0.1f), Vec3f(0.45f, 0.02f, 0.15f),
           texture(fabric(texels(0.5, 0.5), rng_)), tpm_);
  for (int i = 0; i < 3; ++i) {
    const int paper = texture(whiteboard(texels(0.21, 0.3), rng_));
    const Vec3f c(float(rng_.uniform(-0.6, 0.4)), 0.756f + 0.001f * float(i),
                  float(rng_.uniform(-0.2, 0.2)));
    m.addQuad(c, Vec3f(0.21f, 0, 0), Vec3f(0, 0, 0.3f), paper, tpm_);
  }
  m.addPrism(Vec3f(0.5f, 0.755f, 0.15f), 0.04f, 0.1f, 8, texture(fabric(texels(0.3, 0.3), rng_)),
             tpm_);
  const int books = texture(bookshelfFront(texels(0.4, 0.4), tpm_, rng_));
  m.addBox(Vec3f(-0.5f, 0.83f, -0.22f), Vec3f(0.3f, 0.15f, 0.22f), books, tpm_, 17.0f);
  place(m, at, yaw);
}

void WorldBuilder::chair(const Vec2& at, double yaw) {
  Mesh m;
  const int cloth = texture(fabric(texels(1.0, 1.0), rng_));
  const int metal = texture(plaster(texels(0.3, 0.3), rng_));
  m.addBox(Vec3f(0, 0.46f, 0), Vec3f(0.46f, 0.06f, 0.46f), cloth, tpm_);
  m.addBox(Vec3f(0, 0.75f, -0.21f), Vec3f(0.44f, 0.5f, 0.05f), cloth, tpm_, 40.0f);
  for (float sx : {-0.2f, 0.2f})
    for (float sz : {-0.2f, 0.2f})
      m.addBox(Vec3f(sx, 0.215f, sz), Vec3f(0.035f, 0.43f, 0.035f), metal, tpm_);
  place(m, at, yaw);
}

void WorldBuilder::shelf(const Vec2& at, double yaw, double width_m) {
  Mesh m;
  const float w = float(width_m), h = 1.9f, d = 0.35f;
  const int wood = texture(woodPlanks(texels(2.0, 2.0), tpm_, rng_));
  const int front = texture(bookshelfFront(texels(w, h), tpm_, rng_));
  m.addBox(Vec3f(0, h / 2, 0), Vec3f(w, h, d), {wood, wood, wood, wood, front, wood}, tpm_);
  place(m, at, yaw);
}

void WorldBuilder::cabinet(const Vec2& at, double yaw) {
  Mesh m;
  const int front = texture(doorPanel(texels(0.8, 1.0), rng_));
  const int side = texture(woodPlanks(texels(1.0, 1.0), tpm_, rng_));
  m.addBox(Vec3f(0, 0.5f, 0), Vec3f(0.8f, 1.0f, 0.45f), {side, side, side, side, front, side},
           tpm_);
  const int stuff = texture(poster(texels(0.3, 0.3), rng_, photos_));
  m.addBox(Vec3f(0.15f, 1.1f, 0), Vec3f(0.3f, 0.2f, 0.25f), stuff, tpm_);
  place(m, at, yaw);
}

void WorldBuilder::partition(const Vec2& at, double yaw, double width_m) {
  Mesh m;
  const float w = float(width_m), h = 1.3f, d = 0.06f;
  const int front = texture(pinboard(texels(w, h), tpm_, rng_, photos_));
  const int back = texture(pinboard(texels(w, h), tpm_, rng_, photos_));
  const int frame = texture(plaster(texels(0.5, 1.5), rng_));
  m.addBox(Vec3f(0, h / 2, 0), Vec3f(w, h, d), {frame, frame, frame, frame, front, back}, tpm_);
  place(m, at, yaw);
}

void WorldBuilder::pillar(const Vec2& at, double side_m) {
  Mesh m;
  const float s = float(side_m), h = 2.8f;
  cv::Mat tex = plaster(texels(4 * side_m, h), rng_);
  decorateWall(tex, tpm_, rng_, photos_);
  m.addBox(Vec3f(0, h / 2, 0), Vec3f(s, h, s), texture(tex), tpm_, 0.0f);
  place(m, at, 0.0);
}

void WorldBuilder::plant(const Vec2& at) {
  Mesh m;
  m.addPrism(Vec3f(0, 0, 0), 0.18f, 0.35f, 10, texture(floorTiles(texels(1.2, 0.4), tpm_, rng_)),
             tpm_);
  cv::Mat leaves = carpet(texels(1.0, 1.0), rng_);
  cv::Mat green(leaves.size(), CV_8UC3, cv::Scalar(40, 140, 50));
  cv::addWeighted(leaves, 0.5, green, 0.5, 0.0, leaves);
  m.addBox(Vec3f(0, 0.75f, 0), Vec3f(0.45f, 0.8f, 0.45f), texture(leaves), tpm_);
  place(m, at, 0.0);
}

void WorldBuilder::bin(const Vec2& at) {
  Mesh m;
  m.addPrism(Vec3f(0, 0, 0), 0.16f, 0.4f, 8, texture(fabric(texels(1.0, 0.4), rng_)), tpm_);
  place(m, at, 0.0);
}

void WorldBuilder::closedDoor(const Vec2& at, double yaw) {
  Mesh m;
  const int leaf = texture(doorPanel(texels(0.9, 2.05), rng_));
  const int frame = texture(plaster(texels(0.3, 2.2), rng_));
  m.addBox(Vec3f(0, 1.025f, 0.025f), Vec3f(0.9f, 2.05f, 0.03f),
           {frame, frame, frame, frame, leaf, frame}, tpm_);
  m.addBox(Vec3f(0, 2.08f, 0.02f), Vec3f(1.05f, 0.08f, 0.04f), frame, tpm_);
  m.addBox(Vec3f(0.35f, 1.0f, 0.06f), Vec3f(0.12f, 0.03f, 0.04f), frame, tpm_);
  place(m, at, yaw);
}

void WorldBuilder::openDoor(const Vec2& hinge, double yaw) {
  Mesh m;
  const int leaf = texture(doorPanel(texels(0.9, 2.05), rng_));
  // Leaf from the hinge along local -x, its panel side facing +z.
  m.addBox(Vec3f(-0.45f, 1.025f, 0.02f), Vec3f(0.9f, 2.05f, 0.04f),
           {leaf, leaf, leaf, leaf, leaf, leaf}, tpm_);
  place(m, hinge, yaw);
}

}  // namespace dynanav::sim
