// Sectors that move: doors, lifts, floors, stairs, ceilings and crushers (Doom's
// p_doors.c, p_plats.c, p_floor.c, p_ceilng.c). Each is a thinker that marks its
// sector busy (special_data) until it is done, so that nothing else starts there.
#include <algorithm>
#include <climits>

#include "engine/play/world.h"

namespace p3d::play {

namespace {

constexpr Fixed kDoorSpeed = 2 * kFracUnit;
constexpr int kDoorWait = 150;  // tics a raised door stays open
constexpr Fixed kPlatSpeed = kFracUnit;
constexpr int kPlatWait = 3;  // seconds a lift waits
constexpr Fixed kCeilingSpeed = kFracUnit;
constexpr int kTicRate = 35;

using MoveResult = World::MoveResult;

// The crush flag as T_MovePlane sees it. Stairs leave it uninitialised: on Doom's
// heap it is neither false nor true, so things in the way are crushed (P_ChangeSector
// only asks whether it is set) but the step goes back as a non-crushing floor does
// (T_MovePlane asks whether it is `true`). Chocolate Doom sets it to 10.
enum class Crush { kNo, kYes, kStairs };

// T_MovePlane: one tic of a floor (0) or ceiling (1) moving by `speed` towards `dest`,
// up (1) or down (-1). Things that no longer fit may stop it: it goes back, unless
// it is a crusher closing in; a ceiling going up never goes back.
MoveResult move_plane(World& w, Sector* sector, Fixed speed, Fixed dest, Crush crush, int floor_or_ceiling,
                      int direction) {
  if ((floor_or_ceiling != 0 && floor_or_ceiling != 1) || (direction != 1 && direction != -1)) return MoveResult::kOk;
  const bool crunch = crush != Crush::kNo;
  Fixed& height = floor_or_ceiling == 0 ? sector->floor_height : sector->ceiling_height;
  const Fixed last = height;
  const bool past = direction < 0 ? wrap_sub(height, speed) < dest : wrap_add(height, speed) > dest;
  if (past) {
    height = dest;
    if (w.change_sector(sector, crunch)) {  // it stays where it was, yet counts as arrived
      height = last;
      w.change_sector(sector, crunch);
    }
    return MoveResult::kPastDest;
  }
  height = direction < 0 ? wrap_sub(height, speed) : wrap_add(height, speed);
  if (!w.change_sector(sector, crunch)) return MoveResult::kOk;
  if (floor_or_ceiling == 1 && direction == 1) return MoveResult::kOk;
  const bool closing = floor_or_ceiling == 0 ? direction == 1 : direction == -1;
  if (closing && crush == Crush::kYes) return MoveResult::kCrushed;  // keeps crushing
  height = last;
  w.change_sector(sector, crunch);
  return MoveResult::kCrushed;
}

void finish(World& w, Thinker* mover, Sector* sector) {
  sector->special_data = nullptr;
  w.remove_thinker(mover);
}

// ---- doors

void door_waited(World& w, Door* door) {
  switch (door->type) {
    case Door::Type::kBlazeRaise:
      door->direction = -1;
      w.start_sector_sound(door->sector, Sound::kBdcls);
      break;
    case Door::Type::kNormal:
      door->direction = -1;
      w.start_sector_sound(door->sector, Sound::kDorcls);
      break;
    case Door::Type::kClose30ThenOpen:
      door->direction = 1;
      w.start_sector_sound(door->sector, Sound::kDoropn);
      break;
    default: break;
  }
}

void door_down(World& w, Door* door) {
  const MoveResult res = w.move_plane(door->sector, door->speed, door->sector->floor_height, false, 1, -1);
  if (res == MoveResult::kPastDest) {
    switch (door->type) {
      case Door::Type::kBlazeRaise:
      case Door::Type::kBlazeClose:
        finish(w, door, door->sector);
        w.start_sector_sound(door->sector, Sound::kBdcls);
        break;
      case Door::Type::kNormal:
      case Door::Type::kClose: finish(w, door, door->sector); break;
      case Door::Type::kClose30ThenOpen:
        door->direction = 0;
        door->top_countdown = kTicRate * 30;
        break;
      default: break;
    }
  } else if (res == MoveResult::kCrushed) {
    if (door->type == Door::Type::kBlazeClose || door->type == Door::Type::kClose) return;  // closes on anything
    door->direction = 1;
    w.start_sector_sound(door->sector, Sound::kDoropn);
  }
}

void door_up(World& w, Door* door) {
  if (w.move_plane(door->sector, door->speed, door->top_height, false, 1, 1) != MoveResult::kPastDest) return;
  switch (door->type) {
    case Door::Type::kBlazeRaise:
    case Door::Type::kNormal:
      door->direction = 0;
      door->top_countdown = door->top_wait;
      break;
    case Door::Type::kClose30ThenOpen:
    case Door::Type::kBlazeOpen:
    case Door::Type::kOpen: finish(w, door, door->sector); break;
    default: break;
  }
}

// A hand-opened door used again while its sector moves: a raising door going down
// goes back up; a player sends it down. Doom does so to whatever mover is there,
// writing a door's direction into the other's record: into a lift's wait (Doom's
// 32-bit layout; Chocolate Doom sets the wait on purpose, though on 64 bits its test
// for -1 reads the count) and a ceiling's speed (the same field in Doom and Chocolate
// Doom alike). A floor's field differs between the two, and either way it breaks the
// game later: left alone here.
void reverse_mover(Thinker* mover, const Mobj* thing) {
  int* direction = nullptr;
  switch (mover->kind) {
    case Thinker::Kind::kDoor: direction = &static_cast<Door*>(mover)->direction; break;
    case Thinker::Kind::kPlat: direction = &static_cast<Plat*>(mover)->wait; break;
    case Thinker::Kind::kCeiling: direction = &static_cast<Ceiling*>(mover)->speed; break;
    default: return;
  }
  if (*direction == -1) {
    *direction = 1;
  } else if (thing->player) {  // monsters never close doors
    *direction = -1;
  }
}

// The key a locked line asks for: blue 0, yellow 1, red 2 (the card's bit; the skull's
// is 3 higher), or -1.
int lock_color(int special) {
  switch (special) {
    case 26:
    case 32:
    case 99:
    case 133: return 0;
    case 27:
    case 34:
    case 136:
    case 137: return 1;
    case 28:
    case 33:
    case 134:
    case 135: return 2;
    default: return -1;
  }
}

bool has_key(const Player& player, int color) {
  return (player.cards >> color & 1) || (player.cards >> (color + 3) & 1);
}

// ---- plats

void add_active_plat(World& w, Plat* plat) {
  for (Plat*& slot : w.active_plats_) {
    if (!slot) {
      slot = plat;
      return;
    }
  }
  w.active_plats_.push_back(plat);
}

void remove_active_plat(World& w, Plat* plat) {
  const auto it = std::find(w.active_plats_.begin(), w.active_plats_.end(), plat);
  if (it == w.active_plats_.end()) return;  // Doom stops with an error
  finish(w, plat, plat->sector);
  *it = nullptr;
}

void plat_up(World& w, Plat* plat) {
  const MoveResult res = w.move_plane(plat->sector, plat->speed, plat->high, plat->crush, 0, 1);
  const bool changes = plat->type == Plat::Type::kRaiseAndChange || plat->type == Plat::Type::kRaiseToNearestAndChange;
  if (changes && !(w.level_time_ & 7)) w.start_sector_sound(plat->sector, Sound::kStnmov);
  if (res == MoveResult::kCrushed && !plat->crush) {
    plat->count = plat->wait;
    plat->status = Plat::Status::kDown;
    w.start_sector_sound(plat->sector, Sound::kPstart);
  } else if (res == MoveResult::kPastDest) {
    plat->count = plat->wait;
    plat->status = Plat::Status::kWaiting;
    w.start_sector_sound(plat->sector, Sound::kPstop);
    if (plat->type != Plat::Type::kPerpetualRaise) remove_active_plat(w, plat);
  }
}

// ---- floors

// sectors[s].lines[i] as Doom reads it: every sector's lines are one stretch of a
// single buffer, in sector order, so an index past a sector's own lines reads the
// next sectors' (lowerAndChange does); nullptr past the buffer's end.
Line* buffered_line(Map& map, int sector, size_t i) {
  for (size_t s = size_t(sector); s < map.sectors.size(); ++s) {
    const std::vector<Line*>& lines = map.sectors[s].lines;
    if (i < lines.size()) return lines[i];
    i -= lines.size();
  }
  return nullptr;
}

Sector* side_sector(Map& map, const Line* line, int side) {
  return line->side[size_t(side)] < 0 ? nullptr : map.sides[size_t(line->side[size_t(side)])].sector;
}

// The shortest lower texture on either side of the sector's two-sided lines, in 16.16
// (INT_MAX for none). Doom tests `bottomtexture >= 0`, which lets "-" (its texture 0)
// count with texture 0's height; a missing texture here has no height.
Fixed shortest_lower_texture(World& w, int secnum) {
  Fixed shortest = INT_MAX;
  auto consider = [&](const Side* side) {
    const int t = side->bottom;
    if (t < 0 || size_t(t) >= w.level_.textures.size()) return;
    const Fixed height = to_fixed(w.level_.textures[size_t(t)].height);
    if (height < shortest) shortest = height;
  };
  const Sector& sec = w.map_.sectors[size_t(secnum)];
  for (size_t i = 0; i < sec.lines.size(); ++i) {
    const Line* line = sec.lines[i];
    if (!(line->flags & kMlTwoSided) || line->side[0] < 0 || line->side[1] < 0) continue;
    consider(w.get_side(secnum, int(i), 0));
    consider(w.get_side(secnum, int(i), 1));
  }
  return shortest;
}

// lowerAndChange's new flat and special: those of the first neighbour across a
// two-sided line whose floor is at the destination. Doom reuses its sector variable
// for the neighbour, so the loop then runs to the neighbour's line count, reading
// past the sector's own lines into the next sectors' (buffered_line).
void find_change_model(World& w, int secnum, Floor* floor) {
  const Sector* counted = &w.map_.sectors[size_t(secnum)];
  for (size_t i = 0; i < counted->lines.size(); ++i) {
    const Line* line = buffered_line(w.map_, secnum, i);
    if (!line) return;  // past Doom's buffer
    if (!(line->flags & kMlTwoSided)) continue;
    const Sector* front = side_sector(w.map_, line, 0);
    const Sector* other = side_sector(w.map_, line, front == &w.map_.sectors[size_t(secnum)] ? 1 : 0);
    if (!front || !other) continue;  // a broken two-sided line: Doom reads a side before the first
    counted = other;
    if (other->floor_height == floor->destination) {
      floor->texture = other->floor_pic;
      floor->new_special = other->special;
      return;
    }
  }
}

void start_floor(World& w, Floor* floor, Sector* sec, int secnum, const Line* line) {
  switch (floor->type) {
    case Floor::Type::kLower:
      floor->direction = -1;
      floor->speed = kFloorSpeed;
      floor->destination = w.find_highest_floor_surrounding(sec);
      break;
    case Floor::Type::kLowerToLowest:
      floor->direction = -1;
      floor->speed = kFloorSpeed;
      floor->destination = w.find_lowest_floor_surrounding(sec);
      break;
    case Floor::Type::kTurboLower:
      floor->direction = -1;
      floor->speed = kFloorSpeed * 4;
      floor->destination = w.find_highest_floor_surrounding(sec);
      if (floor->destination != sec->floor_height) floor->destination = wrap_add(floor->destination, 8 * kFracUnit);
      break;
    case Floor::Type::kRaiseCrush:
    case Floor::Type::kRaise:
      floor->crush = floor->type == Floor::Type::kRaiseCrush;
      floor->direction = 1;
      floor->speed = kFloorSpeed;
      floor->destination = std::min(w.find_lowest_ceiling_surrounding(sec), sec->ceiling_height);
      if (floor->crush) floor->destination = wrap_sub(floor->destination, 8 * kFracUnit);
      break;
    case Floor::Type::kRaiseTurbo:
    case Floor::Type::kRaiseToNearest:
      floor->direction = 1;
      floor->speed = floor->type == Floor::Type::kRaiseTurbo ? kFloorSpeed * 4 : kFloorSpeed;
      floor->destination = w.find_next_highest_floor(sec, sec->floor_height);
      break;
    case Floor::Type::kRaise24:
    case Floor::Type::kRaise24AndChange:
    case Floor::Type::kRaise512:
      floor->direction = 1;
      floor->speed = kFloorSpeed;
      floor->destination = wrap_add(sec->floor_height, (floor->type == Floor::Type::kRaise512 ? 512 : 24) * kFracUnit);
      if (floor->type == Floor::Type::kRaise24AndChange) {
        sec->floor_pic = line->front->floor_pic;
        sec->special = line->front->special;
      }
      break;
    case Floor::Type::kRaiseToTexture:
      floor->direction = 1;
      floor->speed = kFloorSpeed;
      floor->destination = wrap_add(sec->floor_height, shortest_lower_texture(w, secnum));
      break;
    case Floor::Type::kLowerAndChange:
      floor->direction = -1;
      floor->speed = kFloorSpeed;
      floor->destination = w.find_lowest_floor_surrounding(sec);
      floor->texture = sec->floor_pic;
      find_change_model(w, secnum, floor);
      break;
    default: break;
  }
}

// One step of a staircase: a floor rising to `height`, of Doom's stairs' kind (a
// "lower" floor going up, with the crush flag Doom leaves unset).
void start_stair_step(World& w, Sector* sec, Fixed speed, Fixed height) {
  Floor* floor = w.make_thinker<Floor>();
  sec->special_data = floor;
  floor->direction = 1;
  floor->sector = sec;
  floor->speed = speed;
  floor->destination = height;
  floor->type = Floor::Type::kLower;
  floor->crush = false;  // see Crush::kStairs
}

// Doom builds stairs as lowerFloor movers going up; nothing else moves so.
bool is_stair_step(const Floor* floor) { return floor->type == Floor::Type::kLower && floor->direction == 1; }

// ---- ceilings

void add_active_ceiling(World& w, Ceiling* ceiling) {
  for (Ceiling*& slot : w.active_ceilings_) {
    if (!slot) {
      slot = ceiling;
      return;
    }
  }
  w.active_ceilings_.push_back(ceiling);  // Doom's 30 slots silently dropped the 31st
}

void remove_active_ceiling(World& w, Ceiling* ceiling) {
  const auto it = std::find(w.active_ceilings_.begin(), w.active_ceilings_.end(), ceiling);
  if (it == w.active_ceilings_.end()) return;
  finish(w, ceiling, ceiling->sector);
  *it = nullptr;
}

void ceiling_up(World& w, Ceiling* ceiling) {
  const MoveResult res = w.move_plane(ceiling->sector, ceiling->speed, ceiling->top_height, false, 1, 1);
  const bool silent = ceiling->type == Ceiling::Type::kSilentCrushAndRaise;
  if (!(w.level_time_ & 7) && !silent) w.start_sector_sound(ceiling->sector, Sound::kStnmov);
  if (res != MoveResult::kPastDest) return;
  switch (ceiling->type) {
    case Ceiling::Type::kRaiseToHighest: remove_active_ceiling(w, ceiling); break;
    case Ceiling::Type::kSilentCrushAndRaise:
      w.start_sector_sound(ceiling->sector, Sound::kPstop);
      ceiling->direction = -1;
      break;
    case Ceiling::Type::kFastCrushAndRaise:
    case Ceiling::Type::kCrushAndRaise: ceiling->direction = -1; break;
    default: break;
  }
}

void ceiling_down(World& w, Ceiling* ceiling) {
  const MoveResult res = w.move_plane(ceiling->sector, ceiling->speed, ceiling->bottom_height, ceiling->crush, 1, -1);
  const Ceiling::Type type = ceiling->type;
  const bool silent = type == Ceiling::Type::kSilentCrushAndRaise;
  if (!(w.level_time_ & 7) && !silent) w.start_sector_sound(ceiling->sector, Sound::kStnmov);
  if (res == MoveResult::kPastDest) {
    switch (type) {
      case Ceiling::Type::kSilentCrushAndRaise:
      case Ceiling::Type::kCrushAndRaise:
      case Ceiling::Type::kFastCrushAndRaise:
        if (silent) w.start_sector_sound(ceiling->sector, Sound::kPstop);
        if (type != Ceiling::Type::kFastCrushAndRaise) ceiling->speed = kCeilingSpeed;
        ceiling->direction = 1;
        break;
      case Ceiling::Type::kLowerAndCrush:
      case Ceiling::Type::kLowerToFloor: remove_active_ceiling(w, ceiling); break;
      default: break;
    }
  } else if (res == MoveResult::kCrushed) {
    // slowed down while crushing (the fast crusher is not)
    if (silent || type == Ceiling::Type::kCrushAndRaise || type == Ceiling::Type::kLowerAndCrush)
      ceiling->speed = kCeilingSpeed / 8;
  }
}

}  // namespace

World::MoveResult World::move_plane(Sector* sector, Fixed speed, Fixed dest, bool crush, int floor_or_ceiling,
                                    int direction) {
  return play::move_plane(*this, sector, speed, dest, crush ? Crush::kYes : Crush::kNo, floor_or_ceiling, direction);
}

// ---- doors (p_doors.c) --------------------------------------------------------

// T_VerticalDoor: 1 up, 0 waiting open, -1 down, 2 waiting before opening.
void World::think_door(Door* door) {
  switch (door->direction) {
    case 0:
      if (!--door->top_countdown) door_waited(*this, door);
      break;
    case 2:
      if (!--door->top_countdown && door->type == Door::Type::kRaiseIn5Mins) {
        door->direction = 1;
        door->type = Door::Type::kNormal;
        start_sector_sound(door->sector, Sound::kDoropn);
      }
      break;
    case -1: door_down(*this, door); break;
    case 1: door_up(*this, door); break;
    default: break;
  }
}

// EV_DoDoor: a door in each tagged sector not already moving; true if any started.
bool World::do_door(Line* line, Door::Type type) {
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    started = true;
    Door* door = make_thinker<Door>();
    sec->special_data = door;
    door->sector = sec;
    door->type = type;
    door->top_wait = kDoorWait;
    door->speed = kDoorSpeed;
    switch (type) {
      case Door::Type::kBlazeClose:
      case Door::Type::kClose:
        door->top_height = wrap_sub(find_lowest_ceiling_surrounding(sec), 4 * kFracUnit);
        door->direction = -1;
        if (type == Door::Type::kBlazeClose) door->speed = kDoorSpeed * 4;
        start_sector_sound(sec, type == Door::Type::kBlazeClose ? Sound::kBdcls : Sound::kDorcls);
        break;
      case Door::Type::kClose30ThenOpen:
        door->top_height = sec->ceiling_height;
        door->direction = -1;
        start_sector_sound(sec, Sound::kDorcls);
        break;
      case Door::Type::kBlazeRaise:
      case Door::Type::kBlazeOpen:
      case Door::Type::kNormal:
      case Door::Type::kOpen: {
        const bool blaze = type == Door::Type::kBlazeRaise || type == Door::Type::kBlazeOpen;
        door->direction = 1;
        door->top_height = wrap_sub(find_lowest_ceiling_surrounding(sec), 4 * kFracUnit);
        if (blaze) door->speed = kDoorSpeed * 4;
        if (door->top_height != sec->ceiling_height) start_sector_sound(sec, blaze ? Sound::kBdopn : Sound::kDoropn);
        break;
      }
      default: break;
    }
  }
  return started;
}

