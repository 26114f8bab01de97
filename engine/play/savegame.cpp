// Savegames (savegame.h), Doom's part: Doom's records written from a World and read
// back into one, as Chocolate Doom's p_saveg.c; our extension is savegame_extension.cpp.
//
// Index:
//   [numbers]    DoomNumbers: Doom's texture and flat numbers, both ways
//   [bytes]      the writer, with Doom's padding (the reader is savegame_local.h's)
//   [shared]     thinker lists and conversions the extension uses too
//   [write]      the World as Doom's records (P_Archive*), and their bytes
//   [read]       Doom's records from bytes, checked (P_UnArchive*'s reads)
//   [load]       Doom's records into a freshly set-up World (P_UnArchive*'s effects), then ours
#include "engine/play/savegame.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <unordered_map>

#include "engine/play/savegame_local.h"
#include "engine/util/bytes.h"
#include "engine/util/doom.h"
#include "engine/util/error.h"
#include "engine/wad/art.h"

namespace p3d::play {

using namespace savegame_local;

namespace {

constexpr char kVersionString[] = "version 109";  // Chocolate Doom's G_VanillaVersionCode() for v1.9 and later
constexpr int kNoWeaponChange = 10;  // Doom's wp_nochange
constexpr int32_t kStairsCrush = 10;  // Chocolate Doom's STAIRS_UNINITIALIZED_CRUSH_FIELD_VALUE

// Doom's thinker classes in the thinkers and specials sections.
enum : uint8_t { kTcEnd = 0, kTcMobj = 1 };
enum : uint8_t { kTcCeiling, kTcDoor, kTcFloor, kTcPlat, kTcFlash, kTcStrobe, kTcGlow, kTcEndSpecials };


}  // namespace

std::string SaveHeader::map_name(bool commercial) const { return doom::map_name(commercial, episode, map); }

// ---- [numbers] ----------------------------------------------------------------

DoomNumbers::DoomNumbers(const wad::Stack& wads, const level::Level& level) {
  const wad::Art art(wads);
  texture_names_ = art.texture_numbers();
  // Doom's lump numbers run through the WADs in order; F_START is the last one of the name.
  std::vector<const wad::Lump*> lumps;
  for (const wad::Wad& w : wads.wads())
    for (const wad::Lump& l : w.lumps()) lumps.push_back(&l);
  size_t first_flat = lumps.size() + 1;
  for (size_t i = 0; i < lumps.size(); ++i)
    if (lumps[i]->name == "F_START") first_flat = i + 1;
  if (first_flat > lumps.size()) throw Error("the WADs have no F_START: no Doom flats to number");
  for (size_t i = first_flat; i < lumps.size(); ++i) flat_lumps_.push_back(lumps[i]->name);

  std::unordered_map<std::string, int> texture_number, flat_number;
  for (size_t n = 0; n < texture_names_.size(); ++n) texture_number.emplace(texture_names_[n], int(n));  // the first wins
  for (size_t i = 0; i < lumps.size(); ++i) flat_number[lumps[i]->name] = int(i) - int(first_flat);  // the last wins
  if (const auto it = flat_number.find(std::string(wad::kSkyFlat)); it != flat_number.end()) sky_flat_ = it->second;

  // The level's flats: its sectors' floors and ceilings, and the animations they are in.
  std::vector<bool> is_flat(level.textures.size(), false);
  auto mark = [&](int t) {
    if (t >= 0 && size_t(t) < is_flat.size()) is_flat[size_t(t)] = true;
  };
  for (const level::Sector& s : level.sectors) mark(s.floor_texture), mark(s.ceiling_texture);
  for (const doom::TextureAnimation& a : level.animations)
    if (std::any_of(a.frames.begin(), a.frames.end(), [&](int32_t f) { return f >= 0 && size_t(f) < is_flat.size() && is_flat[size_t(f)]; }))
      for (int32_t f : a.frames) mark(f);

  texture_of_level_.assign(level.textures.size(), -1);
  flat_of_level_.assign(level.textures.size(), -1);
  level_of_texture_.assign(texture_names_.size(), level::kNone);
  level_of_flat_.assign(flat_lumps_.size(), level::kNone);
  for (size_t i = 0; i < level.textures.size(); ++i) {
    const std::string name = wad::normalize_name(level.textures[i].name);
    if (const auto it = texture_number.find(name); it != texture_number.end()) texture_of_level_[i] = it->second;
    if (const auto it = flat_number.find(name); it != flat_number.end() && it->second >= 0) flat_of_level_[i] = it->second;
  }
  // Back from Doom's numbers: a flat prefers the level's flats, a texture its walls'.
  for (int pass = 0; pass < 2; ++pass)
    for (size_t i = 0; i < level.textures.size(); ++i) {
      if (is_flat[i] == (pass == 0) && flat_of_level_[i] >= 0 && size_t(flat_of_level_[i]) < level_of_flat_.size() &&
          level_of_flat_[size_t(flat_of_level_[i])] == level::kNone)
        level_of_flat_[size_t(flat_of_level_[i])] = int(i);
      if (is_flat[i] == (pass == 1) && texture_of_level_[i] > 0 && level_of_texture_[size_t(texture_of_level_[i])] == level::kNone)
        level_of_texture_[size_t(texture_of_level_[i])] = int(i);
    }
}

std::optional<int> DoomNumbers::texture_number(int level_texture) const {
  if (level_texture == level::kNone) return 0;
  if (level_texture < 0 || size_t(level_texture) >= texture_of_level_.size() || texture_of_level_[size_t(level_texture)] < 0)
    return std::nullopt;
  return texture_of_level_[size_t(level_texture)];
}

std::optional<int> DoomNumbers::flat_number(int level_texture) const {
  if (level_texture == level::kSky) return sky_flat_ >= 0 ? std::optional<int>(sky_flat_) : std::nullopt;
  if (level_texture < 0 || size_t(level_texture) >= flat_of_level_.size() || flat_of_level_[size_t(level_texture)] < 0)
    return std::nullopt;
  return flat_of_level_[size_t(level_texture)];
}

std::optional<int> DoomNumbers::level_texture(int number) const {
  if (number == 0) return level::kNone;
  if (number < 0 || size_t(number) >= level_of_texture_.size() || level_of_texture_[size_t(number)] == level::kNone)
    return std::nullopt;
  return level_of_texture_[size_t(number)];
}

std::optional<int> DoomNumbers::level_flat(int number) const {
  if (number == sky_flat_ && number >= 0) return level::kSky;
  if (number < 0 || size_t(number) >= level_of_flat_.size() || level_of_flat_[size_t(number)] == level::kNone)
    return std::nullopt;
  return level_of_flat_[size_t(number)];
}

std::string DoomNumbers::texture_name(int number) const {
  return number >= 0 && size_t(number) < texture_names_.size() ? texture_names_[size_t(number)] : "(none)";
}

std::string DoomNumbers::flat_name(int number) const {
  return number >= 0 && size_t(number) < flat_lumps_.size() ? flat_lumps_[size_t(number)] : "(none)";
}

// ---- [bytes] ------------------------------------------------------------------

namespace {

// Doom's writes: little-endian, padding counted from the file's first byte.
class SaveWriter {
 public:
  void u8(uint8_t v) { out_.u8(v); }
  void i16(int32_t v) { out_.u16(uint16_t(v)); }  // Doom's shorts keep the low 16 bits
  void i32(int32_t v) { out_.i32(v); }
  void u32(uint32_t v) { out_.u32(v); }
  void pointer() { out_.u32(0); }  // what Doom writes raw and resets on loading
  void pad() {
    while (out_.size() & 3) out_.u8(0);
  }
  void raw(std::span<const uint8_t> b) { out_.raw(b); }
  size_t size() const { return out_.size(); }
  std::vector<uint8_t> release() { return out_.release(); }

