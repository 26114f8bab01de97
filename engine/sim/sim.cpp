// Movement and collision. Each tic: turn, thrust (on the ground), move through
// substeps of at most 8 units (half the radius), friction, then fall or step up.
// A substep pushes the circle out of every wall that blocks it (sliding along
// it), then is accepted only if the centre crossed no blocking wall, the circle
// overlaps none, and the floor, step and headroom under the circle allow it;
// otherwise the axes are tried alone, then the player stops. So no speed or
// frame rate can carry the player through a wall.
#include "engine/sim/sim.h"

#include <algorithm>
#include <cmath>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::sim {

namespace {

constexpr double kThrustPerUnit = 1.0 / 32;  // Doom: move * 2048 in 16.16 fixed point
constexpr double kFriction = 0xE800 / 65536.0;
constexpr double kStopSpeed = 1.0 / 16;
constexpr double kGravity = 1;
constexpr double kMaxMove = 30;   // units per tic on each axis, as Doom's MAXMOVE
constexpr double kSubstep = 8;    // at most half the radius per substep
constexpr double kTouch = 1e-6;   // slack when testing "at least the radius away"

using geom::closest_point;

// Whether the path p -> q crosses the segment a-b (strictly changes side within it).
bool crosses(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  const double sp = geom::cross(b - a, p - a), sq = geom::cross(b - a, q - a);
  if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0) || (sp == 0 && sq == 0)) return false;
  const double sa = geom::cross(q - p, a - p), sb = geom::cross(q - p, b - p);
  return !((sa > 0 && sb > 0) || (sa < 0 && sb < 0));
}

geom::BBox box_around(Vec2 a, Vec2 b, double margin) {
  geom::BBox box;
  box.add(a);
  box.add(b);
  box.min -= Vec2(margin);
  box.max += Vec2(margin);
  return box;
}

}  // namespace

// ---- blockmap ----------------------------------------------------------------

Blockmap::Blockmap(const level::Level& level) {
  const geom::BBox& b = level.bounds;
  origin_ = b.min - Vec2(kCell);
  cols_ = int((b.max.x - origin_.x) / kCell) + 2;
  rows_ = int((b.max.y - origin_.y) / kCell) + 2;
  std::vector<std::vector<uint32_t>> cells(size_t(cols_) * rows_);
  for (uint32_t i = 0; i < level.walls.size(); ++i) {
    const level::Wall& w = level.walls[i];
    const int c0 = cell_x(std::min(w.a.x, w.b.x)), c1 = cell_x(std::max(w.a.x, w.b.x));
    const int r0 = cell_y(std::min(w.a.y, w.b.y)), r1 = cell_y(std::max(w.a.y, w.b.y));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        // Only the cells the segment passes near: its distance to the cell's centre.
        const Vec2 centre = origin_ + Vec2((c + 0.5) * kCell, (r + 0.5) * kCell);
        if (glm::length(centre - closest_point(centre, w.a, w.b)) <= kCell * M_SQRT1_2 + 1e-9)
          cells[size_t(r) * cols_ + c].push_back(i);
      }
  }
  start_.assign(cells.size() + 1, 0);
  for (size_t c = 0; c < cells.size(); ++c) {
    walls_.insert(walls_.end(), cells[c].begin(), cells[c].end());
    start_[c + 1] = uint32_t(walls_.size());
  }
}

// ---- world -------------------------------------------------------------------

World::World(const level::Level& level, int skill)
    : level_(level), blockmap_(level), state_(level::start_state(level, skill)) {}

Player World::spawn() const { return spawn_at(level_.player_start, level_.player_angle); }

Player World::spawn_at(Vec2 pos, double angle) const {
  Player p;
  p.pos = pos;
  p.angle = std::fmod(std::fmod(angle, 360.0) + 360.0, 360.0);
  p.z = heights_at(pos).floor;
  return p;
}

std::vector<uint32_t> World::walls_near(const geom::BBox& box) const {
  std::vector<uint32_t> walls;
  blockmap_.for_each_near(box, [&](uint32_t w) { walls.push_back(w); });
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  return walls;
}