// EV_DoLockedDoor: switches that open doors only for the player with the key.
bool World::do_locked_door(Line* line, Door::Type type, Mobj* thing) {
  Player* player = thing->player;
  if (!player) return false;
  static constexpr const char* kNeeds[] = {"You need a blue key to activate this object",
                                           "You need a yellow key to activate this object",
                                           "You need a red key to activate this object"};
  if (const int color = lock_color(line->special); color >= 0 && !has_key(*player, color)) {
    say(*player, kNeeds[color]);
    start_sound(nullptr, Sound::kOof);
    return false;
  }
  return do_door(line, type);
}

// EV_VerticalDoor: a door used by hand opens the sector behind the line.
void World::vertical_door(Line* line, Mobj* thing) {
  mark_line(line);
  static constexpr const char* kNeeds[] = {"You need a blue key to open this door",
                                           "You need a yellow key to open this door",
                                           "You need a red key to open this door"};
  if (const int color = lock_color(line->special); color >= 0) {
    if (!thing->player) return;
    if (!has_key(*thing->player, color)) {
      say(*thing->player, kNeeds[color]);
      start_sound(nullptr, Sound::kOof);
      return;
    }
  }
  Sector* sec = side_sector(map_, line, 1);
  if (!sec) return;  // Doom stops with an error: a door on a one-sided line

  const int special = line->special;
  if (sec->special_data) {
    switch (special) {
      case 1:  // raising doors turn around; opening ones start another mover below
      case 26:
      case 27:
      case 28:
      case 117: reverse_mover(sec->special_data, thing); return;
      default: break;
    }
  }
  start_sector_sound(sec, special == 117 || special == 118 ? Sound::kBdopn : Sound::kDoropn);

  Door* door = make_thinker<Door>();
  sec->special_data = door;
  door->sector = sec;
  door->direction = 1;
  door->speed = kDoorSpeed;
  door->top_wait = kDoorWait;
  switch (special) {
    case 1:
    case 26:
    case 27:
    case 28: door->type = Door::Type::kNormal; break;
    case 31:
    case 32:
    case 33:
    case 34:
      door->type = Door::Type::kOpen;
      line->special = 0;
      break;
    case 117:
      door->type = Door::Type::kBlazeRaise;
      door->speed = kDoorSpeed * 4;
      break;
    case 118:
      door->type = Door::Type::kBlazeOpen;
      line->special = 0;
      door->speed = kDoorSpeed * 4;
      break;
    default: break;
  }
  door->top_height = wrap_sub(find_lowest_ceiling_surrounding(sec), 4 * kFracUnit);
}