 private:
  ByteWriter out_;
};

// A save of another map of the same name (another game's) runs out of bytes or meets
// bytes that are no record where this map's records should be.
constexpr char kAnotherMap[] = " (a save of another game's map of this name, or cut short)";

}  // namespace

// ---- [shared] what savegame_extension.cpp uses too (savegame_local.h) ------------

namespace savegame_local {

namespace {

bool in_list(const std::vector<Ceiling*>& list, const Thinker* t) {
  return std::find(list.begin(), list.end(), t) != list.end();
}

}  // namespace

ThinkerLists thinker_lists(const World& w) {
  ThinkerLists out;
  for (const auto& owned : w.thinkers_) {
    const Thinker* t = owned.get();
    if (t->removed) continue;
    bool doom = true;
    switch (t->kind) {
      case Thinker::Kind::kMobj:
        out.order.push_back({0, uint32_t(out.mobjs.size())});
        out.mobjs.push_back(static_cast<const Mobj*>(t));
        continue;
      // Doom saves a thinker without a function (stopped in stasis) only if it is an
      // active ceiling: its lifts stopped so are lost.
      case Thinker::Kind::kCeiling: doom = t->active || in_list(w.active_ceilings_, t); break;
      case Thinker::Kind::kPlat: doom = t->active; break;
      case Thinker::Kind::kFireFlicker: doom = false; break;
      default: break;
    }
    if (doom) {
      out.order.push_back({1, uint32_t(out.specials.size())});
      out.specials.push_back(t);
    } else {
      out.order.push_back({2, uint32_t(out.own.size())});
      out.own.push_back(t);
    }
  }
  return out;
}

DoomMobj doom_mobj_of(const World& w, const Mobj& m) {
  DoomMobj d;
  d.x = m.x, d.y = m.y, d.z = m.z;
  d.angle = int32_t(m.angle);
  d.sprite = int32_t(m.sprite);
  d.frame = m.frame;
  d.floor_z = m.floor_z, d.ceiling_z = m.ceiling_z;
  d.radius = m.radius, d.height = m.height;
  d.mom_x = m.mom_x, d.mom_y = m.mom_y, d.mom_z = m.mom_z;
  d.valid_count = m.valid_count;
  d.type = int32_t(m.type);
  d.tics = m.tics;
  d.state = int32_t(m.state);
  d.flags = int32_t(m.flags);
  d.health = m.health;
  d.move_dir = m.move_dir, d.move_count = m.move_count;
  d.reaction_time = m.reaction_time, d.threshold = m.threshold;
  d.player = m.player ? int32_t(m.player - &w.player(0)) + 1 : 0;
  d.last_look = m.last_look;
  d.spawn_x = m.spawn_point.x, d.spawn_y = m.spawn_point.y, d.spawn_angle = m.spawn_point.angle;
  d.spawn_type = m.spawn_point.type, d.spawn_options = m.spawn_point.options;
  return d;
}

DoomPlat doom_plat_of(const Plat& p) {
  return {p.active,        p.sector->index, p.speed, p.low, p.high, p.wait, p.count, int32_t(p.status), int32_t(p.old_status),
          int32_t(p.crush), p.tag,         int32_t(p.type)};
}

void check_range(SaveReader& in, size_t at, int64_t value, int64_t low, int64_t high, const std::string& what) {
  if (value < low || value > high)
    in.fail_at(at, what + " " + std::to_string(value) + " is out of range (" + std::to_string(low) + ".." + std::to_string(high) + ")");
}


void check_counter(SaveReader& in, size_t at, int64_t value, const std::string& what) {
  check_range(in, at, value, -kMostCount, kMostCount, what);
}

void check_height(SaveReader& in, size_t at, int64_t value, const std::string& what) {
  check_range(in, at, value, -kMostHeight, kMostHeight, what);
}

void check_mobj_counters(SaveReader& in, const DoomMobj& d, const std::array<size_t, 13>& at) {
  const int32_t values[] = {d.radius, d.height, d.mom_x, d.mom_y, d.mom_z, d.tics, d.health, d.move_count, d.reaction_time, d.threshold};
  const char* names[] = {"radius", "height", "momentum", "momentum", "momentum", "tics", "health", "move count", "reaction time", "threshold"};
  for (size_t i = 0; i < 2; ++i) check_range(in, at[i], values[i], 0, kMostHeight / 8, std::string("a thing's ") + names[i]);
  for (size_t i = 2; i < 10; ++i) check_counter(in, at[i], values[i], std::string("a thing's ") + names[i]);
  const int32_t heights[] = {d.z, d.floor_z, d.ceiling_z};
  for (size_t i = 0; i < 3; ++i) check_height(in, at[10 + i], heights[i], "a thing's z, floor or ceiling");
}

void check_special_counters(SaveReader& in, const DoomSpecial& s, size_t at) {
  // (field, its place after the thinker) for every counted field of the record
  std::vector<std::pair<int32_t, size_t>> counted, heights;
  std::visit(
      [&](const auto& r) {
        using T = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<T, DoomCeiling>) {
          counted = {{r.direction, 24}, {r.old_direction, 32}};
          heights = {{r.bottom_height, 8}, {r.top_height, 12}};
        } else if constexpr (std::is_same_v<T, DoomDoor>) {
          counted = {{r.direction, 16}, {r.top_wait, 20}, {r.top_countdown, 24}};
          heights = {{r.top_height, 8}};
        } else if constexpr (std::is_same_v<T, DoomFloor>) {
          counted = {{r.direction, 12}, {r.new_special, 16}};
          heights = {{r.destination, 22}};
        } else if constexpr (std::is_same_v<T, DoomPlat>) {
          counted = {{r.wait, 16}, {r.count, 20}};
          heights = {{r.low, 8}, {r.high, 12}};
        }
        else if constexpr (std::is_same_v<T, DoomFlash>)
          counted = {{r.count, 4}, {r.max_light, 8}, {r.min_light, 12}, {r.max_time, 16}, {r.min_time, 20}};
        else if constexpr (std::is_same_v<T, DoomStrobe>)
          counted = {{r.count, 4}, {r.min_light, 8}, {r.max_light, 12}, {r.dark_time, 16}, {r.bright_time, 20}};
        else counted = {{r.min_light, 4}, {r.max_light, 8}, {r.direction, 12}};
      },
      s);
  for (const auto& [value, offset] : counted) check_counter(in, at + offset, value, "a mover's or light's count");
  for (const auto& [value, offset] : heights) check_height(in, at + offset, value, "a mover's height");
}

namespace {

MapThing spawn_point_of(const World& w, const DoomMobj& d) {
  MapThing mt{d.spawn_x, d.spawn_y, d.spawn_angle, d.spawn_type, d.spawn_options, -1};
  for (const MapThing& placed : w.map_.things)
    if (placed.x == mt.x && placed.y == mt.y && placed.angle == mt.angle && placed.type == mt.type && placed.options == mt.options) {
      mt.placed = placed.placed;
      break;
    }
  return mt;
}

}  // namespace

void fill_mobj(World& w, Mobj& m, const DoomMobj& d) {
  m.x = d.x, m.y = d.y, m.z = d.z;
  m.angle = Angle(uint32_t(d.angle));
  m.sprite = Sprite(d.sprite);
  m.frame = d.frame;
  m.floor_z = d.floor_z, m.ceiling_z = d.ceiling_z;
  m.radius = d.radius, m.height = d.height;
  m.mom_x = d.mom_x, m.mom_y = d.mom_y, m.mom_z = d.mom_z;
  m.valid_count = d.valid_count;
  m.type = ThingType(d.type);
  m.info = &w.thing_info_[size_t(d.type)];
  m.tics = d.tics;
  m.state = StateId(d.state);
  m.flags = uint32_t(d.flags);
  m.health = d.health;
  m.move_dir = d.move_dir, m.move_count = d.move_count;
  m.target = m.tracer = nullptr;
  m.reaction_time = d.reaction_time, m.threshold = d.threshold;
  m.player = d.player ? &w.players_[size_t(d.player - 1)] : nullptr;
  m.last_look = d.last_look;
  m.spawn_point = spawn_point_of(w, d);
}

}  // namespace savegame_local

