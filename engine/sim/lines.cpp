// What the player acts on: lines used (the use key) and walked over, switches and
// their textures, locks and keys, teleporters, exits and secrets. Doom's rules
// (p_map.c's use trace, p_spec.c's triggers, p_switch.c, p_telept.c, p_inter.c):
// - use traces 64 units ahead; the nearest line with a special is used from its
//   front side only, and a closed line before it stops the trace;
// - a line is walked over when the player's centre changes side while its box
//   touches the line; only teleporters care from which side;
// - once-only specials are cleared when triggered (switches and doors only when
//   they started something); a switch flips to its pair texture, a repeatable one
//   back after a second.
#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/sim/sim.h"
#include "engine/util/doom.h"

namespace p3d::sim {

namespace {

constexpr double kUseRange = 64;
constexpr int kButtonTics = 35;
constexpr int kTeleportFreeze = 18;
constexpr double kPickupBelow = 8;  // a pickup this far below the feet is still reached (Doom's -8)

// 1 on the back (left) side of the wall, 0 on the front or on the line.
int side_of(const level::Wall& w, Vec2 p) { return geom::cross(w.b - w.a, p - w.a) > 0 ? 1 : 0; }

// Whether a box straddles the wall: the boxes overlap and the line separates its corners.
bool box_on_line(const level::Wall& w, const geom::BBox& box) {
  if (std::max(w.a.x, w.b.x) <= box.min.x || std::min(w.a.x, w.b.x) >= box.max.x ||
      std::max(w.a.y, w.b.y) <= box.min.y || std::min(w.a.y, w.b.y) >= box.max.y)
    return false;
  int sides = 0;
  for (Vec2 c : {box.min, box.max, Vec2(box.min.x, box.max.y), Vec2(box.max.x, box.min.y)})
    sides |= 1 << side_of(w, c);
  return sides == 3;
}

}  // namespace

void World::say(Event::Kind kind, std::string message) { events_.push_back({kind, std::move(message)}); }

// ---- using -------------------------------------------------------------------

void World::use_lines(Player& p) {
  const double a = p.angle * (M_PI / 180);
  const Vec2 d = Vec2(std::cos(a), std::sin(a)) * kUseRange;
  geom::BBox box;
  box.add(p.pos);
  box.add(p.pos + d);
  std::vector<std::pair<double, uint32_t>> hits;  // trace fraction, wall
  for (uint32_t i : walls_near(box)) {
    const level::Wall& w = level_.walls[i];
    const Vec2 e = w.b - w.a, to_a = w.a - p.pos;
    const double denom = geom::cross(d, e);
    if (denom == 0) continue;
    const double t = geom::cross(to_a, e) / denom, u = geom::cross(to_a, d) / denom;
    if (t >= 0 && t <= 1 && u >= 0 && u <= 1) hits.push_back({t, i});
  }
  std::sort(hits.begin(), hits.end());
  for (const auto& [t, i] : hits) {
    const level::Wall& w = level_.walls[i];
    if (state_.specials[i] != 0) {
      if (side_of(w, p.pos) == 0) use_line(p, i);
      return;
    }
    auto grunt = [&] { sounds_.push_back({play::Sound::kNoway}); };  // Doom's "oof" at a plain wall
    if (!w.two_sided()) return grunt();
    const level::SectorState& f = state_.sectors[size_t(w.sides[0].sector)];
    const level::SectorState& b = state_.sectors[size_t(w.sides[1].sector)];
    if (std::min(f.ceiling, b.ceiling) - std::max(f.floor, b.floor) <= 0) return grunt();  // a closed door, a wall
  }
}

void World::use_line(Player& p, uint32_t wall) {
  const LineSpecial* s = line_special(state_.specials[wall]);
  if (!s || s->monsters_only) return;
  if (s->trigger == Trigger::kManual) {
    if (unlocked(p, s->lock, true) && movers_.use_door(*s, wall) && !s->repeat) clear_special(wall);
    return;
  }
  if (s->trigger != Trigger::kSwitch || !unlocked(p, s->lock, false)) return;  // walk-over lines do nothing used
  if (s->action == Action::kExit || s->action == Action::kSecretExit) {
    flip_switch(wall, false);
    exit_ = s->action == Action::kExit ? Exit::kNormal : Exit::kSecret;
    say(Event::Kind::kExit);
    return;
  }
  if (movers_.activate(*s, wall)) flip_switch(wall, s->repeat);
}

bool World::unlocked(const Player& p, Lock lock, bool door) {
  uint8_t keys = 0;
  const char* colour = "";
  switch (lock) {
    case Lock::kNone:
      return true;
    case Lock::kBlue:
      keys = kBlueCard | kBlueSkull, colour = "blue";
      break;
    case Lock::kYellow:
      keys = kYellowCard | kYellowSkull, colour = "yellow";
      break;
    case Lock::kRed:
      keys = kRedCard | kRedSkull, colour = "red";
      break;
  }
  if (p.keys & keys) return true;
  say(Event::Kind::kLocked,
      std::string("You need a ") + colour + " key to " + (door ? "open this door" : "activate this object"));
  sounds_.push_back({play::Sound::kOof});
  return false;
}

bool World::trigger(uint32_t wall) {
  const LineSpecial* s = line_special(state_.specials[wall]);
  if (!s) return false;
  if (s->trigger == Trigger::kManual) return movers_.use_door(*s, wall);
  if (s->action == Action::kTeleport || s->action == Action::kExit || s->action == Action::kSecretExit) return false;
  return movers_.activate(*s, wall);
}

// ---- switches ------------------------------------------------------------------

void World::clear_special(uint32_t wall) {
  for (uint32_t w : pieces_[wall]) state_.specials[w] = 0;
}

// The first of the front side's upper, middle and lower textures that is a switch
// flips to its pair (on every piece of the line).
void World::flip_switch(uint32_t wall, bool repeat) {
  if (!repeat) clear_special(wall);
  for (int part : {level::kUpperPart, level::kMiddlePart, level::kLowerPart}) {
    const int texture = state_.texture(wall, 0, part);
    if (texture < 0 || switch_partner_[size_t(texture)] == level::kNone) continue;
    for (uint32_t w : pieces_[wall]) state_.texture(w, 0, part) = switch_partner_[size_t(texture)];
    const bool pressed = std::any_of(buttons_.begin(), buttons_.end(), [&](const Button& b) { return b.wall == wall; });
    if (repeat && !pressed) buttons_.push_back({wall, part, texture, kButtonTics});
    say(Event::Kind::kSwitch);
    const LineSpecial* s = line_special(level_.walls[wall].special);
    const bool exit = s && (s->action == Action::kExit || s->action == Action::kSecretExit);
    sounds_.push_back({exit ? play::Sound::kSwtchx : play::Sound::kSwtchn, level_.walls[wall].sides[0].sector});
    return;
  }
}

void World::tick_buttons() {
  for (Button& b : buttons_)
    if (--b.tics == 0) {
      for (uint32_t w : pieces_[b.wall]) state_.texture(w, 0, b.part) = b.texture;
      sounds_.push_back({play::Sound::kSwtchn, level_.walls[b.wall].sides[0].sector});
    }
  std::erase_if(buttons_, [](const Button& b) { return b.tics == 0; });
}

// ---- walking over --------------------------------------------------------------

void World::cross_lines(Player& p, Vec2 from) {
  geom::BBox box;
  box.add(p.pos - Vec2(kPlayerRadius));
  box.add(p.pos + Vec2(kPlayerRadius));
  std::vector<int32_t> crossed;  // LINEDEFs already triggered by this step (a line may be in pieces)
  for (uint32_t i : walls_near(box)) {
    const level::Wall& w = level_.walls[i];
    if (state_.specials[i] == 0 || !w.two_sided() || (w.flags & level::kImpassable)) continue;
    const int side = side_of(w, from);
    if (side == side_of(w, p.pos) || !box_on_line(w, box)) continue;
    if (std::find(crossed.begin(), crossed.end(), w.source) != crossed.end()) continue;
    crossed.push_back(w.source);
    cross_line(p, i, side);
    if (teleported_) return;
  }
}

void World::cross_line(Player& p, uint32_t wall, int side) {
  const LineSpecial* s = line_special(state_.specials[wall]);
  if (!s || s->trigger != Trigger::kWalk || s->monsters_only) return;
  switch (s->action) {
    case Action::kTeleport:
      if (side == 0) teleport(p, wall);  // only from the front
      break;
    case Action::kExit:
    case Action::kSecretExit:
      exit_ = s->action == Action::kExit ? Exit::kNormal : Exit::kSecret;
      say(Event::Kind::kExit);
      return;
    default:
      movers_.activate(*s, wall);
      break;
  }
  if (!s->repeat) clear_special(wall);
}

// ---- teleporting ---------------------------------------------------------------

// To the first teleport destination (by thing order) in the lowest-numbered sector
// with the line's tag; facing its way, standing still, frozen for half a second.
bool World::teleport(Player& p, uint32_t wall) {
  const int tag = level_.walls[wall].tag;
  int best = -1;
  for (const level::ShownThing& shown : state_.things) {  // in THINGS order
    if (shown.placed == level::kNone) continue;
    const level::Thing& t = level_.things[size_t(shown.placed)];
    if (t.type != doom::kTeleportDestination || level_.sectors[size_t(t.sector)].tag != tag) continue;
    if (best < 0 || t.sector < level_.things[size_t(best)].sector) best = shown.placed;
  }
  if (best < 0) return false;
  const level::Thing& dest = level_.things[size_t(best)];
  p.pos = dest.pos;
  p.z = player_floor_ = heights_at(dest.pos).floor;
  p.angle = dest.angle;
  p.momentum = {0, 0};
  p.momz = 0;
  p.view_offset = 0;
  p.frozen = kTeleportFreeze;
  teleported_ = true;
  say(Event::Kind::kTeleport);
  sounds_.push_back({play::Sound::kTelept});
  return true;
}

// ---- things and sectors ----------------------------------------------------------

// Doom's P_TouchSpecialThing, for every thing it lets the player pick up: the boxes
// of the player and the thing overlap, and the thing is within reach of the feet.
void World::pick_up(Player& p) {
  std::vector<size_t> taken;  // entries of state_.things, leaving the world after the loop
  for (size_t k = 0; k < state_.things.size(); ++k) {  // in THINGS order
    if (state_.things[k].placed == level::kNone) continue;
    const size_t i = size_t(state_.things[k].placed);
    const level::Thing& t = level_.things[i];
    const play::ThingType type = pickup_types_[i];
    if (type == play::ThingType::kCount) continue;
    const double reach = kPlayerRadius + play::to_double(play::thing_info(type).radius);
    if (std::fabs(t.pos.x - p.pos.x) >= reach || std::fabs(t.pos.y - p.pos.y) >= reach) continue;
    const double dz = state_.sectors[size_t(t.sector)].floor - p.z;
    if (dz < -kPickupBelow || dz > kPlayerHeight) continue;
    const play::Pickup got = play::touch(p.inventory, p.keys, type, false, skill_);
    if (!got.taken) continue;
    // No weapon sprite runs here to lower the old weapon: the pending one is in hand at once.
    play::Inventory& inv = p.inventory;
    if (inv.pending != play::Weapon::kCount) inv.ready = std::exchange(inv.pending, play::Weapon::kCount);
    taken.push_back(k);
    const bool key = t.type == doom::kBlueCardThing || t.type == doom::kYellowCardThing || t.type == doom::kRedCardThing ||
                     t.type == doom::kBlueSkullThing || t.type == doom::kYellowSkullThing || t.type == doom::kRedSkullThing;
    if (!got.message.empty()) say(key ? Event::Kind::kKey : Event::Kind::kPickup, got.message);
    sounds_.push_back({got.sound});
  }
  for (size_t j = taken.size(); j-- > 0;) state_.things.erase(state_.things.begin() + std::ptrdiff_t(taken[j]));
}

// Standing on the floor of a secret sector finds it (once).
// And the floors that hurt, every 32 tics of level time, unless the radiation suit
// is on (super slime gets through it now and then, by Doom's play stream).
void World::in_special_sector(Player& p) {
  const int sector = level_.sector_at(p.pos);
  if (sector == level::kNone) return;
  level::SectorState& s = state_.sectors[size_t(sector)];
  if (p.z != s.floor) return;  // not all the way down yet
  const bool suit = p.inventory.powers[size_t(play::Power::kIronFeet)] != 0;
  const bool now = (level_time_ & 31) == 0;
  switch (s.special) {
    case doom::kSecretSector:
      s.special = 0;
      ++secrets_found_;
      say(Event::Kind::kSecret, "A secret is revealed!");
      break;
    case doom::kSlimeHurt:
      if (!suit && now) hurt(p, 10);
      break;
    case doom::kNukageHurt:
      if (!suit && now) hurt(p, 5);
      break;
    case doom::kSuperSlimeHurt:
    case doom::kStrobeHurt:
      if ((!suit || random_.play() < 5) && now) hurt(p, 20);
      break;
    case doom::kExitHurt:
      if (now) hurt(p, std::min(20, p.inventory.health - 1));  // Doom's hack: the end of E1M8 never kills
      if (p.inventory.health <= 10) exit_ = Exit::kNormal;
      break;
    default:
      break;
  }
}

// Doom's P_DamageMobj on the player from the world: the inventory's rules, then death,
// or pain by Doom's play stream (the player's pain chance is 255 of 256).
void World::hurt(Player& p, int amount) {
  if (p.inventory.powers[size_t(play::Power::kInvulnerability)]) return;
  play::damage(p.inventory, amount, skill_);
  if (p.inventory.health <= 0) {
    p.dead = true;
    p.momentum = {0, 0};
    sounds_.push_back({play::Sound::kPldeth});
    return;
  }
  if (random_.play() < play::thing_info(play::ThingType::kPlayer).pain_chance) sounds_.push_back({play::Sound::kPlpain});
}

}  // namespace p3d::sim