// Sector special 10: the door closes after 30 seconds and stays closed.
void World::spawn_door_close_in_30(Sector* sec) {
  Door* door = make_thinker<Door>();
  sec->special_data = door;
  sec->special = 0;
  door->sector = sec;
  door->direction = 0;
  door->type = Door::Type::kNormal;
  door->speed = kDoorSpeed;
  door->top_countdown = 30 * kTicRate;
}

// Sector special 14: the door opens after 5 minutes, then closes as a raised door does.
void World::spawn_door_raise_in_5_mins(Sector* sec) {
  Door* door = make_thinker<Door>();
  sec->special_data = door;
  sec->special = 0;
  door->sector = sec;
  door->direction = 2;
  door->type = Door::Type::kRaiseIn5Mins;
  door->speed = kDoorSpeed;
  door->top_height = wrap_sub(find_lowest_ceiling_surrounding(sec), 4 * kFracUnit);
  door->top_wait = kDoorWait;
  door->top_countdown = 5 * 60 * kTicRate;
}

// ---- lifts (p_plats.c) --------------------------------------------------------

// T_PlatRaise
void World::think_plat(Plat* plat) {
  switch (plat->status) {
    case Plat::Status::kUp: plat_up(*this, plat); break;
    case Plat::Status::kDown:
      if (move_plane(plat->sector, plat->speed, plat->low, false, 0, -1) == MoveResult::kPastDest) {
        plat->count = plat->wait;
        plat->status = Plat::Status::kWaiting;
        start_sector_sound(plat->sector, Sound::kPstop);
      }
      break;
    case Plat::Status::kWaiting:
      if (!--plat->count) {
        plat->status = plat->sector->floor_height == plat->low ? Plat::Status::kUp : Plat::Status::kDown;
        start_sector_sound(plat->sector, Sound::kPstart);
      }
      break;
    case Plat::Status::kInStasis: break;
  }
}