namespace {

// ---- [write] ------------------------------------------------------------------

int16_t whole_units(Fixed f) { return int16_t(f >> kFracBits); }

struct Numbering {
  const DoomNumbers& numbers;
  std::vector<std::string>* warnings;
  std::set<std::pair<bool, int>> warned;
  int16_t flat(int level_texture, const level::Level& level) {
    if (const auto n = numbers.flat_number(level_texture)) return int16_t(*n);
    warn(true, level_texture, level);
    return 0;
  }
  int16_t texture(int level_texture, const level::Level& level) {
    if (const auto n = numbers.texture_number(level_texture)) return int16_t(*n);
    warn(false, level_texture, level);
    return 0;
  }
  void warn(bool flat, int t, const level::Level& level) {
    if (!warnings || !warned.insert({flat, t}).second) return;
    const std::string name = t >= 0 && size_t(t) < level.textures.size() ? level.textures[size_t(t)].name : std::to_string(t);
    warnings->push_back(std::string(flat ? "flat " : "texture ") + name + " has no Doom number: written as 0");
  }
};

DoomPlayer doom_player_of(const Player& p) {
  DoomPlayer d;
  d.state = int32_t(p.state);
  d.forward = p.cmd.forward;
  d.side = p.cmd.side;
  d.turn = p.cmd.turn;
  d.buttons = p.cmd.buttons;
  d.view_z = p.view_z;
  d.view_height = p.view_height;
  d.delta_view_height = p.delta_view_height;
  d.bob = p.bob;
  const Inventory& inv = p.inv;
  d.health = inv.health;
  d.armor_points = inv.armor;
  d.armor_type = inv.armor_type;
  for (size_t i = 0; i < d.powers.size(); ++i) d.powers[i] = inv.powers[i];
  for (size_t i = 0; i < d.cards.size(); ++i) d.cards[i] = (p.cards >> i) & 1;
  d.backpack = inv.backpack;
  d.ready_weapon = int32_t(inv.ready);
  d.pending_weapon = inv.pending == Weapon::kCount ? kNoWeaponChange : int32_t(inv.pending);
  for (size_t i = 0; i < d.weapon_owned.size(); ++i) d.weapon_owned[i] = inv.weapons[i];
  for (size_t i = 0; i < 4; ++i) d.ammo[i] = inv.ammo[i], d.max_ammo[i] = inv.max_ammo[i];
  d.attack_down = p.attack_down;
  d.use_down = p.use_down;
  d.cheats = p.cheats;
  d.refire = p.refire;
  d.kill_count = p.kill_count;
  d.item_count = inv.items;
  d.secret_count = p.secret_count;
  d.damage_count = inv.damage_count;
  d.bonus_count = inv.bonus_count;
  d.extra_light = p.extra_light;
  d.fixed_colormap = p.fixed_colormap;
  for (size_t i = 0; i < 2; ++i)
    d.psprites[i] = {int32_t(p.psprites[i].state), p.psprites[i].tics, p.psprites[i].sx, p.psprites[i].sy};
  d.did_secret = p.did_secret;
  for (size_t i = 0; i < d.frags.size(); ++i) d.frags[i] = p.frags[i];
  return d;
}

// Doom builds stairs as lowerFloor movers going up (movers.cpp's is_stair_step).
bool stair_step(const Floor& f) { return f.type == Floor::Type::kLower && f.direction == 1; }

DoomSpecial doom_special_of(const Thinker* t, Numbering& numbering, const level::Level& level) {
  switch (t->kind) {
    case Thinker::Kind::kCeiling: {
      const Ceiling& c = *static_cast<const Ceiling*>(t);
      return DoomCeiling{c.active,        int32_t(c.type), c.sector->index, c.bottom_height, c.top_height, c.speed,
                         int32_t(c.crush), c.direction,    c.tag,           c.old_direction};
    }
    case Thinker::Kind::kDoor: {
      const Door& d = *static_cast<const Door*>(t);
      return DoomDoor{int32_t(d.type), d.sector->index, d.top_height, d.speed, d.direction, d.top_wait, d.top_countdown};
    }
    case Thinker::Kind::kFloor: {
      const Floor& f = *static_cast<const Floor*>(t);
      const int16_t texture = f.texture == level::kNone ? 0 : numbering.flat(f.texture, level);
      return DoomFloor{int32_t(f.type), stair_step(f) ? kStairsCrush : int32_t(f.crush), f.sector->index, f.direction,
                       f.new_special, texture, f.destination, f.speed};
    }
    case Thinker::Kind::kPlat: return doom_plat_of(*static_cast<const Plat*>(t));
    case Thinker::Kind::kLightFlash: {
      const LightFlash& l = *static_cast<const LightFlash*>(t);
      return DoomFlash{l.sector->index, l.count, l.max_light, l.min_light, l.max_time, l.min_time};
    }
    case Thinker::Kind::kStrobe: {
      const Strobe& s = *static_cast<const Strobe*>(t);
      return DoomStrobe{s.sector->index, s.count, s.min_light, s.max_light, s.dark_time, s.bright_time};
    }
    case Thinker::Kind::kGlow: {
      const Glow& g = *static_cast<const Glow*>(t);
      return DoomGlow{g.sector->index, g.min_light, g.max_light, g.direction};
    }
    default: break;
  }
  return DoomGlow{};  // not reached: thinker_lists gives only Doom's kinds
}

void write_thinker(SaveWriter& w, bool thinking) {
  w.pointer();           // prev
  w.pointer();           // next
  w.u32(thinking ? 1 : 0);  // the function: Doom asks only whether a ceiling's or a lift's is set
}

void write_player(SaveWriter& w, const DoomPlayer& d) {
  w.pointer();  // mo
  w.i32(d.state);
  w.u8(uint8_t(d.forward)), w.u8(uint8_t(d.side)), w.i16(d.turn), w.i16(d.consistancy), w.u8(d.chat), w.u8(d.buttons);
  for (int32_t v : {d.view_z, d.view_height, d.delta_view_height, d.bob, d.health, d.armor_points, d.armor_type}) w.i32(v);
  for (int32_t v : d.powers) w.i32(v);
  for (int32_t v : d.cards) w.i32(v);
  w.i32(d.backpack);
  for (int32_t v : d.frags) w.i32(v);
  w.i32(d.ready_weapon), w.i32(d.pending_weapon);
  for (int32_t v : d.weapon_owned) w.i32(v);
  for (int32_t v : d.ammo) w.i32(v);
  for (int32_t v : d.max_ammo) w.i32(v);
  for (int32_t v : {d.attack_down, d.use_down, d.cheats, d.refire, d.kill_count, d.item_count, d.secret_count}) w.i32(v);
  w.pointer();  // message
  w.i32(d.damage_count), w.i32(d.bonus_count);
  w.pointer();  // attacker
  w.i32(d.extra_light), w.i32(d.fixed_colormap), w.i32(d.colormap);
  for (const DoomPlayer::Psprite& p : d.psprites) w.i32(p.state), w.i32(p.tics), w.i32(p.sx), w.i32(p.sy);
  w.i32(d.did_secret);
}

void write_mobj(SaveWriter& w, const DoomMobj& d) {
  write_thinker(w, true);
  w.i32(d.x), w.i32(d.y), w.i32(d.z);
  w.pointer(), w.pointer();  // snext, sprev
  w.i32(d.angle), w.i32(d.sprite), w.i32(d.frame);
  w.pointer(), w.pointer(), w.pointer();  // bnext, bprev, subsector
  for (int32_t v : {d.floor_z, d.ceiling_z, d.radius, d.height, d.mom_x, d.mom_y, d.mom_z, d.valid_count, d.type}) w.i32(v);
  w.pointer();  // info
  for (int32_t v : {d.tics, d.state, d.flags, d.health, d.move_dir, d.move_count}) w.i32(v);
  w.pointer();  // target
  w.i32(d.reaction_time), w.i32(d.threshold), w.i32(d.player), w.i32(d.last_look);
  for (int16_t v : {d.spawn_x, d.spawn_y, d.spawn_angle, d.spawn_type, d.spawn_options}) w.i16(v);
  w.pointer();  // tracer
}

void write_special(SaveWriter& w, const DoomSpecial& s) {
  w.u8(uint8_t(s.index()));  // the variant's order is Doom's classes'
  w.pad();
  std::visit(
      [&](const auto& r) {
        using T = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<T, DoomCeiling>) {
          write_thinker(w, r.thinking);
          for (int32_t v : {r.type, r.sector, r.bottom_height, r.top_height, r.speed, r.crush, r.direction, r.tag, r.old_direction})
            w.i32(v);
        } else if constexpr (std::is_same_v<T, DoomDoor>) {
          write_thinker(w, true);
          for (int32_t v : {r.type, r.sector, r.top_height, r.speed, r.direction, r.top_wait, r.top_countdown}) w.i32(v);
        } else if constexpr (std::is_same_v<T, DoomFloor>) {
          write_thinker(w, true);
          for (int32_t v : {r.type, r.crush, r.sector, r.direction, r.new_special}) w.i32(v);
          w.i16(r.texture);
          w.i32(r.destination), w.i32(r.speed);
        } else if constexpr (std::is_same_v<T, DoomPlat>) {
          write_thinker(w, r.thinking);
          for (int32_t v : {r.sector, r.speed, r.low, r.high, r.wait, r.count, r.status, r.old_status, r.crush, r.tag, r.type})
            w.i32(v);
        } else if constexpr (std::is_same_v<T, DoomFlash>) {
          write_thinker(w, true);
          for (int32_t v : {r.sector, r.count, r.max_light, r.min_light, r.max_time, r.min_time}) w.i32(v);
        } else if constexpr (std::is_same_v<T, DoomStrobe>) {
          write_thinker(w, true);
          for (int32_t v : {r.sector, r.count, r.min_light, r.max_light, r.dark_time, r.bright_time}) w.i32(v);
        } else {
          write_thinker(w, true);
          for (int32_t v : {r.sector, r.min_light, r.max_light, r.direction}) w.i32(v);
        }
      },
      s);
}

}  // namespace