World::Heights World::heights_at(Vec2 pos) const {
  int sector = level_.sector_at(pos);
  if (sector == level::kNone) sector = level_.default_sector;
  Heights h{-INFINITY, INFINITY};
  auto touch = [&](int s) {
    if (s == level::kNone) return;
    h.floor = std::max(h.floor, state_.sectors[size_t(s)].floor);
    h.ceiling = std::min(h.ceiling, state_.sectors[size_t(s)].ceiling);
  };
  touch(sector);
  for (uint32_t i : walls_near(box_around(pos, pos, kPlayerRadius))) {
    const level::Wall& w = level_.walls[i];
    if (!w.two_sided() || glm::length(pos - closest_point(pos, w.a, w.b)) >= kPlayerRadius) continue;
    touch(w.sides[0].sector);
    touch(w.sides[1].sector);
  }
  if (h.floor == -INFINITY) h = {0, 0};  // in the void of a level without a default sector
  return h;
}

bool World::blocks(uint32_t wall, Vec2 from, double z) const {
  const level::Wall& w = level_.walls[wall];
  if (!w.two_sided() || (w.flags & level::kImpassable)) return true;  // one-sided, plain segments, Doom's impassable
  const int near = geom::cross(w.b - w.a, from - w.a) > 0 ? 1 : 0;
  const level::SectorState& far = state_.sectors[size_t(w.sides[1 - near].sector)];
  return far.floor - z > kMaxStep || far.ceiling - far.floor < kPlayerHeight ||
         far.ceiling - std::max(z, far.floor) < kPlayerHeight;
}

bool World::step(Player& p, Vec2 delta) const {
  Vec2 target = p.pos + delta;
  const std::vector<uint32_t> near = walls_near(box_around(p.pos, target, 2 * kPlayerRadius + 1));
  std::vector<uint32_t> blocking;
  for (uint32_t i : near)
    if (blocks(i, p.pos, p.z)) blocking.push_back(i);

  // Push the circle out of every blocking wall it overlaps: this is the slide.
  for (int pass = 0; pass < 4; ++pass) {
    bool pushed = false;
    for (uint32_t i : blocking) {
      const level::Wall& w = level_.walls[i];
      const Vec2 c = closest_point(target, w.a, w.b);
      const Vec2 away = target - c;
      const double d = glm::length(away);
      if (d >= kPlayerRadius) continue;
      Vec2 normal = d > 1e-9 ? away / d : Vec2(w.a.y - w.b.y, w.b.x - w.a.x) / w.length;  // the wall's right side
      if (d <= 1e-9 && geom::cross(w.b - w.a, p.pos - w.a) > 0) normal = -normal;           // back towards the player
      target = c + normal * (kPlayerRadius + kTouch);
      pushed = true;
    }
    if (!pushed) break;
  }

  for (uint32_t i : blocking) {
    const level::Wall& w = level_.walls[i];
    if (crosses(p.pos, target, w.a, w.b)) return false;
    if (glm::length(target - closest_point(target, w.a, w.b)) < kPlayerRadius - kTouch) return false;
  }
  const Heights h = heights_at(target);
  if (h.floor - p.z > kMaxStep || h.ceiling - h.floor < kPlayerHeight || h.ceiling - std::max(p.z, h.floor) < kPlayerHeight)
    return false;
  p.pos = target;
  return true;
}

void World::move(Player& p) const {
  const Vec2 delta{std::clamp(p.momentum.x, -kMaxMove, kMaxMove), std::clamp(p.momentum.y, -kMaxMove, kMaxMove)};
  const int steps = std::max(1, int(std::ceil(glm::length(delta) / kSubstep)));
  const Vec2 sub = delta / double(steps);
  for (int i = 0; i < steps; ++i) {
    if (step(p, sub)) continue;
    // Blocked: slide along one axis (a ledge too high, a corner), else stop.
    if (sub.x != 0 && step(p, {sub.x, 0})) {
      p.momentum.y = 0;
      continue;
    }
    if (sub.y != 0 && step(p, {0, sub.y})) {
      p.momentum.x = 0;
      continue;
    }
    p.momentum = {0, 0};
    break;
  }
}

void World::fall(Player& p) const {
  const Heights h = heights_at(p.pos);
  if (p.z < h.floor) {  // stepped up: the eye dips, then recovers
    p.view_offset -= h.floor - p.z;
    p.z = h.floor;
    p.momz = 0;
  } else if (p.z > h.floor) {
    p.momz -= kGravity;
    p.z += p.momz;
    if (p.z <= h.floor) {
      if (p.momz < -8) p.view_offset += p.momz / 4;  // a hard landing squats
      p.z = h.floor;
      p.momz = 0;
    }
  }
  p.view_offset = std::max(p.view_offset, -(kViewHeight - 8));
  p.view_offset = std::fabs(p.view_offset) < 0.05 ? 0 : p.view_offset * 0.7;
}