// EV_DoPlat: a lift in each tagged sector not already moving (perpetual lifts stopped
// earlier start again first). `amount`: the rise of kRaiseAndChange.
bool World::do_plat(Line* line, Plat::Type type, int amount) {
  if (type == Plat::Type::kPerpetualRaise) activate_in_stasis(line->tag);
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    started = true;
    Plat* plat = make_thinker<Plat>();
    plat->type = type;
    plat->sector = sec;
    sec->special_data = plat;
    plat->crush = false;
    plat->tag = line->tag;
    switch (type) {
      case Plat::Type::kRaiseToNearestAndChange:
      case Plat::Type::kRaiseAndChange:
        plat->speed = kPlatSpeed / 2;
        sec->floor_pic = side_sector(map_, line, 0)->floor_pic;
        plat->high = type == Plat::Type::kRaiseAndChange ? wrap_add(sec->floor_height, amount * kFracUnit)
                                                         : find_next_highest_floor(sec, sec->floor_height);
        plat->wait = 0;
        plat->status = Plat::Status::kUp;
        if (type == Plat::Type::kRaiseToNearestAndChange) sec->special = 0;  // no more hurting
        start_sector_sound(sec, Sound::kStnmov);
        break;
      case Plat::Type::kDownWaitUpStay:
      case Plat::Type::kBlazeDwus:
        plat->speed = kPlatSpeed * (type == Plat::Type::kBlazeDwus ? 8 : 4);
        plat->low = std::min(find_lowest_floor_surrounding(sec), sec->floor_height);
        plat->high = sec->floor_height;
        plat->wait = kTicRate * kPlatWait;
        plat->status = Plat::Status::kDown;
        start_sector_sound(sec, Sound::kPstart);
        break;
      case Plat::Type::kPerpetualRaise:
        plat->speed = kPlatSpeed;
        plat->low = std::min(find_lowest_floor_surrounding(sec), sec->floor_height);
        plat->high = std::max(find_highest_floor_surrounding(sec), sec->floor_height);
        plat->wait = kTicRate * kPlatWait;
        plat->status = Plat::Status(random_.play() & 1);  // up or down
        start_sector_sound(sec, Sound::kPstart);
        break;
    }
    add_active_plat(*this, plat);
  }
  return started;
}