std::string why_not_savable(const World& world) {
  const GameOptions& o = world.options();
  if (!world.map().wall_lines.empty() || o.map < 1)
    return world.map().where + " is no WAD map: Doom's savegames hold a WAD's MAPxx or ExMy";
  if (o.map > 255 || o.episode < 0 || o.episode > 255)
    return world.map().where + ": map numbers beyond a byte do not fit Doom's savegame";
  return "";
}

DoomSave doom_save_of(const World& w, const DoomNumbers& numbers, const std::string& description,
                      std::vector<std::string>* warnings) {
  Numbering numbering{numbers, warnings, {}};
  const level::Level& level = w.level_;
  DoomSave s;
  s.header.description = description.substr(0, std::min(description.find('\0'), kSaveDescriptionSize - 1));
  s.header.skill = w.options().skill;
  s.header.episode = w.options().commercial ? 1 : w.options().episode;  // Doom II's games stay in episode 1
  s.header.map = w.options().map;
  s.header.level_time = w.level_time();
  for (int p = 0; p < kMaxPlayers; ++p) {
    s.header.in_game[size_t(p)] = w.in_game(p);
    if (w.in_game(p)) s.players[size_t(p)] = doom_player_of(w.player(p));
  }
  for (const Sector& sec : w.map().sectors)
    s.sectors.push_back({whole_units(sec.floor_height), whole_units(sec.ceiling_height), numbering.flat(sec.floor_pic, level),
                         numbering.flat(sec.ceiling_pic, level), int16_t(sec.light), int16_t(sec.special), int16_t(sec.tag)});
  for (const Line& line : w.map().lines) {
    DoomLine& d = s.lines.emplace_back();
    d.flags = int16_t(line.flags), d.special = int16_t(line.special), d.tag = int16_t(line.tag);
    for (size_t k = 0; k < 2; ++k) {
      if (line.side[k] < 0) continue;
      const Side& side = w.map().sides[size_t(line.side[k])];
      d.sides[k] = DoomSide{whole_units(side.texture_offset), whole_units(side.row_offset), numbering.texture(side.top, level),
                            numbering.texture(side.bottom, level), numbering.texture(side.middle, level)};
    }
  }
  const ThinkerLists lists = thinker_lists(w);
  for (const Mobj* m : lists.mobjs) s.mobjs.push_back(doom_mobj_of(w, *m));
  for (const Thinker* t : lists.specials) s.specials.push_back(doom_special_of(t, numbering, level));
  return s;
}

std::vector<uint8_t> encode_doom_save(const DoomSave& s) {
  SaveWriter w;
  // header (P_WriteSaveGameHeader)
  for (size_t i = 0; i < kSaveDescriptionSize; ++i) w.u8(i < s.header.description.size() ? uint8_t(s.header.description[i]) : 0);
  for (size_t i = 0; i < kSaveVersionSize; ++i) w.u8(i < sizeof kVersionString - 1 ? uint8_t(kVersionString[i]) : 0);
  w.u8(uint8_t(s.header.skill - 1));
  w.u8(uint8_t(s.header.episode));
  w.u8(uint8_t(s.header.map));
  for (bool in : s.header.in_game) w.u8(in);
  w.u8(uint8_t(s.header.level_time >> 16)), w.u8(uint8_t(s.header.level_time >> 8)), w.u8(uint8_t(s.header.level_time));
  // players (P_ArchivePlayers)
  for (const std::optional<DoomPlayer>& player : s.players) {
    if (!player) continue;
    w.pad();
    write_player(w, *player);
  }
  // world (P_ArchiveWorld)
  for (const DoomSector& d : s.sectors)
    for (int16_t v : {d.floor_height, d.ceiling_height, d.floor_pic, d.ceiling_pic, d.light, d.special, d.tag}) w.i16(v);
  for (const DoomLine& d : s.lines) {
    w.i16(d.flags), w.i16(d.special), w.i16(d.tag);
    for (const auto& side : d.sides)
      if (side)
        for (int16_t v : {side->texture_offset, side->row_offset, side->top, side->bottom, side->middle}) w.i16(v);
  }
  // thinkers (P_ArchiveThinkers)
  for (const DoomMobj& m : s.mobjs) {
    w.u8(kTcMobj);
    w.pad();
    write_mobj(w, m);
  }
  w.u8(kTcEnd);
  // specials (P_ArchiveSpecials)
  for (const DoomSpecial& sp : s.specials) write_special(w, sp);
  w.u8(kTcEndSpecials);
  w.u8(kSaveEndMarker);
  return w.release();
}

