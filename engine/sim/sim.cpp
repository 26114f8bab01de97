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
#include <unordered_map>

#include "engine/util/doom.h"
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
  const double max_cells = std::max(double(1 << 16), 8.0 * double(level.walls.size()));
  for (;; cell_ *= 2) {
    origin_ = b.min - Vec2(cell_);
    cols_ = int((b.max.x - origin_.x) / cell_) + 2;
    rows_ = int((b.max.y - origin_.y) / cell_) + 2;
    if (double(cols_) * rows_ <= max_cells) break;
  }
  std::vector<std::vector<uint32_t>> cells(size_t(cols_) * rows_);
  for (uint32_t i = 0; i < level.walls.size(); ++i) {
    const level::Wall& w = level.walls[i];
    const int c0 = cell_x(std::min(w.a.x, w.b.x)), c1 = cell_x(std::max(w.a.x, w.b.x));
    const int r0 = cell_y(std::min(w.a.y, w.b.y)), r1 = cell_y(std::max(w.a.y, w.b.y));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        // Only the cells the segment passes near: its distance to the cell's centre.
        const Vec2 centre = origin_ + Vec2((c + 0.5) * cell_, (r + 0.5) * cell_);
        if (glm::length(centre - closest_point(centre, w.a, w.b)) <= cell_ * M_SQRT1_2 + 1e-9)
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
    : level_(level),
      blockmap_(level),
      state_(level::start_state(level, skill)),
      things_(level, state_, random_),
      movers_(level, state_, random_),
      skill_(skill) {
  // Pieces of one LINEDEF share its special: used once, it is used up on all of them.
  std::unordered_map<int32_t, std::vector<uint32_t>> by_source;
  for (uint32_t w = 0; w < level.walls.size(); ++w) by_source[level.walls[w].source].push_back(w);
  pieces_.resize(level.walls.size());
  for (uint32_t w = 0; w < level.walls.size(); ++w) pieces_[w] = by_source[level.walls[w].source];
  std::unordered_map<std::string, int> by_name;
  for (size_t t = 0; t < level.textures.size(); ++t) by_name.emplace(level.textures[t].name, int(t));
  switch_partner_.assign(level.textures.size(), level::kNone);
  for (size_t t = 0; t < level.textures.size(); ++t)
    if (const auto it = by_name.find(doom::switch_partner(level.textures[t].name)); it != by_name.end())
      switch_partner_[t] = it->second;
  for (const level::SectorState& s : state_.sectors) secrets_total_ += s.special == doom::kSecretSector;
  for (uint32_t w = 0; w < level.walls.size(); ++w)
    if (level.walls[w].special == doom::kScrollLeft) scrolling_.push_back(w);
  for (const level::Thing& t : level.things) {
    const play::ThingType type = play::thing_type_for_editor_number(t.type);
    const bool pickup = type != play::ThingType::kCount && (play::thing_info(type).flags & play::kSpecial);
    pickup_types_.push_back(pickup ? type : play::ThingType::kCount);
  }
  if (!scrolling_.empty()) state_.scrolled.assign(level.walls.size(), 0);
}

// Doom's special 48: the front side's texture moves left a unit each tic. Kept
// below 65536 units, a multiple of every power-of-two texture width (Doom's walls
// wrap at such widths), so the offset never grows without bound.
void World::scroll_walls() {
  for (uint32_t w : scrolling_) state_.scrolled[w] = std::fmod(state_.scrolled[w] + 1, 65536.0);
}

Player World::spawn() const { return spawn_at(level_.player_start, level_.player_angle); }

Player World::spawn_at(Vec2 pos, double angle) const {
  Player p;
  p.pos = pos;
  p.angle = std::fmod(std::fmod(angle, 360.0) + 360.0, 360.0);
  p.z = heights_at(pos).floor;
  return p;
}

std::vector<int> World::sectors_under(Vec2 pos) const {
  std::vector<int> sectors;
  int sector = level_.sector_at(pos);
  if (sector == level::kNone) sector = level_.default_sector;
  if (sector != level::kNone) sectors.push_back(sector);
  for (uint32_t i : walls_near(box_around(pos, pos, kPlayerRadius))) {
    const level::Wall& w = level_.walls[i];
    if (!w.two_sided() || glm::length(pos - closest_point(pos, w.a, w.b)) >= kPlayerRadius) continue;
    sectors.push_back(w.sides[0].sector);
    sectors.push_back(w.sides[1].sector);
  }
  return sectors;
}

std::vector<uint32_t> World::walls_near(const geom::BBox& box) const {
  std::vector<uint32_t> walls;
  blockmap_.for_each_near(box, [&](uint32_t w) { walls.push_back(w); });
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  return walls;
}

World::Heights World::heights_at(Vec2 pos) const {
  Heights h{-INFINITY, INFINITY};
  for (int s : sectors_under(pos)) {
    h.floor = std::max(h.floor, state_.sectors[size_t(s)].floor);
    h.ceiling = std::min(h.ceiling, state_.sectors[size_t(s)].ceiling);
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

bool World::step(Player& p, Vec2 delta) {
  if (p.noclip) {  // through everything, feet on the floor below
    p.pos += delta;
    return true;
  }
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
  const Vec2 from = p.pos;
  p.pos = target;
  cross_lines(p, from);
  return true;
}

void World::move(Player& p) {
  const Vec2 delta{std::clamp(p.momentum.x, -kMaxMove, kMaxMove), std::clamp(p.momentum.y, -kMaxMove, kMaxMove)};
  const int steps = std::max(1, int(std::ceil(glm::length(delta) / kSubstep)));
  const Vec2 sub = delta / double(steps);
  teleported_ = false;
  for (int i = 0; i < steps && !teleported_; ++i) {
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

void World::fall(Player& p) {
  const Heights h = heights_at(p.pos);
  player_floor_ = h.floor;
  if (p.z < h.floor) {  // stepped up: the eye dips, then recovers
    p.view_offset -= h.floor - p.z;
    p.z = h.floor;
    p.momz = 0;
  } else if (p.z > h.floor) {
    p.momz -= kGravity;
    p.z += p.momz;
    if (p.z <= h.floor) {
      if (p.momz < -8) {  // a hard landing squats, with a grunt
        p.view_offset += p.momz / 4;
        sounds_.push_back({play::Sound::kOof});
      }
      p.z = h.floor;
      p.momz = 0;
    }
  }
  p.view_offset = std::max(p.view_offset, -(kViewHeight - 8));
  p.view_offset = std::fabs(p.view_offset) < 0.05 ? 0 : p.view_offset * 0.7;
}

// Whether the player still fits after a plane of `sector` moved (Doom's
// P_ThingHeightClip): standing on the floor, the player rides it; in the air, a
// ceiling coming down pushes the player down.
bool World::fits_after_move(Player& p, int sector) {
  const std::vector<int> under = sectors_under(p.pos);
  if (std::find(under.begin(), under.end(), sector) == under.end()) return true;
  const Heights h = heights_at(p.pos);
  if (p.z == player_floor_)
    p.z = h.floor;
  else if (p.z + kPlayerHeight > h.ceiling)
    p.z = h.ceiling - kPlayerHeight;
  player_floor_ = h.floor;
  return h.ceiling - h.floor >= kPlayerHeight;
}

// Doom's order: the player thinks (turns, thrusts, finds secrets, uses), moves
// (crossing lines), falls; then every mover and light; then switches flip back.
void World::tick(Player& p, const TicCommand& cmd) {
  events_.clear();
  sounds_.clear();
  movers_.clear_sounds();
  if (p.dead)
    dead_tic(p, cmd);
  else
    player_tic(p, cmd);
  movers_.tick([&](int sector) { return fits_after_move(p, sector); });
  tick_buttons();
  sounds_.insert(sounds_.end(), movers_.sounds().begin(), movers_.sounds().end());
  things_.tick(state_);                                    // Doom's thinkers, then
  level::rest_things(level_, state_);                      // (things stay on floors that moved)
  level::animate_textures(level_, state_, level_time_++);  // its P_UpdateSpecials
  scroll_walls();
}

// Doom's P_DeathThink: the view sinks to 6 units above the floor; use asks for the level again.
void World::dead_tic(Player& p, const TicCommand& cmd) {
  p.inventory.tic();
  p.view_offset = std::max(p.view_offset - 1, 6 - kViewHeight);
  if (cmd.buttons & kUse) reborn_ = true;
}

void World::player_tic(Player& p, const TicCommand& cmd) {
  if (cmd.buttons & kNoclip) {
    p.noclip = !p.noclip;
    say(Event::Kind::kCheat, p.noclip ? "No Clipping Mode ON" : "No Clipping Mode OFF");
  }
  const bool on_ground = p.z <= heights_at(p.pos).floor;
  if (p.frozen > 0) {
    --p.frozen;
  } else {
    p.angle = std::fmod(p.angle + cmd.turn * (360.0 / 65536.0) + 360.0, 360.0);
    if (on_ground) {
      const double a = p.angle * (M_PI / 180);
      const Vec2 forward{std::cos(a), std::sin(a)}, right{std::sin(a), -std::cos(a)};
      p.momentum += forward * (cmd.forward * kThrustPerUnit) + right * (cmd.side * kThrustPerUnit);
    }
  }
  p.inventory.tic();
  in_special_sector(p);
  const bool use = cmd.buttons & kUse;
  if (use && !p.use_held) use_lines(p);
  p.use_held = use;
  move(p);
  if (on_ground) {
    p.momentum *= kFriction;
    if (glm::length(p.momentum) < kStopSpeed && cmd.forward == 0 && cmd.side == 0) p.momentum = {0, 0};
  }
  fall(p);
  pick_up(p);
}

}  // namespace p3d::sim