// P_ActivateInStasis: lifts of this tag stopped by a line start again.
void World::activate_in_stasis(int tag) {
  for (Plat* plat : active_plats_) {
    if (plat && plat->tag == tag && plat->status == Plat::Status::kInStasis) {
      plat->status = plat->old_status;
      plat->active = true;
    }
  }
}

// EV_StopPlat
void World::stop_plat(Line* line) {
  for (Plat* plat : active_plats_) {
    if (plat && plat->status != Plat::Status::kInStasis && plat->tag == line->tag) {
      plat->old_status = plat->status;
      plat->status = Plat::Status::kInStasis;
      plat->active = false;
    }
  }
}

// ---- floors (p_floor.c) -------------------------------------------------------

// T_MoveFloor: on arrival a donut's ring and a lowerAndChange floor take their new
// flat and special.
void World::think_floor(Floor* floor) {
  const Crush crush = is_stair_step(floor) ? Crush::kStairs : floor->crush ? Crush::kYes : Crush::kNo;
  const MoveResult res =
      play::move_plane(*this, floor->sector, floor->speed, floor->destination, crush, 0, floor->direction);
  if (!(level_time_ & 7)) start_sector_sound(floor->sector, Sound::kStnmov);
  if (res != MoveResult::kPastDest) return;
  floor->sector->special_data = nullptr;
  const bool changes = (floor->direction == 1 && floor->type == Floor::Type::kDonutRaise) ||
                       (floor->direction == -1 && floor->type == Floor::Type::kLowerAndChange);
  if (changes) {
    floor->sector->special = floor->new_special;
    floor->sector->floor_pic = floor->texture;
  }
  remove_thinker(floor);
  start_sector_sound(floor->sector, Sound::kPstop);
}