// ---- [read] -------------------------------------------------------------------

namespace {

SaveHeader read_header(SaveReader& in) {
  SaveHeader h;
  in.section("the header");
  std::string description;
  for (size_t i = 0; i < kSaveDescriptionSize; ++i) description += char(in.u8());
  h.description = description.substr(0, description.find('\0'));
  const size_t version_at = in.position();
  std::string version;
  for (size_t i = 0; i < kSaveVersionSize; ++i) version += char(in.u8());
  version = version.substr(0, version.find('\0'));
  if (version != kVersionString)
    in.fail_at(version_at, "not a Doom v1.9 savegame (its version is \"" + wad::printable(version) + "\", Doom's \"" +
                               kVersionString + "\")");
  const size_t skill_at = in.position();
  const int skill = in.u8();
  if (skill > 4) in.fail_at(skill_at, "skill " + std::to_string(skill) + " is not Doom's 0..4");
  h.skill = skill + 1;
  h.episode = in.u8();
  h.map = in.u8();
  if (h.episode > 9 || h.map < 1 || h.map > 99)
    in.fail_at(skill_at + 1, "no map of episode " + std::to_string(h.episode) + ", map " + std::to_string(h.map));
  const size_t players_at = in.position();
  std::array<uint8_t, kMaxPlayers> in_game{};
  for (uint8_t& p : in_game) p = in.u8();
  if (std::any_of(in_game.begin(), in_game.end(), [](uint8_t p) { return p > 1; }) ||
      std::none_of(in_game.begin(), in_game.end(), [](uint8_t p) { return p == 1; }))
    in.fail_at(players_at, "players in the game " + std::to_string(in_game[0]) + " " + std::to_string(in_game[1]) + " " +
                               std::to_string(in_game[2]) + " " + std::to_string(in_game[3]) +
                               ": each is 0 or 1, and one at least is 1");
  for (size_t p = 0; p < in_game.size(); ++p) h.in_game[p] = in_game[p] == 1;
  const int a = in.u8(), b = in.u8(), c = in.u8();
  h.level_time = (a << 16) + (b << 8) + c;
  return h;
}

DoomPlayer read_player(SaveReader& in) {
  DoomPlayer d;
  const size_t at = in.position();
  auto counter = [&](int32_t& v, const std::string& what) {
    const size_t field = in.position();
    v = in.i32();
    check_counter(in, field, v, "the player's " + what);
  };
  in.u32();  // mo
  d.state = in.i32();
  check_range(in, at + 4, d.state, 0, 2, "the player's state");
  d.forward = int8_t(in.u8()), d.side = int8_t(in.u8()), d.turn = in.i16(), d.consistancy = in.i16();
  d.chat = in.u8(), d.buttons = in.u8();
  auto height = [&](int32_t& v, const std::string& what) {
    const size_t field = in.position();
    v = in.i32();
    check_height(in, field, v, "the player's " + what);
  };
  height(d.view_z, "view height"), height(d.view_height, "eye height"), height(d.delta_view_height, "eye's spring");
  counter(d.bob, "bob"), counter(d.health, "health"), counter(d.armor_points, "armor"), counter(d.armor_type, "armor type");
  for (int32_t& v : d.powers) counter(v, "power");
  for (int32_t& v : d.cards) v = in.i32();
  d.backpack = in.i32();
  for (int32_t& v : d.frags) v = in.i32();
  const size_t weapons_at = in.position();
  d.ready_weapon = in.i32(), d.pending_weapon = in.i32();
  check_range(in, weapons_at, d.ready_weapon, 0, int(Weapon::kCount) - 1, "the weapon in hand");
  if (d.pending_weapon != kNoWeaponChange)
    check_range(in, weapons_at + 4, d.pending_weapon, 0, int(Weapon::kCount) - 1, "the pending weapon");
  for (int32_t& v : d.weapon_owned) v = in.i32();
  for (int32_t& v : d.ammo) counter(v, "ammo");
  for (int32_t& v : d.max_ammo) counter(v, "most ammo");
  d.attack_down = in.i32(), d.use_down = in.i32(), d.cheats = in.i32();
  counter(d.refire, "refire count"), counter(d.kill_count, "kills"), counter(d.item_count, "items");
  counter(d.secret_count, "secrets");
  in.u32();  // message
  counter(d.damage_count, "red flash"), counter(d.bonus_count, "gold flash");
  in.u32();  // attacker
  counter(d.extra_light, "gun light");
  const size_t colormap_at = in.position();
  d.fixed_colormap = in.i32(), d.colormap = in.i32();
  check_range(in, colormap_at, d.fixed_colormap, 0, kInverseColormap, "the player's fixed light map");
  for (DoomPlayer::Psprite& p : d.psprites) {
    const size_t state_at = in.position();
    p.state = in.i32();
    check_range(in, state_at, p.state, 0, int(StateId::kCount) - 1, "a weapon sprite's state");
    counter(p.tics, "weapon sprite's tics"), counter(p.sx, "weapon sprite's place"), counter(p.sy, "weapon sprite's place");
  }
  d.did_secret = in.i32();
  return d;
}

DoomMobj read_mobj(SaveReader& in) {
  DoomMobj d;
  const size_t at = in.position();
  in.skip(12);  // the thinker: its links and function, which Doom sets anew
  d.x = in.i32(), d.y = in.i32(), d.z = in.i32();
  in.skip(8);  // snext, sprev
  d.angle = in.i32(), d.sprite = in.i32(), d.frame = in.i32();
  in.skip(12);  // bnext, bprev, subsector
  for (int32_t* v : {&d.floor_z, &d.ceiling_z, &d.radius, &d.height, &d.mom_x, &d.mom_y, &d.mom_z, &d.valid_count, &d.type})
    *v = in.i32();
  in.skip(4);  // info
  for (int32_t* v : {&d.tics, &d.state, &d.flags, &d.health, &d.move_dir, &d.move_count}) *v = in.i32();
  in.skip(4);  // target
  d.reaction_time = in.i32(), d.threshold = in.i32(), d.player = in.i32(), d.last_look = in.i32();
  d.spawn_x = in.i16(), d.spawn_y = in.i16(), d.spawn_angle = in.i16(), d.spawn_type = in.i16(), d.spawn_options = in.i16();
  in.skip(4);  // tracer
  // Doom indexes its tables by these without a check.
  check_range(in, at + 36, d.sprite, 0, int(Sprite::kCount) - 1, "a thing's sprite");
  check_range(in, at + 88, d.type, 0, int(ThingType::kCount) - 1, "a thing's type");
  check_range(in, at + 100, d.state, 0, int(StateId::kCount) - 1, "a thing's state");
  check_range(in, at + 112, d.move_dir, 0, 8, "a thing's direction");
  check_range(in, at + 132, d.player, 0, kMaxPlayers, "a thing's player (0: none, else 1..4)");
  check_range(in, at + 136, d.last_look, 0, kMaxPlayers - 1, "a thing's last player looked at");
  check_mobj_counters(in, d, {at + 64, at + 68, at + 72, at + 76, at + 80, at + 96, at + 108, at + 116, at + 124, at + 128,
                             at + 20, at + 56, at + 60});
  return d;
}

constexpr size_t kSpecialSize[] = {48, 40, 42, 56, 36, 36, 28};  // ceiling, door, floor, plat, flash, strobe, glow

DoomSpecial read_special_fields(SaveReader& in, uint8_t cls, size_t sectors);

DoomSpecial read_special(SaveReader& in, uint8_t cls, size_t sectors) {
  const DoomSpecial s = read_special_fields(in, cls, sectors);
  check_special_counters(in, s, in.position() - kSpecialSize[cls] + 12);
  return s;
}

DoomSpecial read_special_fields(SaveReader& in, uint8_t cls, size_t sectors) {
  const size_t at = in.position();
  in.skip(8);  // prev, next
  const bool thinking = in.u32() != 0;
  auto sector = [&](int32_t s, size_t offset) {
    check_range(in, at + offset, s, 0, int64_t(sectors) - 1, "a mover's sector");
    return s;
  };
  switch (cls) {
    case kTcCeiling: {
      DoomCeiling r;
      r.thinking = thinking;
      for (int32_t* v : {&r.type, &r.sector, &r.bottom_height, &r.top_height, &r.speed, &r.crush, &r.direction, &r.tag,
                         &r.old_direction})
        *v = in.i32();
      check_range(in, at + 12, r.type, 0, int(Ceiling::Type::kSilentCrushAndRaise), "a ceiling's type");
      sector(r.sector, 16);
      return r;
    }
    case kTcDoor: {
      DoomDoor r;
      for (int32_t* v : {&r.type, &r.sector, &r.top_height, &r.speed, &r.direction, &r.top_wait, &r.top_countdown}) *v = in.i32();
      check_range(in, at + 12, r.type, 0, int(Door::Type::kBlazeClose), "a door's type");
      sector(r.sector, 16);
      return r;
    }
    case kTcFloor: {
      DoomFloor r;
      for (int32_t* v : {&r.type, &r.crush, &r.sector, &r.direction, &r.new_special}) *v = in.i32();
      r.texture = in.i16();
      r.destination = in.i32(), r.speed = in.i32();
      check_range(in, at + 12, r.type, 0, int(Floor::Type::kRaise512), "a floor's type");
      sector(r.sector, 20);
      return r;
    }
    case kTcPlat: {
      DoomPlat r;
      r.thinking = thinking;
      for (int32_t* v : {&r.sector, &r.speed, &r.low, &r.high, &r.wait, &r.count, &r.status, &r.old_status, &r.crush, &r.tag,
                         &r.type})
        *v = in.i32();
      sector(r.sector, 12);
      check_range(in, at + 36, r.status, 0, int(Plat::Status::kInStasis), "a lift's status");
      check_range(in, at + 40, r.old_status, 0, int(Plat::Status::kInStasis), "a lift's old status");
      check_range(in, at + 52, r.type, 0, int(Plat::Type::kBlazeDwus), "a lift's type");
      return r;
    }
    case kTcFlash: {
      DoomFlash r;
      for (int32_t* v : {&r.sector, &r.count, &r.max_light, &r.min_light, &r.max_time, &r.min_time}) *v = in.i32();
      sector(r.sector, 12);
      return r;
    }
    case kTcStrobe: {
      DoomStrobe r;
      for (int32_t* v : {&r.sector, &r.count, &r.min_light, &r.max_light, &r.dark_time, &r.bright_time}) *v = in.i32();
      sector(r.sector, 12);
      return r;
    }
    default: {
      DoomGlow r;
      for (int32_t* v : {&r.sector, &r.min_light, &r.max_light, &r.direction}) *v = in.i32();
      sector(r.sector, 12);
      return r;
    }
  }
}

}  // namespace