void World::tick(Player& p, const TicCommand& cmd) {
  p.angle = std::fmod(p.angle + cmd.turn * (360.0 / 65536.0) + 360.0, 360.0);
  const bool on_ground = p.z <= heights_at(p.pos).floor;
  if (on_ground) {
    const double a = p.angle * (M_PI / 180);
    const Vec2 forward{std::cos(a), std::sin(a)}, right{std::sin(a), -std::cos(a)};
    p.momentum += forward * (cmd.forward * kThrustPerUnit) + right * (cmd.side * kThrustPerUnit);
  }
  move(p);
  if (on_ground) {
    p.momentum *= kFriction;
    if (glm::length(p.momentum) < kStopSpeed && cmd.forward == 0 && cmd.side == 0) p.momentum = {0, 0};
  }
  fall(p);
}

// ---- demos -------------------------------------------------------------------

namespace {
constexpr char kDemoMagic[8] = {'P', '3', 'D', 'D', 'E', 'M', 'O', '\n'};
constexpr uint32_t kDemoVersion = 2;
constexpr size_t kTicBytes = 5;
constexpr size_t kMaxDemoTics = 35 * 60 * 60 * 24;  // a day of play
}  // namespace

uint64_t fingerprint(const level::Level& level) {
  ByteWriter out;
  for (const level::Wall& w : level.walls) {
    out.i64(w.p1.x), out.i64(w.p1.y), out.i64(w.p2.x), out.i64(w.p2.y);
    out.u32(w.flags);
    out.i32(w.sides[0].sector), out.i32(w.sides[1].sector);
  }
  for (const level::Sector& s : level.sectors) out.f64(s.floor), out.f64(s.ceiling);
  out.i32(level.default_sector);
  return fnv1a64(out.bytes());
}

std::vector<uint8_t> encode_demo(const Demo& d) {
  ByteWriter out;
  out.raw(std::span(reinterpret_cast<const uint8_t*>(kDemoMagic), 8));
  out.u32(kDemoVersion);
  out.u64(d.level_fingerprint);
  out.f64(d.start.x);
  out.f64(d.start.y);
  out.f64(d.angle);
  out.u32(uint32_t(d.tics.size()));
  for (const TicCommand& t : d.tics) {
    out.u8(uint8_t(t.forward));
    out.u8(uint8_t(t.side));
    out.u16(uint16_t(t.turn));
    out.u8(t.buttons);
  }
  out.u64(fnv1a64(out.bytes()));
  return std::move(out.bytes());
}

Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kDemoMagic, 8) != 0) throw Error(what + ": not a demo (bad magic)");
  if (bytes.size() < 8 + 4 + 8 + 24 + 4 + 8) throw Error(what + ": truncated demo");
  const uint64_t expected = fnv1a64(bytes.subspan(0, bytes.size() - 8));
  ByteReader tail(bytes.subspan(bytes.size() - 8), what);
  ByteReader in(bytes.subspan(8, bytes.size() - 16), what);
  const uint32_t version = in.u32();
  if (version != kDemoVersion)
    throw Error(what + ": demo version " + std::to_string(version) + " is not supported (expected " +
                std::to_string(kDemoVersion) + ")");
  Demo d;
  d.level_fingerprint = in.u64();
  d.start = {in.f64(), in.f64()};
  d.angle = in.f64();
  if (!std::isfinite(d.start.x) || !std::isfinite(d.start.y) || !std::isfinite(d.angle))
    throw Error(what + ": demo start is not finite");
  const uint32_t count = in.count(kTicBytes, "tics");
  if (count > kMaxDemoTics) throw Error(what + ": demo is longer than a day");
  if (in.remaining() != size_t(count) * kTicBytes) throw Error(what + ": truncated or padded demo");
  if (tail.u64() != expected) throw Error(what + ": checksum mismatch (the demo is corrupted)");
  d.tics.resize(count);
  for (TicCommand& t : d.tics) {
    t.forward = int8_t(in.u8());
    t.side = int8_t(in.u8());
    t.turn = int16_t(in.u16());
    t.buttons = in.u8();
    if (t.buttons & ~uint8_t(kUse)) throw Error(what + ": unknown buttons in a tic");
  }
  return d;
}

}  // namespace p3d::sim