// EV_DoFloor: a floor mover in each tagged sector not already moving.
bool World::do_floor(Line* line, Floor::Type type) {
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    started = true;
    Floor* floor = make_thinker<Floor>();
    sec->special_data = floor;
    floor->type = type;
    floor->crush = false;
    floor->sector = sec;
    start_floor(*this, floor, sec, secnum, line);
  }
  return started;
}

// EV_BuildStairs: from each tagged sector, each step is the sector behind the first
// two-sided line that faces out of the last step (its front on the last step's side)
// with the same flat, rising a step higher. A step already moving still counts in
// the height, and the search goes on from there. The next tagged sector is searched
// for after the last step's number, as Doom does.
bool World::build_stairs(Line* line, bool turbo) {
  const Fixed speed = turbo ? kFloorSpeed * 4 : kFloorSpeed / 4;
  const Fixed step = (turbo ? 16 : 8) * kFracUnit;
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    started = true;
    Fixed height = wrap_add(sec->floor_height, step);
    start_stair_step(*this, sec, speed, height);
    const int flat = sec->floor_pic;
    for (bool found = true; found;) {
      found = false;
      for (Line* l : sec->lines) {
        if (!(l->flags & kMlTwoSided) || l->front != &map_.sectors[size_t(secnum)]) continue;
        Sector* next = l->back;
        if (!next || next->floor_pic != flat) continue;  // (a two-sided line has a back in Doom's maps)
        height = wrap_add(height, step);
        if (next->special_data) continue;
        sec = next;
        secnum = next->index;
        start_stair_step(*this, sec, speed, height);
        found = true;
        break;
      }
    }
  }
  return started;
}