SaveHeader read_save_header(std::span<const uint8_t> bytes, const std::string& what) {
  SaveReader in(bytes, what);
  return read_header(in);
}

std::optional<std::string> save_description(std::span<const uint8_t> bytes) {
  try {
    return read_save_header(bytes, "save").description;
  } catch (const Error&) {
    return std::nullopt;
  }
}

DoomSave parse_doom_save(std::span<const uint8_t> bytes, const std::string& what, const Map& map) {
  SaveReader in(bytes, what);
  DoomSave s;
  s.header = read_header(in);
  in.section("the players");
  for (size_t p = 0; p < s.players.size(); ++p) {
    if (!s.header.in_game[p]) continue;
    in.pad();
    if (!s.player_at) s.player_at = in.position();
    s.players[p] = read_player(in);
  }
  in.section("the sectors", kAnotherMap);
  s.world_at = in.position();
  for (size_t i = 0; i < map.sectors.size(); ++i) {
    DoomSector& d = s.sectors.emplace_back();
    const size_t at = in.position();
    for (int16_t* v : {&d.floor_height, &d.ceiling_height, &d.floor_pic, &d.ceiling_pic, &d.light, &d.special, &d.tag}) *v = in.i16();
    check_range(in, at, d.floor_height, -(kMostHeight >> 16), kMostHeight >> 16, "a sector's floor");
    check_range(in, at + 2, d.ceiling_height, -(kMostHeight >> 16), kMostHeight >> 16, "a sector's ceiling");
  }
  in.section("the lines", kAnotherMap);
  for (const Line& line : map.lines) {
    DoomLine& d = s.lines.emplace_back();
    d.flags = in.i16(), d.special = in.i16(), d.tag = in.i16();
    for (size_t k = 0; k < 2; ++k) {
      if (line.side[k] < 0) continue;
      DoomSide side;
      for (int16_t* v : {&side.texture_offset, &side.row_offset, &side.top, &side.bottom, &side.middle}) *v = in.i16();
      d.sides[k] = side;
    }
  }
  in.section("the things", kAnotherMap);
  s.thinkers_at = in.position();
  for (;;) {
    const size_t at = in.position();
    const uint8_t cls = in.u8();
    if (cls == kTcEnd) break;
    if (cls != kTcMobj)
      in.fail_at(at, "unknown thinker class " + std::to_string(cls) + " (Doom's: 0 end, 1 thing)" + kAnotherMap);
    in.pad();
    s.mobj_at.push_back(in.position());
    s.mobjs.push_back(read_mobj(in));
    if (const int p = s.mobjs.back().player; p && !s.header.in_game[size_t(p - 1)])
      in.fail_at(s.mobj_at.back() + 132, "a thing of player " + std::to_string(p) + ", who is not in the game");
  }
  for (int p = 1; p <= kMaxPlayers; ++p) {
    const bool has_thing = std::any_of(s.mobjs.begin(), s.mobjs.end(), [p](const DoomMobj& m) { return m.player == p; });
    if (s.header.in_game[size_t(p - 1)] && !has_thing) in.fail_at(s.thinkers_at, "no thing is player " + std::to_string(p) + "'s");
  }
  in.section("the specials", kAnotherMap);
  s.specials_at = in.position();
  for (;;) {
    const size_t at = in.position();
    const uint8_t cls = in.u8();
    if (cls == kTcEndSpecials) break;
    if (cls > kTcGlow)
      in.fail_at(at, "unknown special class " + std::to_string(cls) + " (Doom's: 0..6, 7 the end)");
    in.pad();
    s.special_at.push_back(in.position());
    s.specials.push_back(read_special(in, cls, map.sectors.size()));
  }
  in.section("the end marker");
  const size_t end_at = in.position();
  const uint8_t end = in.u8();
  if (end != kSaveEndMarker)
    in.fail_at(end_at, "Doom's end marker is 0x1d, not 0x" + std::string(1, "0123456789abcdef"[end >> 4]) +
                           std::string(1, "0123456789abcdef"[end & 15]) + " (the save is of another map, or broken)");
  s.end = in.position();
  return s;
}

