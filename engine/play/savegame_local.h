// What savegame.cpp (Doom's part) and savegame_extension.cpp (ours) share: the located
// reader, the lists of thinkers both parts index, conversions between things and Doom's
// records, and the extension read before it is applied. Not the format's contract
// (that is savegame.h).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/play/savegame.h"
#include "engine/util/error.h"

namespace p3d::play::savegame_local {

constexpr int kFaceCount = 42;  // Face::index(): 5 pains x 8, god, dead
constexpr size_t kMaxMessage = 4096;

// Reads with every message located: "<what>: byte N: ...".
class SaveReader {
 public:
  SaveReader(std::span<const uint8_t> bytes, std::string what, size_t start = 0)
      : bytes_(bytes), what_(std::move(what)), pos_(start) {}
  uint8_t u8() {
    need(1);
    return bytes_[pos_++];
  }
  int16_t i16() {
    need(2);
    const uint16_t v = uint16_t(bytes_[pos_] | bytes_[pos_ + 1] << 8);
    pos_ += 2;
    return int16_t(v);
  }
  int32_t i32() { return int32_t(u32()); }
  uint32_t u32() {
    need(4);
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= uint32_t(bytes_[pos_ + size_t(i)]) << (8 * i);
    pos_ += 4;
    return v;
  }
  uint64_t u64() {
    const uint64_t lo = u32();
    return lo | uint64_t(u32()) << 32;
  }
  double f64() {
    const double d = std::bit_cast<double>(u64());
    if (!std::isfinite(d)) fail_at(pos_ - 8, "a number that is not finite");
    return d;
  }
  std::string str(size_t max) {
    const size_t at = pos_;
    const uint32_t n = u32();
    if (n > max) fail_at(at, "a text of " + std::to_string(n) + " bytes (at most " + std::to_string(max) + ")");
    need(n);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  // The next n bytes, not consumed.
  std::span<const uint8_t> peek(size_t n) const {
    need(n);
    return bytes_.subspan(pos_, n);
  }
  void skip(size_t n) {
    need(n);
    pos_ += n;
  }
  void pad() {
    while (pos_ & 3) u8();
  }
  // A count of records of at least `record` bytes each that must fit in what is left.
  uint32_t count(size_t record, const char* what) {
    const size_t at = pos_;
    const uint32_t n = u32();
    if (uint64_t(n) * std::max<size_t>(record, 1) > remaining())
      fail_at(at, std::to_string(n) + " " + what + " do not fit in the " + std::to_string(remaining()) + " bytes left");
    return n;
  }
  size_t position() const { return pos_; }
  size_t remaining() const { return bytes_.size() - pos_; }
  // The section being read, for truncation messages, and what a cut there may mean.
  void section(const char* name, const char* hint = "") {
    section_ = name;
    hint_ = hint;
  }
  [[noreturn]] void fail_at(size_t at, const std::string& message) const {
    throw Error(what_ + ": byte " + std::to_string(at) + ": " + message);
  }

 private:
  void need(size_t n) const {
    if (n > remaining())
      fail_at(bytes_.size(), std::string("truncated in ") + section_ + " (" + std::to_string(n - remaining()) +
                                 " more bytes expected)" + hint_);
  }
  std::span<const uint8_t> bytes_;
  std::string what_;
  size_t pos_ = 0;
  const char* section_ = "the header";
  const char* hint_ = "";
};

// A number Doom uses as an index, checked: "<what> N is out of range (low..high)".
void check_range(SaveReader& in, size_t at, int64_t value, int64_t low, int64_t high, const std::string& what);

constexpr int kInverseColormap = 32;   // the last light map a player's view may be fixed to (invulnerability)
constexpr int32_t kMostCount = 1 << 30;
// A number play counts up or down by small steps (health, ammo, tics, timers, lights,
// momentum): within +-2^30, years of tics from overflowing.
void check_counter(SaveReader& in, size_t at, int64_t value, const std::string& what);
// A height (a floor, a ceiling, a thing's z, a mover's destination, the view's): within
// +-8192 units, where Doom's maps keep theirs by far (beyond, play's arithmetic on
// heights overflows).
constexpr int32_t kMostHeight = 8192 << 16;
void check_height(SaveReader& in, size_t at, int64_t value, const std::string& what);
// A thing's counted fields (radius, height, momentum x, y, z, tics, health, move count,
// reaction time, threshold) and heights (z, floor, ceiling), read at these places.
void check_mobj_counters(SaveReader& in, const DoomMobj& d, const std::array<size_t, 13>& at);
// A mover's or light's counted fields (timers, counts, directions, lights), its first
// field after the thinker at `at`.
void check_special_counters(SaveReader& in, const DoomSpecial& s, size_t at);

// The thinkers as Doom's sections list them, and the rest.
struct ThinkerLists {
  std::vector<const Mobj*> mobjs;        // the thinkers section: live things in thinker order
  std::vector<const Thinker*> specials;  // the specials section
  std::vector<const Thinker*> own;       // what Doom does not save: fire flickers, lifts in stasis
  struct Entry {
    uint8_t source;  // 0 mobjs, 1 specials, 2 own
    uint32_t index;
  };
  std::vector<Entry> order;  // every live thinker, in run order
};
ThinkerLists thinker_lists(const World& w);

DoomMobj doom_mobj_of(const World& w, const Mobj& m);
DoomPlat doom_plat_of(const Plat& p);
// A thing from Doom's record, with no target or tracer, its place among the map's
// things found by its spawn point.
void fill_mobj(World& w, Mobj& m, const DoomMobj& d);

// Our extension, read and checked, before anything of it is applied.
struct Extension {
  SaveExtras extras;
  uint8_t play_random = 0, other_random = 0;
  int32_t level_time = 0, game_tic_at_start = 0;
  bool on_ground = false;
  uint8_t exit = 0;
  uint32_t next_id = 1;
  int32_t total_kills = 0, total_items = 0, total_secrets = 0;
  bool brain_easy = false;
  uint32_t brain_target_on = 0;
  std::vector<int32_t> brain_targets;
  std::array<int32_t, kMaxPlayers> attackers{-1, -1, -1, -1};  // per player in the game
  std::array<std::string, kMaxPlayers> messages;
  // A netgame's queues (version 2): the corpses kept (Doom's bodyque) and the items
  // waiting to come back (altdeath's itemrespawnque, tail to head).
  struct Queues {
    uint32_t body_slot = 0;
    std::vector<int32_t> bodies;
    uint32_t item_head = 0, item_tail = 0;
    std::vector<std::pair<MapThing, int32_t>> items;  // the spot and the level time it was taken
  };
  std::optional<Queues> queues;
  struct SectorExtra {
    int32_t floor = 0, ceiling = 0, floor_pic = 0, ceiling_pic = 0, light = 0, special = 0, tag = 0;
    int32_t sound_target = -1, special_data = -1;
    std::vector<int32_t> things;
  };
  std::vector<SectorExtra> sectors;
  std::vector<std::array<int32_t, 5>> sides;
  std::vector<std::array<int32_t, 3>> lines;
  struct Own {
    uint8_t kind = 0;  // 0 fire flicker, 1 lift, 2 crusher
    std::array<int32_t, 4> flicker{};
    DoomPlat plat;
    DoomCeiling ceiling;
  };
  std::vector<Own> own;
  std::vector<ThinkerLists::Entry> order;
  struct MobjExtra {
    int32_t target = -1, tracer = -1;
    uint32_t id = 0;
    int32_t placed = -1;
  };
  std::vector<MobjExtra> live;
  std::optional<std::array<int32_t, 4>> blockmap_header;  // origin x, y, width, height (version 2)
  std::vector<std::pair<uint32_t, std::vector<int32_t>>> cells;
  std::vector<int32_t> plats, ceilings;
  struct ButtonExtra {
    int32_t line = -1, where = 0, texture = 0, timer = 0, sound_sector = -1;
  };
  std::vector<ButtonExtra> buttons;
  std::vector<std::pair<DoomMobj, MobjExtra>> ghosts;
};

// Our extension of the World as it stands, with the game's extras: magic, version,
// length, checksum, payload.
std::vector<uint8_t> encode_extension(const World& w, const SaveExtras& extras);
// Read and checked against Doom's part and the World freshly set up (its level, its
// map's counts); `file` stands at the byte after Doom's end marker.
Extension read_extension(SaveReader& file, const DoomSave& doom, const World& w);
// Puts it back after Doom's part has been loaded; `in` and `at` locate its messages.
void apply_extension(World& w, const DoomSave& doom, const Extension& x, SaveReader& in, size_t at);

}  // namespace p3d::play::savegame_local