// ---- ceilings (p_ceilng.c) ----------------------------------------------------

// T_MoveCeiling: crushers go down and up for ever; the others stop at the end.
void World::think_ceiling(Ceiling* ceiling) {
  switch (ceiling->direction) {
    case 1: ceiling_up(*this, ceiling); break;
    case -1: ceiling_down(*this, ceiling); break;
    default: break;  // 0: stopped
  }
}

// EV_DoCeiling: a ceiling mover in each tagged sector not already moving (crushers of
// the tag stopped earlier start again first).
bool World::do_ceiling(Line* line, Ceiling::Type type) {
  switch (type) {
    case Ceiling::Type::kFastCrushAndRaise:
    case Ceiling::Type::kSilentCrushAndRaise:
    case Ceiling::Type::kCrushAndRaise: activate_in_stasis_ceiling(line); break;
    default: break;
  }
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    started = true;
    Ceiling* ceiling = make_thinker<Ceiling>();
    sec->special_data = ceiling;
    ceiling->sector = sec;
    ceiling->crush = false;
    switch (type) {
      case Ceiling::Type::kFastCrushAndRaise:
        ceiling->crush = true;
        ceiling->top_height = sec->ceiling_height;
        ceiling->bottom_height = wrap_add(sec->floor_height, 8 * kFracUnit);
        ceiling->direction = -1;
        ceiling->speed = kCeilingSpeed * 2;
        break;
      case Ceiling::Type::kSilentCrushAndRaise:
      case Ceiling::Type::kCrushAndRaise:
        ceiling->crush = true;
        ceiling->top_height = sec->ceiling_height;
        [[fallthrough]];
      case Ceiling::Type::kLowerAndCrush:
      case Ceiling::Type::kLowerToFloor:
        ceiling->bottom_height = sec->floor_height;
        if (type != Ceiling::Type::kLowerToFloor)
          ceiling->bottom_height = wrap_add(ceiling->bottom_height, 8 * kFracUnit);
        ceiling->direction = -1;
        ceiling->speed = kCeilingSpeed;
        break;
      case Ceiling::Type::kRaiseToHighest:
        ceiling->top_height = find_highest_ceiling_surrounding(sec);
        ceiling->direction = 1;
        ceiling->speed = kCeilingSpeed;
        break;
    }
    ceiling->tag = sec->tag;
    ceiling->type = type;
    add_active_ceiling(*this, ceiling);
  }
  return started;
}

// EV_CeilingCrushStop: moving crushers of the line's tag stop where they are.
bool World::ceiling_crush_stop(Line* line) {
  bool stopped = false;
  for (Ceiling* ceiling : active_ceilings_) {
    if (ceiling && ceiling->tag == line->tag && ceiling->direction != 0) {
      ceiling->old_direction = ceiling->direction;
      ceiling->active = false;
      ceiling->direction = 0;
      stopped = true;
    }
  }
  return stopped;
}

// P_ActivateInStasisCeiling
void World::activate_in_stasis_ceiling(Line* line) {
  for (Ceiling* ceiling : active_ceilings_) {
    if (ceiling && ceiling->tag == line->tag && ceiling->direction == 0) {
      ceiling->direction = ceiling->old_direction;
      ceiling->active = true;
    }
  }
}

}  // namespace p3d::play
