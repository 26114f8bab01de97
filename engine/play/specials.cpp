// Lines walked over, used and shot; sectors that hurt or count as secrets; what the
// level's specials start with; switches and teleporters (Doom's p_spec.c,
// p_switch.c, p_telept.c). The textures' animation is not here: the renderers
// draw it from the level time.
#include <cctype>
#include <climits>
#include <iterator>
#include <string_view>
#include <unordered_map>

#include "engine/play/world.h"

namespace p3d::play {

namespace {

constexpr int kButtonTime = 35;                // tics before a button pops back out
constexpr int kMaxAdjoiningSectors = 20;       // the size of Doom's list in P_FindNextHighestFloor
constexpr int kTeleportFreezeTics = 18;
constexpr bool kOnce = false, kAgain = true;  // a switch stays flipped, or is a button

// Doom's switch pairs in its order, which decides which of a side's textures flips
// when more than one are switches. `game`: 1 every game, 2 the registered episodes
// too, 3 only Doom II.
struct SwitchPair {
  const char* off;
  const char* on;
  int game;
};
constexpr SwitchPair kSwitchPairs[] = {
    {"SW1BRCOM", "SW2BRCOM", 1}, {"SW1BRN1", "SW2BRN1", 1},   {"SW1BRN2", "SW2BRN2", 1},   {"SW1BRNGN", "SW2BRNGN", 1},
    {"SW1BROWN", "SW2BROWN", 1}, {"SW1COMM", "SW2COMM", 1},   {"SW1COMP", "SW2COMP", 1},   {"SW1DIRT", "SW2DIRT", 1},
    {"SW1EXIT", "SW2EXIT", 1},   {"SW1GRAY", "SW2GRAY", 1},   {"SW1GRAY1", "SW2GRAY1", 1}, {"SW1METAL", "SW2METAL", 1},
    {"SW1PIPE", "SW2PIPE", 1},   {"SW1SLAD", "SW2SLAD", 1},   {"SW1STARG", "SW2STARG", 1}, {"SW1STON1", "SW2STON1", 1},
    {"SW1STON2", "SW2STON2", 1}, {"SW1STONE", "SW2STONE", 1}, {"SW1STRTN", "SW2STRTN", 1}, {"SW1BLUE", "SW2BLUE", 2},
    {"SW1CMT", "SW2CMT", 2},     {"SW1GARG", "SW2GARG", 2},   {"SW1GSTON", "SW2GSTON", 2}, {"SW1HOT", "SW2HOT", 2},
    {"SW1LION", "SW2LION", 2},   {"SW1SATYR", "SW2SATYR", 2}, {"SW1SKIN", "SW2SKIN", 2},   {"SW1VINE", "SW2VINE", 2},
    {"SW1WOOD", "SW2WOOD", 2},   {"SW1PANEL", "SW2PANEL", 3}, {"SW1ROCK", "SW2ROCK", 3},   {"SW1MET2", "SW2MET2", 3},
    {"SW1WDMET", "SW2WDMET", 3}, {"SW1BRIK", "SW2BRIK", 3},   {"SW1MOD1", "SW2MOD1", 3},   {"SW1ZIM", "SW2ZIM", 3},
    {"SW1STON6", "SW2STON6", 3}, {"SW1TEK", "SW2TEK", 3},     {"SW1MARB", "SW2MARB", 3},   {"SW1SKULL", "SW2SKULL", 3},
};

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A switch texture's place in Doom's list of switches (pairs in turn, the off texture
// first), or -1. Doom's list holds the registered game's pairs, and Doom II's too
// only in Doom II; the pairs left out all come last, so places keep their order.
int switch_place(std::string_view name, bool commercial) {
  const std::string n = upper(name);
  const int game = commercial ? 3 : 2;
  for (size_t k = 0; k < std::size(kSwitchPairs); ++k) {
    if (kSwitchPairs[k].game > game) continue;
    if (n == kSwitchPairs[k].off) return int(2 * k);
    if (n == kSwitchPairs[k].on) return int(2 * k + 1);
  }
  return -1;
}

const char* switch_pair_name(int place) {
  const SwitchPair& p = kSwitchPairs[size_t(place / 2)];
  return place % 2 ? p.off : p.on;
}

// Per level texture, the level texture it flips to, or kNone: not a switch, or its
// pair is not in the level (then it cannot flip).
std::vector<int> switch_partners(const level::Level& level, bool commercial) {
  std::unordered_map<std::string, int> by_name;
  for (size_t t = 0; t < level.textures.size(); ++t) by_name.emplace(upper(level.textures[t].name), int(t));
  std::vector<int> partner(level.textures.size(), level::kNone);
  for (size_t t = 0; t < level.textures.size(); ++t) {
    const int place = switch_place(level.textures[t].name, commercial);
    if (place < 0) continue;
    if (const auto it = by_name.find(switch_pair_name(place)); it != by_name.end()) partner[t] = it->second;
  }
  return partner;
}

int& side_part(Side& side, int where) { return where == 0 ? side.top : where == 1 ? side.middle : side.bottom; }

// P_StartButton: the switch flips back after `time` tics, unless already counting.
void start_button(World& w, Line* line, int where, int texture, int time) {
  for (const World::Button& b : w.buttons_)
    if (b.timer && b.line == line) return;
  const World::Button button{line, where, texture, time, line->front};
  for (World::Button& b : w.buttons_) {
    if (!b.timer) {
      b = button;  // the first free slot, as Doom's fixed list reuses them
      return;
    }
  }
  w.buttons_.push_back(button);
}

// Things other than the player may trigger lines walked over: not these missiles, and
// then only teleporters, door 4 and lifts 10 and 88 (other missiles, as the
// mancubus's, may well open a door).
bool may_cross_without_player(ThingType type, int special) {
  switch (type) {
    case ThingType::kRocket:
    case ThingType::kPlasma:
    case ThingType::kBfg:
    case ThingType::kTroopshot:
    case ThingType::kHeadshot:
    case ThingType::kBruisershot: return false;
    default: break;
  }
  switch (special) {
    case 39:
    case 97:
    case 125:
    case 126:
    case 4:
    case 10:
    case 88: return true;
    default: return false;
  }
}

// The first teleport destination in a sector tagged `tag`: sectors in order, then
// things in thinker order.
Mobj* find_teleport_destination(World& w, int tag) {
  for (const Sector& sector : w.map_.sectors) {
    if (sector.tag != tag) continue;
    for (const auto& t : w.thinkers_) {
      if (t->removed || t->kind != Thinker::Kind::kMobj) continue;
      auto* m = static_cast<Mobj*>(t.get());
      if (m->type == ThingType::kTeleportman && m->subsector->sector == &sector) return m;
    }
  }
  return nullptr;
}

}  // namespace

// ---- neighbours ---------------------------------------------------------------

Side* World::get_side(int sector, int line, int side) {
  return &map_.sides[size_t(map_.sectors[size_t(sector)].lines[size_t(line)]->side[size_t(side)])];
}

Sector* World::get_sector(int sector, int line, int side) { return get_side(sector, line, side)->sector; }

bool World::two_sided(int sector, int line) {
  return map_.sectors[size_t(sector)].lines[size_t(line)]->flags & kMlTwoSided;
}

Sector* World::get_next_sector(Line* line, Sector* sector) {
  if (!(line->flags & kMlTwoSided)) return nullptr;
  return line->front == sector ? line->back : line->front;
}

Fixed World::find_lowest_floor_surrounding(Sector* sec) {
  Fixed floor = sec->floor_height;
  for (Line* line : sec->lines) {
    const Sector* other = get_next_sector(line, sec);
    if (other && other->floor_height < floor) floor = other->floor_height;
  }
  return floor;
}

Fixed World::find_highest_floor_surrounding(Sector* sec) {
  Fixed floor = -500 * kFracUnit;
  for (Line* line : sec->lines) {
    const Sector* other = get_next_sector(line, sec);
    if (other && other->floor_height > floor) floor = other->floor_height;
  }
  return floor;
}

// The lowest neighbouring floor above `current`. Doom lists the candidates in an array
// of 20 on the stack: the 22nd overwrites `height`, so later candidates are compared
// with that floor instead (Doom crashes at the 23rd; here the list just grows).
Fixed World::find_next_highest_floor(Sector* sec, Fixed current) {
  Fixed height = current;
  std::vector<Fixed> heights;
  for (Line* line : sec->lines) {
    const Sector* other = get_next_sector(line, sec);
    if (!other || other->floor_height <= height) continue;
    if (heights.size() == kMaxAdjoiningSectors + 1) height = other->floor_height;
    heights.push_back(other->floor_height);
  }
  if (heights.empty()) return current;
  Fixed lowest = heights[0];
  for (Fixed h : heights)
    if (h < lowest) lowest = h;
  return lowest;
}

Fixed World::find_lowest_ceiling_surrounding(Sector* sec) {
  Fixed height = INT_MAX;
  for (Line* line : sec->lines) {
    const Sector* other = get_next_sector(line, sec);
    if (other && other->ceiling_height < height) height = other->ceiling_height;
  }
  return height;
}

Fixed World::find_highest_ceiling_surrounding(Sector* sec) {
  Fixed height = 0;
  for (Line* line : sec->lines) {
    const Sector* other = get_next_sector(line, sec);
    if (other && other->ceiling_height > height) height = other->ceiling_height;
  }
  return height;
}

int World::find_sector_from_line_tag(const Line* line, int start) {
  for (size_t i = size_t(start + 1); i < map_.sectors.size(); ++i)
    if (map_.sectors[i].tag == line->tag) return int(i);
  return -1;
}

int World::find_min_surrounding_light(Sector* sector, int max) {
  int min = max;
  for (Line* line : sector->lines) {
    const Sector* other = get_next_sector(line, sector);
    if (other && other->light < min) min = other->light;
  }
  return min;
}

// ---- lines walked over, shot and used ---------------------------------------

// Lines walked over once (W1) lose their special; the rest (WR) keep it.
void World::cross_special_line(int line_number, int side, Mobj* thing) {
  Line* line = &map_.lines[size_t(line_number)];
  if (!thing->player && !may_cross_without_player(thing->type, line->special)) return;
  mark_line(line);  // its special may be used up
  switch (line->special) {
    case 2: do_door(line, Door::Type::kOpen); break;
    case 3: do_door(line, Door::Type::kClose); break;
    case 4: do_door(line, Door::Type::kNormal); break;
    case 5: do_floor(line, Floor::Type::kRaise); break;
    case 6: do_ceiling(line, Ceiling::Type::kFastCrushAndRaise); break;
    case 8: build_stairs(line, false); break;
    case 10: do_plat(line, Plat::Type::kDownWaitUpStay, 0); break;
    case 12: light_turn_on(line, 0); break;
    case 13: light_turn_on(line, 255); break;
    case 16: do_door(line, Door::Type::kClose30ThenOpen); break;
    case 17: start_light_strobing(line); break;
    case 19: do_floor(line, Floor::Type::kLower); break;
    case 22: do_plat(line, Plat::Type::kRaiseToNearestAndChange, 0); break;
    case 25: do_ceiling(line, Ceiling::Type::kCrushAndRaise); break;
    case 30: do_floor(line, Floor::Type::kRaiseToTexture); break;
    case 35: light_turn_on(line, 35); break;
    case 36: do_floor(line, Floor::Type::kTurboLower); break;
    case 37: do_floor(line, Floor::Type::kLowerAndChange); break;
    case 38: do_floor(line, Floor::Type::kLowerToLowest); break;
    case 39: teleport(line, side, thing); break;
    case 40:
      do_ceiling(line, Ceiling::Type::kRaiseToHighest);
      do_floor(line, Floor::Type::kLowerToLowest);
      break;
    case 44: do_ceiling(line, Ceiling::Type::kLowerAndCrush); break;
    case 52: exit_level(false); return;  // keeps its special
    case 53: do_plat(line, Plat::Type::kPerpetualRaise, 0); break;
    case 54: stop_plat(line); break;
    case 56: do_floor(line, Floor::Type::kRaiseCrush); break;
    case 57: ceiling_crush_stop(line); break;
    case 58: do_floor(line, Floor::Type::kRaise24); break;
    case 59: do_floor(line, Floor::Type::kRaise24AndChange); break;
    case 100: build_stairs(line, true); break;
    case 104: turn_tag_lights_off(line); break;
    case 108: do_door(line, Door::Type::kBlazeRaise); break;
    case 109: do_door(line, Door::Type::kBlazeOpen); break;
    case 110: do_door(line, Door::Type::kBlazeClose); break;
    case 119: do_floor(line, Floor::Type::kRaiseToNearest); break;
    case 121: do_plat(line, Plat::Type::kBlazeDwus, 0); break;
    case 124: exit_level(true); return;  // keeps its special
    case 125:
      if (thing->player) return;  // monsters only: left for them
      teleport(line, side, thing);
      break;
    case 130: do_floor(line, Floor::Type::kRaiseTurbo); break;
    case 141: do_ceiling(line, Ceiling::Type::kSilentCrushAndRaise); break;

    // Repeatable
    case 72: do_ceiling(line, Ceiling::Type::kLowerAndCrush); return;
    case 73: do_ceiling(line, Ceiling::Type::kCrushAndRaise); return;
    case 74: ceiling_crush_stop(line); return;
    case 75: do_door(line, Door::Type::kClose); return;
    case 76: do_door(line, Door::Type::kClose30ThenOpen); return;
    case 77: do_ceiling(line, Ceiling::Type::kFastCrushAndRaise); return;
    case 79: light_turn_on(line, 35); return;
    case 80: light_turn_on(line, 0); return;
    case 81: light_turn_on(line, 255); return;
    case 82: do_floor(line, Floor::Type::kLowerToLowest); return;
    case 83: do_floor(line, Floor::Type::kLower); return;
    case 84: do_floor(line, Floor::Type::kLowerAndChange); return;
    case 86: do_door(line, Door::Type::kOpen); return;
    case 87: do_plat(line, Plat::Type::kPerpetualRaise, 0); return;
    case 88: do_plat(line, Plat::Type::kDownWaitUpStay, 0); return;
    case 89: stop_plat(line); return;
    case 90: do_door(line, Door::Type::kNormal); return;
    case 91: do_floor(line, Floor::Type::kRaise); return;
    case 92: do_floor(line, Floor::Type::kRaise24); return;
    case 93: do_floor(line, Floor::Type::kRaise24AndChange); return;
    case 94: do_floor(line, Floor::Type::kRaiseCrush); return;
    case 95: do_plat(line, Plat::Type::kRaiseToNearestAndChange, 0); return;
    case 96: do_floor(line, Floor::Type::kRaiseToTexture); return;
    case 97: teleport(line, side, thing); return;
    case 98: do_floor(line, Floor::Type::kTurboLower); return;
    case 105: do_door(line, Door::Type::kBlazeRaise); return;
    case 106: do_door(line, Door::Type::kBlazeOpen); return;
    case 107: do_door(line, Door::Type::kBlazeClose); return;
    case 120: do_plat(line, Plat::Type::kBlazeDwus, 0); return;
    case 126:
      if (!thing->player) teleport(line, side, thing);
      return;
    case 128: do_floor(line, Floor::Type::kRaiseToNearest); return;
    case 129: do_floor(line, Floor::Type::kRaiseTurbo); return;
    default: return;
  }
  line->special = 0;
}

// Things other than the player open only door 46 by shooting.
void World::shoot_special_line(Mobj* thing, Line* line) {
  if (!thing->player && line->special != 46) return;
  mark_line(line);
  switch (line->special) {
    case 24:
      do_floor(line, Floor::Type::kRaise);
      change_switch_texture(line, kOnce);
      break;
    case 46:
      do_door(line, Door::Type::kOpen);
      change_switch_texture(line, kAgain);
      break;
    case 47:
      do_plat(line, Plat::Type::kRaiseToNearestAndChange, 0);
      change_switch_texture(line, kOnce);
      break;
    default: break;
  }
}

// Lines are used from the front (Doom lets 124 through from the back, to do nothing).
// Monsters open plain doors (1, 32, 33, 34) that are not secret. A switch flips when
// what it starts did start (exits and lights always).
bool World::use_special_line(Mobj* thing, Line* line, int side) {
  if (side && line->special != 124) return false;
  mark_line(line);
  if (!thing->player) {
    if (line->flags & kMlSecret) return false;
    const int s = line->special;
    if (s != 1 && s != 32 && s != 33 && s != 34) return false;
  }
  auto flip_if = [&](bool started, bool use_again) {
    if (started) change_switch_texture(line, use_again);
  };
  switch (line->special) {
    // Doors opened by hand
    case 1:
    case 26:
    case 27:
    case 28:
    case 31:
    case 32:
    case 33:
    case 34:
    case 117:
    case 118: vertical_door(line, thing); break;

    // Switches
    case 7: flip_if(build_stairs(line, false), kOnce); break;
    case 9: flip_if(do_donut(line), kOnce); break;
    case 11:
      change_switch_texture(line, kOnce);
      exit_level(false);
      break;
    case 14: flip_if(do_plat(line, Plat::Type::kRaiseAndChange, 32), kOnce); break;
    case 15: flip_if(do_plat(line, Plat::Type::kRaiseAndChange, 24), kOnce); break;
    case 18: flip_if(do_floor(line, Floor::Type::kRaiseToNearest), kOnce); break;
    case 20: flip_if(do_plat(line, Plat::Type::kRaiseToNearestAndChange, 0), kOnce); break;
    case 21: flip_if(do_plat(line, Plat::Type::kDownWaitUpStay, 0), kOnce); break;
    case 23: flip_if(do_floor(line, Floor::Type::kLowerToLowest), kOnce); break;
    case 29: flip_if(do_door(line, Door::Type::kNormal), kOnce); break;
    case 41: flip_if(do_ceiling(line, Ceiling::Type::kLowerToFloor), kOnce); break;
    case 49: flip_if(do_ceiling(line, Ceiling::Type::kCrushAndRaise), kOnce); break;
    case 50: flip_if(do_door(line, Door::Type::kClose), kOnce); break;
    case 51:
      change_switch_texture(line, kOnce);
      exit_level(true);
      break;
    case 55: flip_if(do_floor(line, Floor::Type::kRaiseCrush), kOnce); break;
    case 71: flip_if(do_floor(line, Floor::Type::kTurboLower), kOnce); break;
    case 101: flip_if(do_floor(line, Floor::Type::kRaise), kOnce); break;
    case 102: flip_if(do_floor(line, Floor::Type::kLower), kOnce); break;
    case 103: flip_if(do_door(line, Door::Type::kOpen), kOnce); break;
    case 111: flip_if(do_door(line, Door::Type::kBlazeRaise), kOnce); break;
    case 112: flip_if(do_door(line, Door::Type::kBlazeOpen), kOnce); break;
    case 113: flip_if(do_door(line, Door::Type::kBlazeClose), kOnce); break;
    case 122: flip_if(do_plat(line, Plat::Type::kBlazeDwus, 0), kOnce); break;
    case 127: flip_if(build_stairs(line, true), kOnce); break;
    case 131: flip_if(do_floor(line, Floor::Type::kRaiseTurbo), kOnce); break;
    case 133:
    case 135:
    case 137: flip_if(do_locked_door(line, Door::Type::kBlazeOpen, thing), kOnce); break;
    case 140: flip_if(do_floor(line, Floor::Type::kRaise512), kOnce); break;

    // Buttons
    case 42: flip_if(do_door(line, Door::Type::kClose), kAgain); break;
    case 43: flip_if(do_ceiling(line, Ceiling::Type::kLowerToFloor), kAgain); break;
    case 45: flip_if(do_floor(line, Floor::Type::kLower), kAgain); break;
    case 60: flip_if(do_floor(line, Floor::Type::kLowerToLowest), kAgain); break;
    case 61: flip_if(do_door(line, Door::Type::kOpen), kAgain); break;
    case 62: flip_if(do_plat(line, Plat::Type::kDownWaitUpStay, 1), kAgain); break;
    case 63: flip_if(do_door(line, Door::Type::kNormal), kAgain); break;
    case 64: flip_if(do_floor(line, Floor::Type::kRaise), kAgain); break;
    case 65: flip_if(do_floor(line, Floor::Type::kRaiseCrush), kAgain); break;
    case 66: flip_if(do_plat(line, Plat::Type::kRaiseAndChange, 24), kAgain); break;
    case 67: flip_if(do_plat(line, Plat::Type::kRaiseAndChange, 32), kAgain); break;
    case 68: flip_if(do_plat(line, Plat::Type::kRaiseToNearestAndChange, 0), kAgain); break;
    case 69: flip_if(do_floor(line, Floor::Type::kRaiseToNearest), kAgain); break;
    case 70: flip_if(do_floor(line, Floor::Type::kTurboLower), kAgain); break;
    case 99:
    case 134:
    case 136: flip_if(do_locked_door(line, Door::Type::kBlazeOpen, thing), kAgain); break;
    case 114: flip_if(do_door(line, Door::Type::kBlazeRaise), kAgain); break;
    case 115: flip_if(do_door(line, Door::Type::kBlazeOpen), kAgain); break;
    case 116: flip_if(do_door(line, Door::Type::kBlazeClose), kAgain); break;
    case 123: flip_if(do_plat(line, Plat::Type::kBlazeDwus, 0), kAgain); break;
    case 132: flip_if(do_floor(line, Floor::Type::kRaiseTurbo), kAgain); break;
    case 138:
      light_turn_on(line, 255);
      change_switch_texture(line, kAgain);
      break;
    case 139:
      light_turn_on(line, 35);
      change_switch_texture(line, kAgain);
      break;
    default: break;
  }
  return true;
}

// ---- sectors ----------------------------------------------------------------

// Standing on the floor of a special sector (Doom's caller checks it has a special):
// hurt every 32 tics unless in the suit (which the worst floors get through now and
// then), a secret found, or E1M8's end.
void World::player_in_special_sector(Player& player) {
  Sector* sector = player.mo->subsector->sector;
  if (player.mo->z != sector->floor_height) return;  // not down yet
  const bool suit = player.inv.powers[size_t(Power::kIronFeet)] != 0;
  const bool hurts_now = !(level_time_ & 0x1f);
  switch (sector->special) {
    case 5:
      if (!suit && hurts_now) damage_mobj(player.mo, nullptr, nullptr, 10);
      break;
    case 7:
      if (!suit && hurts_now) damage_mobj(player.mo, nullptr, nullptr, 5);
      break;
    case 16:
    case 4:
      if ((!suit || random_.play() < 5) && hurts_now) damage_mobj(player.mo, nullptr, nullptr, 20);
      break;
    case 9:  // Doom says nothing when a secret is found
      ++player.secret_count;
      sector->special = 0;
      break;
    case 11:
      player.cheats &= ~kCheatGodMode;
      if (hurts_now) damage_mobj(player.mo, nullptr, nullptr, 20);
      if (player.inv.health <= 10) exit_level(false);
      break;
    default: break;  // Doom stops with an error
  }
}

// After the thinkers, each tic: walls scroll, buttons pop back out.
void World::update_specials() {
  for (Line* line : scrolling_lines_) {
    if (line->special == 48 && line->side[0] >= 0) {
      Side& side = map_.sides[size_t(line->side[0])];
      side.texture_offset = wrap_add(side.texture_offset, kFracUnit);
    }
  }
  for (Button& b : buttons_) {
    if (!b.timer || --b.timer) continue;
    side_part(map_.sides[size_t(b.line->side[0])], b.where) = b.texture;
    mark_line(b.line);
    // Doom's origin is the button record itself, a place that is nowhere in particular
    start_sector_sound(b.sound_sector, Sound::kSwtchn);
    b = Button{};
  }
}

// The movers and lights the sectors' specials start with, in sector order (some draw
// random numbers), then the scrolling walls.
void World::spawn_specials() {
  for (Sector& sector : map_.sectors) {
    switch (sector.special) {
      case 1: spawn_light_flash(&sector); break;
      case 2: spawn_strobe_flash(&sector, kFastDark, false); break;
      case 3: spawn_strobe_flash(&sector, kSlowDark, false); break;
      case 4:
        spawn_strobe_flash(&sector, kFastDark, false);
        sector.special = 4;  // it still hurts
        break;
      case 8: spawn_glowing_light(&sector); break;
      case 9: ++total_secrets_; break;
      case 10: spawn_door_close_in_30(&sector); break;
      case 12: spawn_strobe_flash(&sector, kSlowDark, true); break;
      case 13: spawn_strobe_flash(&sector, kFastDark, true); break;
      case 14: spawn_door_raise_in_5_mins(&sector); break;
      case 17: spawn_fire_flicker(&sector); break;
      default: break;
    }
  }
  scrolling_lines_.clear();
  for (Line& line : map_.lines)
    if (line.special == 48) scrolling_lines_.push_back(&line);
  active_plats_.clear();
  active_ceilings_.clear();
  buttons_.clear();
  switch_partner_ = switch_partners(level_, options_.commercial);
}

// Switch 9: each tagged sector (the hole) lowers to the floor beyond its ring (the
// sector across its first line), which rises to it and takes its flat.
bool World::do_donut(Line* line) {
  bool started = false;
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* hole = &map_.sectors[size_t(secnum)];
    if (hole->special_data) continue;
    started = true;
    Sector* ring = get_next_sector(hole->lines[0], hole);
    if (!ring) break;  // Doom reads whatever memory; Chocolate Doom stops here too
    for (Line* ring_line : ring->lines) {
      const Sector* outside = ring_line->back;
      if (outside == hole) continue;
      // A one-sided line: Doom reads its floor from address 0 (height 0 under Windows
      // 98, as Chocolate Doom assumes); the flat read there is not one we know, so the
      // ring keeps its own.
      const Fixed height = outside ? outside->floor_height : 0;
      const int flat = outside ? outside->floor_pic : ring->floor_pic;

      Floor* rise = make_thinker<Floor>();
      ring->special_data = rise;
      rise->type = Floor::Type::kDonutRaise;
      rise->crush = false;
      rise->direction = 1;
      rise->sector = ring;
      rise->speed = kFloorSpeed / 2;
      rise->texture = flat;
      rise->new_special = 0;
      rise->destination = height;

      Floor* lower = make_thinker<Floor>();
      hole->special_data = lower;
      lower->type = Floor::Type::kLower;
      lower->crush = false;
      lower->direction = -1;
      lower->sector = hole;
      lower->speed = kFloorSpeed / 2;
      lower->destination = height;
      break;
    }
  }
  return started;
}

// ---- switches ---------------------------------------------------------------

// The first of the front side's textures in Doom's list of switches flips to its pair
// (top before middle before bottom for the same place); a button flips back later.
void World::change_switch_texture(Line* line, bool use_again) {
  mark_line(line);
  if (!use_again) line->special = 0;
  // Doom asks for the exit switch's sound only now, when a once-only exit switch has
  // lost its special: the exit sounds as any switch does.
  const Sound sound = line->special == 11 ? Sound::kSwtchx : Sound::kSwtchn;
  if (line->side[0] < 0) return;
  if (switch_partner_.size() != level_.textures.size()) switch_partner_ = switch_partners(level_, options_.commercial);
  Side& side = map_.sides[size_t(line->side[0])];
  int where = -1, best_place = INT_MAX;
  for (int part = 0; part < 3; ++part) {
    const int texture = side_part(side, part);
    if (texture < 0 || size_t(texture) >= switch_partner_.size() || switch_partner_[size_t(texture)] == level::kNone)
      continue;
    const int place = switch_place(level_.textures[size_t(texture)].name, options_.commercial);
    if (place < best_place) {
      best_place = place;
      where = part;
    }
  }
  if (where < 0) return;
  int& texture = side_part(side, where);
  const int was = texture;
  // Doom plays it from the first button's origin (nowhere while no button counts);
  // the switch's sector is where it is heard here.
  start_sector_sound(line->front, sound);
  texture = switch_partner_[size_t(was)];
  if (use_again) start_button(*this, line, where, was, kButtonTime);
}

// ---- teleporters ------------------------------------------------------------

// Things (not missiles) crossing a teleporter from its front go to the first
// destination in its tagged sectors, if they fit there, with a flash at both ends.
bool World::teleport(Line* line, int side, Mobj* thing) {
  if (thing->flags & kMissile) return false;
  if (side == 1) return false;  // so that one can step off a teleporter
  Mobj* dest = find_teleport_destination(*this, line->tag);
  if (!dest) return false;
  const Fixed old_x = thing->x, old_y = thing->y, old_z = thing->z;
  if (!teleport_move(thing, dest->x, dest->y)) return false;
  thing->z = thing->floor_z;  // (Final Doom's first executable did not)
  if (thing->player) thing->player->view_z = wrap_add(thing->z, thing->player->view_height);
  Mobj* fog = spawn_mobj(old_x, old_y, old_z, ThingType::kTfog);
  start_sound(fog, Sound::kTelept);
  const int an = fine(dest->angle);
  fog = spawn_mobj(wrap_add(dest->x, 20 * fine_cosine(an)), wrap_add(dest->y, 20 * fine_sine(an)), thing->z,
                   ThingType::kTfog);
  start_sound(fog, Sound::kTelept);
  if (thing->player) thing->reaction_time = kTeleportFreezeTics;
  thing->angle = dest->angle;
  thing->mom_x = thing->mom_y = thing->mom_z = 0;
  return true;
}

}  // namespace p3d::play