// ---- [load] -------------------------------------------------------------------

namespace {

struct Warnings {
  std::vector<std::string>& out;
  const std::string& what;
  size_t count = 0;
  void add(size_t at, const std::string& message) {
    if (++count <= 12) out.push_back(what + ": byte " + std::to_string(at) + ": " + message);
  }
  void finish() {
    if (count > 12) out.push_back(what + ": " + std::to_string(count - 12) + " more like these");
  }
};

// Empties the World of thinkers as Doom's P_UnArchiveThinkers does (every thing out of
// its lists, every thinker gone), and of every pointer into them.
void clear_thinkers(World& w) {
  // Doom removes the new level's things with P_RemoveMobj, which queues every item for
  // altdeath's respawning at the save's level time (set before): 30 seconds after a
  // load, the items of the map as it began come back where they stood.
  for (const auto& owned : w.thinkers_)
    if (owned->kind == Thinker::Kind::kMobj && !owned->removed) w.queue_item_respawn(*static_cast<const Mobj*>(owned.get()));
  for (Sector& s : w.map_.sectors) s.thing_list = nullptr, s.special_data = nullptr, s.sound_target = nullptr;
  std::fill(w.block_links_.begin(), w.block_links_.end(), nullptr);
  w.thinkers_.clear();
  w.graveyard_.clear();
  w.removed_since_pass_ = 0;
  w.active_plats_.clear();
  w.active_ceilings_.clear();
  for (Player& p : w.players_) p.mo = nullptr, p.attacker = nullptr;
  w.body_queue_.clear();  // Doom's P_SetupLevel starts its queue again
  w.body_queue_slot_ = 0;
  // Doom's globals pointing at things are all set before they are read, save the
  // boss brain's spots, which Doom keeps pointing at the old level's things.
  w.tm_ = {};
  w.line_target_ = w.shoot_thing_ = w.slide_mo_ = w.bomb_source_ = w.bomb_spot_ = nullptr;
  w.sound_target_ = w.corpse_hit_ = w.vile_obj_ = nullptr;
  w.best_slide_line_ = w.second_slide_line_ = nullptr;
  w.intercepts_.clear();
  w.brain_targets_.clear();
  w.brain_target_on_ = 0;
  w.sounds_.clear();
  w.messages_.clear();
  w.console_spawned_ = false;
}

void apply_player(Player& p, const DoomPlayer& d) {
  p.state = PlayerState(d.state);
  p.cmd = TicCmd{d.forward, d.side, d.turn, d.buttons};
  p.view_z = d.view_z, p.view_height = d.view_height, p.delta_view_height = d.delta_view_height, p.bob = d.bob;
  Inventory& inv = p.inv;
  inv.health = d.health, inv.armor = d.armor_points, inv.armor_type = d.armor_type;
  for (size_t i = 0; i < d.powers.size(); ++i) inv.powers[i] = d.powers[i];
  p.cards = 0;
  for (size_t i = 0; i < d.cards.size(); ++i) p.cards |= uint8_t((d.cards[i] != 0) << i);
  inv.backpack = d.backpack != 0;
  inv.ready = Weapon(d.ready_weapon);
  inv.pending = d.pending_weapon == kNoWeaponChange ? Weapon::kCount : Weapon(d.pending_weapon);
  for (size_t i = 0; i < d.weapon_owned.size(); ++i) inv.weapons[i] = d.weapon_owned[i] != 0;
  for (size_t i = 0; i < 4; ++i) inv.ammo[i] = d.ammo[i], inv.max_ammo[i] = d.max_ammo[i];
  p.attack_down = d.attack_down != 0, p.use_down = d.use_down != 0;
  p.cheats = d.cheats, p.refire = d.refire;
  p.kill_count = d.kill_count, inv.items = d.item_count, p.secret_count = d.secret_count;
  p.message.clear();
  inv.damage_count = d.damage_count, inv.bonus_count = d.bonus_count;
  p.attacker = nullptr;
  p.extra_light = d.extra_light, p.fixed_colormap = d.fixed_colormap;
  for (size_t i = 0; i < 2; ++i)
    p.psprites[i] = {StateId(d.psprites[i].state), d.psprites[i].tics, d.psprites[i].sx, d.psprites[i].sy};
  p.did_secret = d.did_secret != 0;
  for (size_t i = 0; i < d.frags.size(); ++i) p.frags[i] = d.frags[i];
}

void apply_world(World& w, const DoomSave& s, const DoomNumbers& numbers, Warnings& warnings) {
  const level::Level& level = w.level_;
  auto name = [&](int t) { return t >= 0 && size_t(t) < level.textures.size() ? level.textures[size_t(t)].name : std::string("sky"); };
  auto flat = [&](int number, int& pic, size_t at, const char* which, size_t sector) {
    if (const auto t = numbers.level_flat(number)) {
      pic = *t;
      return;
    }
    warnings.add(at, "sector " + std::to_string(sector) + "'s " + which + ": flat " + std::to_string(number) + " (" +
                         numbers.flat_name(number) + ") is not in this level (kept " + name(pic) + ")");
  };
  auto texture = [&](int number, int& t, size_t at, size_t line) {
    // Doom's texture 0 is "-" and also the first of TEXTURE1 (which Doom never draws):
    // a side that has either keeps it.
    if (number == 0 && numbers.texture_number(t) == 0) return;
    if (const auto found = numbers.level_texture(number)) {
      t = *found;
      return;
    }
    warnings.add(at, "line " + std::to_string(line) + ": texture " + std::to_string(number) + " (" +
                         numbers.texture_name(number) + ") is not in this level (kept " +
                         (t == level::kNone ? std::string("none") : name(t)) + ")");
  };
  size_t at = s.world_at;
  for (size_t i = 0; i < s.sectors.size(); ++i, at += 14) {
    const DoomSector& d = s.sectors[i];
    Sector& sec = w.map_.sectors[i];
    sec.floor_height = Fixed(d.floor_height) * kFracUnit;
    sec.ceiling_height = Fixed(d.ceiling_height) * kFracUnit;
    flat(d.floor_pic, sec.floor_pic, at + 4, "floor", i);
    flat(d.ceiling_pic, sec.ceiling_pic, at + 6, "ceiling", i);
    sec.light = d.light, sec.special = d.special, sec.tag = d.tag;
  }
  for (size_t l = 0; l < s.lines.size(); ++l) {
    const DoomLine& d = s.lines[l];
    Line& line = w.map_.lines[l];
    line.flags = uint16_t(d.flags), line.special = d.special, line.tag = d.tag;
    at += 6;
    for (size_t k = 0; k < 2; ++k) {
      if (!d.sides[k]) continue;
      Side& side = w.map_.sides[size_t(line.side[k])];
      side.texture_offset = Fixed(d.sides[k]->texture_offset) * kFracUnit;
      side.row_offset = Fixed(d.sides[k]->row_offset) * kFracUnit;
      texture(d.sides[k]->top, side.top, at + 4, l);
      texture(d.sides[k]->bottom, side.bottom, at + 6, l);
      texture(d.sides[k]->middle, side.middle, at + 8, l);
      at += 10;
    }
  }
}

// P_UnArchiveThinkers' and P_UnArchiveSpecials' effects.
void apply_thinkers(World& w, const DoomSave& s, const DoomNumbers& numbers, Warnings& warnings) {
  for (const DoomMobj& d : s.mobjs) {
    Mobj* m = w.make_thinker<Mobj>();
    fill_mobj(w, *m, d);
    m->id = w.next_id_++;
    w.set_thing_position(m);
    m->floor_z = m->subsector->sector->floor_height;  // Doom's loader: the sector's, not the saved ones
    m->ceiling_z = m->subsector->sector->ceiling_height;
    if (m->player) m->player->mo = m;
  }
  for (size_t i = 0; i < s.specials.size(); ++i) {
    std::visit(
        [&](const auto& r) {
          using T = std::decay_t<decltype(r)>;
          Sector* sector = &w.map_.sectors[size_t(r.sector)];
          if constexpr (std::is_same_v<T, DoomCeiling>) {
            Ceiling* c = w.make_thinker<Ceiling>();
            c->active = r.thinking;
            c->type = Ceiling::Type(r.type), c->sector = sector, c->bottom_height = r.bottom_height;
            c->top_height = r.top_height, c->speed = r.speed, c->crush = r.crush != 0, c->direction = r.direction;
            c->tag = r.tag, c->old_direction = r.old_direction;
            sector->special_data = c;
            w.active_ceilings_.push_back(c);
          } else if constexpr (std::is_same_v<T, DoomDoor>) {
            Door* d = w.make_thinker<Door>();
            d->type = Door::Type(r.type), d->sector = sector, d->top_height = r.top_height, d->speed = r.speed;
            d->direction = r.direction, d->top_wait = r.top_wait, d->top_countdown = r.top_countdown;
            sector->special_data = d;
          } else if constexpr (std::is_same_v<T, DoomFloor>) {
            Floor* f = w.make_thinker<Floor>();
            f->type = Floor::Type(r.type), f->crush = r.crush == 1, f->sector = sector, f->direction = r.direction;
            f->new_special = r.new_special, f->destination = r.destination, f->speed = r.speed;
            // Only the floors that change their flat read it (Doom leaves the others' unset).
            if (f->type == Floor::Type::kLowerAndChange || f->type == Floor::Type::kDonutRaise) {
              f->texture = sector->floor_pic;
              if (const auto t = numbers.level_flat(r.texture))
                f->texture = *t;
              else
                warnings.add(s.special_at[i] + 32, "a floor's new flat " + std::to_string(r.texture) + " (" +
                                                       numbers.flat_name(r.texture) + ") is not in this level (its own kept)");
            }
            sector->special_data = f;
          } else if constexpr (std::is_same_v<T, DoomPlat>) {
            Plat* p = w.make_thinker<Plat>();
            p->active = r.thinking;
            p->sector = sector, p->speed = r.speed, p->low = r.low, p->high = r.high, p->wait = r.wait;
            p->count = r.count, p->status = Plat::Status(r.status), p->old_status = Plat::Status(r.old_status);
            p->crush = r.crush != 0, p->tag = r.tag, p->type = Plat::Type(r.type);
            sector->special_data = p;
            w.active_plats_.push_back(p);
          } else if constexpr (std::is_same_v<T, DoomFlash>) {
            LightFlash* l = w.make_thinker<LightFlash>();
            l->sector = sector, l->count = r.count, l->max_light = r.max_light, l->min_light = r.min_light;
            l->max_time = r.max_time, l->min_time = r.min_time;
          } else if constexpr (std::is_same_v<T, DoomStrobe>) {
            Strobe* l = w.make_thinker<Strobe>();
            l->sector = sector, l->count = r.count, l->min_light = r.min_light, l->max_light = r.max_light;
            l->dark_time = r.dark_time, l->bright_time = r.bright_time;
          } else {
            Glow* g = w.make_thinker<Glow>();
            g->sector = sector, g->min_light = r.min_light, g->max_light = r.max_light, g->direction = r.direction;
          }
        },
        s.specials[i]);
  }
}

// The renderers' view of the level, drawn anew from the map.
void show_all(World& w) {
  for (size_t l = 0; l < w.map_.lines.size(); ++l) w.show_line(l);
  w.changed_lines_.clear();
  w.stale_ = true;
}

}  // namespace

