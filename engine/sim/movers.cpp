// Index: construction (walls and tags by sector, the sector specials' lights and
// timed doors), neighbour queries, starting movers per action, move_plane (Doom's
// T_MovePlane), one tic of each kind of mover, lights.
#include "engine/sim/movers.h"

#include "engine/util/doom.h"

#include <algorithm>
#include <cmath>

namespace p3d::sim {

namespace {

constexpr int kDoorWait = 150;          // tics a raised door stays open
constexpr int kDoorCloseWait = 30 * 35; // tics a close-and-reopen door stays shut
constexpr int kDoorRaiseIn5Min = 5 * 60 * 35;
constexpr int kPlatWait = 3 * 35;
constexpr double kDoorGap = 4;          // a door opens to the lowest neighbour ceiling - 4
constexpr double kCrusherGap = 8;       // crushers come down to floor + 8
constexpr double kCrushingSpeed = 1.0 / 8;
constexpr double kDoorSpeed = 2;
constexpr double kNoNeighbourFloor = -500;  // Doom's start for the highest surrounding floor
constexpr int kGlowStep = 8;
constexpr int kStrobeBright = 5, kStrobeFastDark = 15, kStrobeSlowDark = 35;

using namespace doom;

const std::vector<int> kNoSectors;

}  // namespace

Movers::Movers(const level::Level& level, level::State& state, play::Random& random)
    : level_(level), state_(state), random_(random), busy_(level.sectors.size(), 0), sector_walls_(level.sectors.size()) {
  for (uint32_t w = 0; w < level.walls.size(); ++w) {
    const level::Wall& wall = level.walls[w];
    if (!wall.two_sided()) continue;
    sector_walls_[size_t(wall.sides[0].sector)].push_back(w);
    if (wall.sides[1].sector != wall.sides[0].sector) sector_walls_[size_t(wall.sides[1].sector)].push_back(w);
  }
  for (size_t s = 0; s < level.sectors.size(); ++s) tagged_[level.sectors[s].tag].push_back(int(s));
  start_lights_and_timers();
}

const std::vector<int>& Movers::tagged(int tag) const {
  const auto it = tagged_.find(tag);
  return it == tagged_.end() ? kNoSectors : it->second;
}

int Movers::other_side(uint32_t wall, int sector) const {
  const level::Wall& w = level_.walls[wall];
  return w.sides[0].sector == sector ? w.sides[1].sector : w.sides[0].sector;
}

int Movers::next_random() { return random_.play(); }

// ---- neighbours ----------------------------------------------------------------

double Movers::lowest_floor_around(int sector) const {
  double h = state_.sectors[size_t(sector)].floor;
  for (uint32_t w : sector_walls_[size_t(sector)]) h = std::min(h, state_.sectors[size_t(other_side(w, sector))].floor);
  return h;
}

double Movers::highest_floor_around(int sector) const {
  double h = kNoNeighbourFloor;
  for (uint32_t w : sector_walls_[size_t(sector)]) h = std::max(h, state_.sectors[size_t(other_side(w, sector))].floor);
  return h;
}

double Movers::next_higher_floor(int sector, double height) const {
  double h = INFINITY;
  for (uint32_t w : sector_walls_[size_t(sector)]) {
    const double f = state_.sectors[size_t(other_side(w, sector))].floor;
    if (f > height) h = std::min(h, f);
  }
  return h == INFINITY ? height : h;
}

double Movers::lowest_ceiling_around(int sector) const {
  double h = INFINITY;
  for (uint32_t w : sector_walls_[size_t(sector)]) h = std::min(h, state_.sectors[size_t(other_side(w, sector))].ceiling);
  return h == INFINITY ? state_.sectors[size_t(sector)].ceiling : h;
}

double Movers::highest_ceiling_around(int sector) const {
  double h = 0;
  for (uint32_t w : sector_walls_[size_t(sector)]) h = std::max(h, state_.sectors[size_t(other_side(w, sector))].ceiling);
  return h;
}

int Movers::darkest_around(int sector, int start) const {
  int light = start;
  for (uint32_t w : sector_walls_[size_t(sector)]) light = std::min(light, state_.sectors[size_t(other_side(w, sector))].light);
  return light;
}

int Movers::brightest_around(int sector) const {
  int light = 0;
  for (uint32_t w : sector_walls_[size_t(sector)]) light = std::max(light, state_.sectors[size_t(other_side(w, sector))].light);
  return light;
}

// ---- starting ------------------------------------------------------------------

Movers::Mover& Movers::add(Kind kind, Action action, int sector, double speed) {
  busy_[size_t(sector)] = 1;
  Mover m{};
  m.kind = kind;
  m.action = action;
  m.sector = sector;
  m.tag = level_.sectors[size_t(sector)].tag;
  m.speed = m.base_speed = speed;
  movers_.push_back(m);
  return movers_.back();
}

bool Movers::activate(const LineSpecial& s, uint32_t wall) {
  const int tag = level_.walls[wall].tag;
  bool started = false;
  switch (s.action) {
    case Action::kPlatStop:
      for (Mover& m : movers_)
        if (m.kind == Kind::kPlat && m.tag == tag && m.status != Status::kStopped) {
          m.old_status = m.status;
          m.status = Status::kStopped;
          started = true;
        }
      return started;
    case Action::kCeilingCrushStop:
      for (Mover& m : movers_)
        if (m.kind == Kind::kCeiling && m.tag == tag && m.direction != 0) {
          m.old_direction = m.direction;
          m.direction = 0;
          started = true;
        }
      return started;
    case Action::kPlatPerpetual:  // restarts stopped plats first (not counted as starting anything)
      for (Mover& m : movers_)
        if (m.kind == Kind::kPlat && m.tag == tag && m.status == Status::kStopped) m.status = m.old_status;
      break;
    case Action::kCeilingCrushAndRaise:  // likewise for stopped crushers
      for (Mover& m : movers_)
        if (m.kind == Kind::kCeiling && m.tag == tag && m.direction == 0) m.direction = m.old_direction;
      break;
    default:
      break;
  }
  for (int sector : tagged(tag)) {
    switch (s.action) {
      case Action::kLightToBrightest:
      case Action::kLightTo:
      case Action::kLightToDarkest:
      case Action::kLightStrobe:
        started |= change_light(s, sector);
        continue;
      default:
        break;
    }
    if (busy(sector)) continue;
    switch (s.action) {
      case Action::kDoorRaise:
      case Action::kDoorOpen:
      case Action::kDoorClose:
      case Action::kDoorCloseWait:
        started |= start_door(s, sector);
        break;
      case Action::kPlatDownWaitUp:
      case Action::kPlatPerpetual:
      case Action::kPlatRaiseAndChange:
      case Action::kPlatRaiseToNearestAndChange:
        started |= start_plat(s, sector, wall);
        break;
      case Action::kCeilingLowerToFloor:
      case Action::kCeilingLowerAndCrush:
      case Action::kCeilingCrushAndRaise:
      case Action::kCeilingRaiseToHighest:
        started |= start_ceiling(s, sector);
        break;
      case Action::kStairs:
        started |= build_stairs(s, sector);
        break;
      case Action::kDonut:
        started |= start_donut(s, sector);
        break;
      case Action::kFloorLowerToHighest:
      case Action::kFloorLowerToLowest:
      case Action::kFloorTurboLower:
      case Action::kFloorLowerAndChange:
      case Action::kFloorRaise:
      case Action::kFloorRaiseToNearest:
      case Action::kFloorRaiseBy:
      case Action::kFloorRaiseByAndChange:
      case Action::kFloorRaiseToTexture:
        started |= start_floor(s, sector, wall);
        break;
      default:  // teleports and exits act on the player, not on sectors
        break;
    }
  }
  return started;
}

bool Movers::use_door(const LineSpecial& s, uint32_t wall) {
  const int sector = level_.walls[wall].sides[1].sector;
  if (sector == level::kNone) return false;
  if (busy(sector)) {
    // Only raise doors react to use while they move; open-once doors ignore it.
    if (s.action != Action::kDoorRaise) return false;
    for (Mover& m : movers_)
      if (m.sector == sector && m.kind == Kind::kDoor && !m.finished) {
        m.direction = m.direction == -1 ? 1 : -1;  // closing: reopen; else close now
        return true;
      }
    return false;
  }
  return start_door(s, sector);
}

bool Movers::start_door(const LineSpecial& s, int sector) {
  Mover& m = add(Kind::kDoor, s.action, sector, s.speed);
  m.blaze = s.blaze;
  m.wait = kDoorWait;
  m.high = lowest_ceiling_around(sector) - kDoorGap;
  switch (s.action) {
    case Action::kDoorClose:
      m.direction = -1;
      break;
    case Action::kDoorCloseWait:
      m.direction = -1;
      m.high = state_.sectors[size_t(sector)].ceiling;  // it reopens to where it was
      break;
    default:
      m.direction = 1;
      break;
  }
  door_sound(m);
  return true;
}

void Movers::door_sound(const Mover& m) {
  using play::Sound;
  if (m.direction == 1) sound(m.blaze ? Sound::kBdopn : Sound::kDoropn, m.sector);
  if (m.direction == -1) sound(m.blaze ? Sound::kBdcls : Sound::kDorcls, m.sector);
}

bool Movers::start_floor(const LineSpecial& s, int sector, uint32_t wall) {
  level::SectorState& sec = state_.sectors[size_t(sector)];
  Mover& m = add(Kind::kFloor, s.action, sector, s.speed);
  m.crush = s.crush;
  m.direction = 1;
  double dest = sec.floor;
  switch (s.action) {
    case Action::kFloorLowerToHighest:
      dest = highest_floor_around(sector);
      m.direction = -1;
      break;
    case Action::kFloorLowerToLowest:
      dest = lowest_floor_around(sector);
      m.direction = -1;
      break;
    case Action::kFloorTurboLower:
      dest = highest_floor_around(sector);
      if (dest != sec.floor) dest += 8;
      m.direction = -1;
      break;
    case Action::kFloorLowerAndChange: {
      dest = lowest_floor_around(sector);
      m.direction = -1;
      m.change_texture = sec.floor_texture;
      m.change_special = sec.special;
      for (uint32_t w : sector_walls_[size_t(sector)]) {  // the first neighbour at that height gives its flat
        const level::SectorState& n = state_.sectors[size_t(other_side(w, sector))];
        if (n.floor == dest) {
          m.change_texture = n.floor_texture;
          m.change_special = n.special;
          break;
        }
      }
      break;
    }
    case Action::kFloorRaise:
      dest = std::min(lowest_ceiling_around(sector), sec.ceiling) - s.amount;
      break;
    case Action::kFloorRaiseToNearest:
      dest = next_higher_floor(sector, sec.floor);
      break;
    case Action::kFloorRaiseBy:
      dest = sec.floor + s.amount;
      break;
    case Action::kFloorRaiseByAndChange: {
      dest = sec.floor + s.amount;
      const int front = level_.walls[wall].sides[0].sector;
      sec.floor_texture = state_.sectors[size_t(front)].floor_texture;
      sec.special = state_.sectors[size_t(front)].special;
      break;
    }
    case Action::kFloorRaiseToTexture: {
      int shortest = 0;
      for (uint32_t w : sector_walls_[size_t(sector)])
        for (int side = 0; side < 2; ++side) {
          const int t = state_.texture(w, side, level::kLowerPart);
          if (t < 0) continue;
          const int h = level_.textures[size_t(t)].height;
          if (shortest == 0 || h < shortest) shortest = h;
        }
      dest = sec.floor + shortest;
      break;
    }
    default:
      break;
  }
  (m.direction > 0 ? m.high : m.low) = dest;
  return true;
}

bool Movers::start_plat(const LineSpecial& s, int sector, uint32_t wall) {
  level::SectorState& sec = state_.sectors[size_t(sector)];
  Mover& m = add(Kind::kPlat, s.action, sector, s.speed);
  m.tag = level_.walls[wall].tag;
  m.low = m.high = sec.floor;
  const int front = level_.walls[wall].sides[0].sector;
  switch (s.action) {
    case Action::kPlatDownWaitUp:
      m.low = std::min(lowest_floor_around(sector), sec.floor);
      m.wait = kPlatWait;
      m.status = Status::kDown;
      break;
    case Action::kPlatPerpetual:
      m.low = std::min(lowest_floor_around(sector), sec.floor);
      m.high = std::max(highest_floor_around(sector), sec.floor);
      m.wait = kPlatWait;
      m.status = (next_random() & 1) ? Status::kDown : Status::kUp;
      break;
    case Action::kPlatRaiseAndChange:
      m.high = sec.floor + s.amount;
      m.status = Status::kUp;
      sec.floor_texture = state_.sectors[size_t(front)].floor_texture;
      break;
    case Action::kPlatRaiseToNearestAndChange:
      m.high = next_higher_floor(sector, sec.floor);
      m.status = Status::kUp;
      sec.floor_texture = state_.sectors[size_t(front)].floor_texture;
      sec.special = 0;
      break;
    default:
      break;
  }
  const bool changes = s.action == Action::kPlatRaiseAndChange || s.action == Action::kPlatRaiseToNearestAndChange;
  sound(changes ? play::Sound::kStnmov : play::Sound::kPstart, sector);
  return true;
}

bool Movers::start_ceiling(const LineSpecial& s, int sector) {
  const level::SectorState& sec = state_.sectors[size_t(sector)];
  Mover& m = add(Kind::kCeiling, s.action, sector, s.speed);
  m.crush = s.crush;
  m.blaze = s.blaze;
  m.direction = -1;
  m.low = sec.floor;
  m.high = sec.ceiling;
  switch (s.action) {
    case Action::kCeilingLowerAndCrush:
    case Action::kCeilingCrushAndRaise:
      m.low = sec.floor + kCrusherGap;
      break;
    case Action::kCeilingRaiseToHighest:
      m.high = highest_ceiling_around(sector);
      m.direction = 1;
      break;
    default:
      break;
  }
  return true;
}

// Each step is the sector across a two-sided line whose front is the previous step
// and whose floor has the first step's flat; step k rises to the first floor + k
// steps (a busy sector in the way still counts a step).
bool Movers::build_stairs(const LineSpecial& s, int sector) {
  double height = state_.sectors[size_t(sector)].floor + s.amount;
  const int flat = state_.sectors[size_t(sector)].floor_texture;
  Mover* m = &add(Kind::kFloor, s.action, sector, s.speed);
  m->direction = 1;
  m->high = height;
  for (bool more = true; more;) {
    more = false;
    for (uint32_t w : sector_walls_[size_t(sector)]) {
      const level::Wall& wall = level_.walls[w];
      if (wall.sides[0].sector != sector) continue;
      const int next = wall.sides[1].sector;
      if (state_.sectors[size_t(next)].floor_texture != flat) continue;
      height += s.amount;
      if (busy(next)) continue;
      sector = next;
      m = &add(Kind::kFloor, s.action, sector, s.speed);
      m->direction = 1;
      m->high = height;
      more = true;
      break;
    }
  }
  return true;
}

// A pillar (the tagged sector) sinks while the ring around it rises, both to the
// floor of the sector beyond the ring, whose flat the ring takes.
bool Movers::start_donut(const LineSpecial& s, int pillar) {
  const auto& pillar_walls = sector_walls_[size_t(pillar)];
  if (pillar_walls.empty()) return false;
  const int ring = other_side(pillar_walls.front(), pillar);
  int beyond = level::kNone;
  for (uint32_t w : sector_walls_[size_t(ring)]) {
    const int back = level_.walls[w].sides[1].sector;
    if (back != pillar) {
      beyond = back;
      break;
    }
  }
  if (beyond == level::kNone || ring == pillar || busy(ring)) return false;
  const level::SectorState& b = state_.sectors[size_t(beyond)];
  Mover& r = add(Kind::kFloor, Action::kFloorRaiseBy, ring, s.speed);
  r.direction = 1;
  r.high = b.floor;
  r.change_texture = b.floor_texture;
  r.change_special = 0;
  Mover& p = add(Kind::kFloor, Action::kFloorLowerToLowest, pillar, s.speed);
  p.direction = -1;
  p.low = b.floor;
  return true;
}

bool Movers::change_light(const LineSpecial& s, int sector) {
  level::SectorState& sec = state_.sectors[size_t(sector)];
  switch (s.action) {
    case Action::kLightToBrightest:
      sec.light = brightest_around(sector);
      return true;
    case Action::kLightTo:
      sec.light = s.amount;
      return true;
    case Action::kLightToDarkest:
      sec.light = darkest_around(sector, sec.light);
      return true;
    case Action::kLightStrobe:
      if (busy(sector)) return false;
      add_strobe(sector, kStrobeSlowDark, false);
      sec.special = 0;
      return true;
    default:
      return false;
  }
}

void Movers::add_strobe(int sector, int dark_time, bool in_sync) {
  const int light = state_.sectors[size_t(sector)].light;
  Light l{Light::Kind::kStrobe, sector, darkest_around(sector, light), light};
  if (l.low == l.high) l.low = 0;
  l.low_time = dark_time;
  l.high_time = kStrobeBright;
  l.count = in_sync ? 1 : (next_random() & 7) + 1;
  lights_.push_back(l);
}

void Movers::start_lights_and_timers() {
  for (size_t i = 0; i < state_.sectors.size(); ++i) {
    const int sector = int(i);
    level::SectorState& sec = state_.sectors[i];
    switch (sec.special) {
      case kLightFlicker: {
        Light l{Light::Kind::kFlash, sector, darkest_around(sector, sec.light), sec.light};
        l.high_time = 64;
        l.low_time = 7;
        l.count = (next_random() & l.high_time) + 1;
        lights_.push_back(l);
        break;
      }
      case kStrobeFast:
      case kStrobeHurt:
        add_strobe(sector, kStrobeFastDark, false);
        break;
      case kStrobeSlow:
        add_strobe(sector, kStrobeSlowDark, false);
        break;
      case kStrobeSlowSync:
        add_strobe(sector, kStrobeSlowDark, true);
        break;
      case kStrobeFastSync:
        add_strobe(sector, kStrobeFastDark, true);
        break;
      case kGlow:
        lights_.push_back({Light::Kind::kGlow, sector, darkest_around(sector, sec.light), sec.light});
        break;
      case kFireFlicker: {
        Light l{Light::Kind::kFlicker, sector, darkest_around(sector, sec.light) + 16, sec.light};
        l.count = 4;
        lights_.push_back(l);
        break;
      }
      case kDoorCloseIn30: {
        Mover& m = add(Kind::kDoor, Action::kDoorRaise, sector, kDoorSpeed);
        m.direction = 0;
        m.count = kDoorCloseWait;
        m.wait = kDoorWait;
        m.high = sec.ceiling;
        break;
      }
      case kDoorRaiseIn5Min: {
        Mover& m = add(Kind::kDoor, Action::kDoorRaise, sector, kDoorSpeed);
        m.direction = 2;
        m.count = kDoorRaiseIn5Min;
        m.wait = kDoorWait;
        m.high = lowest_ceiling_around(sector) - kDoorGap;
        break;
      }
      default:
        continue;  // secrets (9) and damage keep their special; others mean nothing
    }
    if (sec.special != kStrobeHurt) sec.special = 0;
  }
}

// ---- moving --------------------------------------------------------------------

// Doom's T_MovePlane, never crushing: a plane steps by the mover's speed and lands
// exactly on dest (from beyond dest it jumps there). If what stands there no longer
// fits, the plane goes back, except a rising ceiling, which never hurts.
Movers::Moved Movers::move_plane(Mover& m, Plane plane, double dest, int direction, const FitsAfterMove& fits) {
  level::SectorState& sec = state_.sectors[size_t(m.sector)];
  double& h = plane == Plane::kFloor ? sec.floor : sec.ceiling;
  const double old = h;
  const bool lands = direction < 0 ? h - m.speed < dest : h + m.speed > dest;
  h = lands ? dest : h + direction * m.speed;
  if (fits(m.sector)) return lands ? Moved::kArrived : Moved::kOk;
  if (!lands && plane == Plane::kCeiling && direction > 0) return Moved::kOk;  // rising ceilings never stop
  h = old;
  fits(m.sector);
  return lands ? Moved::kArrived : Moved::kBlocked;
}

void Movers::tick_door(Mover& m, const FitsAfterMove& fits) {
  switch (m.direction) {
    case 0:  // open, waiting to close (or closed, waiting to reopen)
      if (--m.count == 0) {
        m.direction = m.action == Action::kDoorCloseWait ? 1 : m.action == Action::kDoorRaise ? -1 : 0;
        if (m.direction == 1) sound(play::Sound::kDoropn, m.sector);  // Doom reopens with the plain sound
        if (m.direction == -1) door_sound(m);
      }
      return;
    case 2:  // waiting to open
      if (--m.count == 0) {
        m.direction = 1;
        sound(play::Sound::kDoropn, m.sector);
      }
      return;
    case -1: {
      const Moved r = move_plane(m, Plane::kCeiling, state_.sectors[size_t(m.sector)].floor, -1, fits);
      if (r == Moved::kArrived) {
        if (m.blaze) sound(play::Sound::kBdcls, m.sector);  // a fast door slams shut
        if (m.action == Action::kDoorCloseWait) {
          m.direction = 0;
          m.count = kDoorCloseWait;
        } else {
          m.finished = true;
        }
      } else if (r == Moved::kBlocked && m.action != Action::kDoorClose) {
        m.direction = 1;  // something in the way: back up
        sound(play::Sound::kDoropn, m.sector);
      }
      return;
    }
    case 1:
      if (move_plane(m, Plane::kCeiling, m.high, 1, fits) == Moved::kArrived) {
        if (m.action == Action::kDoorRaise) {
          m.direction = 0;
          m.count = m.wait;
        } else {
          m.finished = true;
        }
      }
      return;
    default:
      return;
  }
}

void Movers::tick_floor(Mover& m, const FitsAfterMove& fits) {
  grind(m);
  const double dest = m.direction > 0 ? m.high : m.low;
  if (move_plane(m, Plane::kFloor, dest, m.direction, fits) != Moved::kArrived) return;  // blocked floors wait
  sound(play::Sound::kPstop, m.sector);
  m.finished = true;
  level::SectorState& sec = state_.sectors[size_t(m.sector)];
  if (m.change_texture != level::kNone) sec.floor_texture = m.change_texture;
  if (m.change_special >= 0) sec.special = m.change_special;
}

void Movers::tick_plat(Mover& m, const FitsAfterMove& fits) {
  const bool changes = m.action == Action::kPlatRaiseAndChange || m.action == Action::kPlatRaiseToNearestAndChange;
  switch (m.status) {
    case Status::kUp: {
      if (changes) grind(m);
      const Moved r = move_plane(m, Plane::kFloor, m.high, 1, fits);
      if (r == Moved::kBlocked && !changes) {  // a lift that meets the player goes back down
        m.status = Status::kDown;
        m.count = m.wait;
        sound(play::Sound::kPstart, m.sector);
      } else if (r == Moved::kArrived) {
        m.status = Status::kWaiting;
        m.count = m.wait;
        sound(play::Sound::kPstop, m.sector);
        if (m.action != Action::kPlatPerpetual) m.finished = true;
      }
      return;
    }
    case Status::kDown:
      if (move_plane(m, Plane::kFloor, m.low, -1, fits) == Moved::kArrived) {
        m.status = Status::kWaiting;
        m.count = m.wait;
        sound(play::Sound::kPstop, m.sector);
      }
      return;
    case Status::kWaiting:
      if (--m.count == 0) {
        m.status = state_.sectors[size_t(m.sector)].floor == m.low ? Status::kUp : Status::kDown;
        sound(play::Sound::kPstart, m.sector);
      }
      return;
    case Status::kStopped:
      return;
  }
}

void Movers::tick_ceiling(Mover& m, const FitsAfterMove& fits) {
  const bool crusher = m.action == Action::kCeilingCrushAndRaise;
  if (m.direction != 0) grind(m);
  if (m.direction == 1) {
    if (move_plane(m, Plane::kCeiling, m.high, 1, fits) == Moved::kArrived) {
      if (crusher)
        m.direction = -1;
      else
        m.finished = true;
    }
  } else if (m.direction == -1) {
    const Moved r = move_plane(m, Plane::kCeiling, m.low, -1, fits);
    if (r == Moved::kArrived) {
      if (crusher) {
        m.direction = 1;
        m.speed = m.base_speed;
      } else {
        m.finished = true;
      }
    } else if (r == Moved::kBlocked && !m.blaze && (crusher || m.action == Action::kCeilingLowerAndCrush)) {
      m.speed = kCrushingSpeed;  // slows at the player, as Doom's crushers slow on what they crush
    }
  }
}

void Movers::tick_light(Light& l) {
  int& light = state_.sectors[size_t(l.sector)].light;
  switch (l.kind) {
    case Light::Kind::kFlash:
      if (--l.count) return;
      if (light == l.high) {
        light = l.low;
        l.count = (next_random() & l.low_time) + 1;
      } else {
        light = l.high;
        l.count = (next_random() & l.high_time) + 1;
      }
      return;
    case Light::Kind::kStrobe:
      if (--l.count) return;
      if (light == l.low) {
        light = l.high;
        l.count = l.high_time;
      } else {
        light = l.low;
        l.count = l.low_time;
      }
      return;
    case Light::Kind::kGlow:
      if (l.direction < 0) {
        light -= kGlowStep;
        if (light <= l.low) {
          light += kGlowStep;
          l.direction = 1;
        }
      } else {
        light += kGlowStep;
        if (light >= l.high) {
          light -= kGlowStep;
          l.direction = -1;
        }
      }
      return;
    case Light::Kind::kFlicker: {
      if (--l.count) return;
      const int amount = (next_random() & 3) * 16;
      light = light - amount < l.low ? l.low : l.high - amount;
      l.count = 4;
      return;
    }
  }
}

void Movers::tick(const FitsAfterMove& fits) {
  for (Mover& m : movers_) {
    switch (m.kind) {
      case Kind::kDoor:
        tick_door(m, fits);
        break;
      case Kind::kFloor:
        tick_floor(m, fits);
        break;
      case Kind::kPlat:
        tick_plat(m, fits);
        break;
      case Kind::kCeiling:
        tick_ceiling(m, fits);
        break;
    }
    if (m.finished) busy_[size_t(m.sector)] = 0;
  }
  std::erase_if(movers_, [](const Mover& m) { return m.finished; });
  for (Light& l : lights_) tick_light(l);
  ++time_;
}

}  // namespace p3d::sim