void carry_over(World& fresh, const World& before, const SaveHeader& header) {
  // G_InitNew's halving (world.cpp), as the game before had it.
  for (size_t s = size_t(StateId::kSargRun1); s <= size_t(StateId::kSargPain2); ++s)
    fresh.states_[s].tics = before.states_[s].tics;
  for (ThingType t : {ThingType::kBruisershot, ThingType::kHeadshot, ThingType::kTroopshot})
    fresh.thing_info_[size_t(t)].speed = before.thing_info_[size_t(t)].speed;
  fresh.on_ground_ = before.on_ground_;
  fresh.brain_easy_ = before.brain_easy_;
  fresh.opening_ = before.opening_;  // Doom's line-opening globals, which a load leaves alone
  fresh.game_tic_at_start_ =
      int(uint32_t(before.game_tic_at_start_) + uint32_t(before.level_time_) - uint32_t(header.level_time));
}

std::vector<uint8_t> write_save(const World& world, const DoomNumbers& numbers, const std::string& description,
                                const SaveExtras& extras, std::vector<std::string>* warnings) {
  if (const std::string why = why_not_savable(world); !why.empty()) throw Error("cannot save: " + why);
  std::vector<uint8_t> bytes = encode_doom_save(doom_save_of(world, numbers, description, warnings));
  const std::vector<uint8_t> extension = encode_extension(world, extras);
  bytes.insert(bytes.end(), extension.begin(), extension.end());
  return bytes;
}

LoadedSave read_save(World& world, std::span<const uint8_t> bytes, const std::string& what, const DoomNumbers& numbers,
                     bool doom_only) {
  LoadedSave out;
  const DoomSave doom = parse_doom_save(bytes, what, world.map_);
  out.header = doom.header;
  // Our extension is read and checked before the World changes (it must fit the level as it was set up).
  std::optional<Extension> extension;
  SaveReader rest(bytes, what, doom.end);
  if (!doom_only && rest.remaining()) extension = read_extension(rest, doom, world);

  Warnings warnings{out.warnings, what};
  for (int p = 0; p < kMaxPlayers; ++p)
    if (world.in_game(p) != doom.header.in_game[size_t(p)])
      throw Error(what + ": its players are not the game's: set the game up with the save's (SaveHeader::in_game)");
  world.level_time_ = doom.header.level_time;  // Doom's P_ReadSaveGameHeader, before the rest
  clear_thinkers(world);
  for (int p = 0; p < kMaxPlayers; ++p)
    if (doom.players[size_t(p)]) apply_player(world.players_[size_t(p)], *doom.players[size_t(p)]);
  apply_world(world, doom, numbers, warnings);
  apply_thinkers(world, doom, numbers, warnings);
  if (extension) {
    apply_extension(world, doom, *extension, rest, doom.end);
    out.extended = true;
    out.extras = extension->extras;
  }
  warnings.finish();
  show_all(world);
  return out;
}

}  // namespace p3d::play
