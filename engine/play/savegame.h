// Savegames: Doom's own format (Chocolate Doom's p_saveg.c layout, "version 109"),
// written from a World and read into one, with our extension after Doom's end marker
// for what Doom's format loses. One reader and one writer, side by side.
//
// Doom's part, in file order (little-endian; "pad" aligns to 4 bytes from the file's start):
//   header    description[24], "version 109"[16], skill, episode, map, playeringame[4],
//             leveltime (3 bytes, high first)
//   players   per player in the game: pad, player_t (pointers written as 0; psprite
//             states as state numbers)
//   world     per sector: floor, ceiling (whole units), floor flat, ceiling flat, light,
//             special, tag (16 bits each); per line: flags, special, tag, then per side
//             it has: x offset, y offset (whole units), top, bottom, middle texture
//   thinkers  per thing in thinker order: 1, pad, mobj_t (state as its number, player
//             as player + 1, target and tracer as 0); then 0
//   specials  per mover or light in thinker order: its class (ceiling 0, door 1, floor
//             2, plat 3, flash 4, strobe 5, glow 6), pad, its record; then 7
//   0x1d      Doom's end marker
// Textures and flats are Doom's numbers (DoomNumbers), not our level's.
//
// Doom's loader (G_DoLoadGame) sets up the level as a new game does, then replaces the
// player, the world and every thinker with the save's: things first, then movers and
// lights, with no targets, tracers or attacker, each thing's floor and ceiling its
// sector's. That loses what a game in progress also depends on; our extension, which
// Doom never reads, keeps it (extension_*), so that a save loaded continues exactly:
//   "P3DSAVE\0", u32 version, u32 length, u64 FNV-1a of the payload, then the payload:
//   the level's fingerprint, the game's extras (SaveExtras), the random indices, the
//   heights and offsets in full, targets and tracers, the thinkers' interleaving and the
//   ones Doom does not save (fire flickers, lifts stopped in stasis), removed things still
//   pointed at, the order of the sectors' and blockmap cells' thing lists, the lists of
//   active lifts and crushers, the switches' timers, and the World's other state.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/status_bar.h"
#include "engine/play/world.h"
#include "engine/wad/wad.h"

namespace p3d::play {

constexpr size_t kSaveDescriptionSize = 24;  // Doom's SAVESTRINGSIZE (the menu writes at most 23 characters)
constexpr size_t kSaveVersionSize = 16;      // Doom's VERSIONSIZE
constexpr uint8_t kSaveEndMarker = 0x1d;     // Doom's SAVEGAME_EOF
// 2: the blockmap's header (which an intercepts overrun may change) before its cells.
// Version 1 files load as well, with the map's own header.
constexpr uint32_t kSaveExtensionVersion = 2;

// The header: what a load menu shows and which game Doom starts before loading.
struct SaveHeader {
  std::string description;  // up to the first NUL of its 24 bytes
  int skill = 3;            // 1..5 (Doom's gameskill + 1)
  int episode = 1, map = 1;
  int level_time = 0;
  std::array<bool, kMaxPlayers> in_game{true, false, false, false};  // Doom's playeringame: a load plays these
  // MAPxx for Doom II's games (commercial), else ExMy.
  std::string map_name(bool commercial) const;
};

// ---- Doom's records, field by field as the file holds them (pointers left out)

struct DoomPlayer {
  int32_t state = 0;
  int8_t forward = 0, side = 0;
  int16_t turn = 0, consistancy = 0;
  uint8_t chat = 0, buttons = 0;
  int32_t view_z = 0, view_height = 0, delta_view_height = 0, bob = 0;
  int32_t health = 0, armor_points = 0, armor_type = 0;
  std::array<int32_t, 6> powers{}, cards{};
  int32_t backpack = 0;
  std::array<int32_t, 4> frags{};
  int32_t ready_weapon = 0, pending_weapon = 0;
  std::array<int32_t, 9> weapon_owned{};
  std::array<int32_t, 4> ammo{}, max_ammo{};
  int32_t attack_down = 0, use_down = 0, cheats = 0, refire = 0;
  int32_t kill_count = 0, item_count = 0, secret_count = 0;
  int32_t damage_count = 0, bonus_count = 0, extra_light = 0, fixed_colormap = 0, colormap = 0;
  struct Psprite {
    int32_t state = 0, tics = 0, sx = 0, sy = 0;
    friend bool operator==(const Psprite&, const Psprite&) = default;
  };
  std::array<Psprite, 2> psprites{};
  int32_t did_secret = 0;
  friend bool operator==(const DoomPlayer&, const DoomPlayer&) = default;
};

struct DoomSector {
  int16_t floor_height = 0, ceiling_height = 0, floor_pic = 0, ceiling_pic = 0, light = 0, special = 0, tag = 0;
  friend bool operator==(const DoomSector&, const DoomSector&) = default;
};
struct DoomSide {
  int16_t texture_offset = 0, row_offset = 0, top = 0, bottom = 0, middle = 0;
  friend bool operator==(const DoomSide&, const DoomSide&) = default;
};
struct DoomLine {
  int16_t flags = 0, special = 0, tag = 0;
  std::array<std::optional<DoomSide>, 2> sides;  // written for the sides the line has
  friend bool operator==(const DoomLine&, const DoomLine&) = default;
};

struct DoomMobj {
  int32_t x = 0, y = 0, z = 0, angle = 0, sprite = 0, frame = 0;
  int32_t floor_z = 0, ceiling_z = 0, radius = 0, height = 0, mom_x = 0, mom_y = 0, mom_z = 0;
  int32_t valid_count = 0, type = 0, tics = 0, state = 0, flags = 0, health = 0;
  int32_t move_dir = 0, move_count = 0, reaction_time = 0, threshold = 0;
  int32_t player = 0;  // 0, or the player's number + 1
  int32_t last_look = 0;
  int16_t spawn_x = 0, spawn_y = 0, spawn_angle = 0, spawn_type = 0, spawn_options = 0;
  friend bool operator==(const DoomMobj&, const DoomMobj&) = default;
};

// The movers and lights. `thinking` is whether the thinker's function is set: a
// crusher stopped by a line (in stasis) has none.
struct DoomCeiling {
  bool thinking = true;
  int32_t type = 0, sector = 0, bottom_height = 0, top_height = 0, speed = 0, crush = 0, direction = 0, tag = 0,
          old_direction = 0;
  friend bool operator==(const DoomCeiling&, const DoomCeiling&) = default;
};
struct DoomDoor {
  int32_t type = 0, sector = 0, top_height = 0, speed = 0, direction = 0, top_wait = 0, top_countdown = 0;
  friend bool operator==(const DoomDoor&, const DoomDoor&) = default;
};
struct DoomFloor {
  int32_t type = 0, crush = 0, sector = 0, direction = 0, new_special = 0;
  int16_t texture = 0;  // a flat's number
  int32_t destination = 0, speed = 0;
  friend bool operator==(const DoomFloor&, const DoomFloor&) = default;
};
struct DoomPlat {
  bool thinking = true;
  int32_t sector = 0, speed = 0, low = 0, high = 0, wait = 0, count = 0, status = 0, old_status = 0, crush = 0, tag = 0,
          type = 0;
  friend bool operator==(const DoomPlat&, const DoomPlat&) = default;
};
struct DoomFlash {
  int32_t sector = 0, count = 0, max_light = 0, min_light = 0, max_time = 0, min_time = 0;
  friend bool operator==(const DoomFlash&, const DoomFlash&) = default;
};
struct DoomStrobe {
  int32_t sector = 0, count = 0, min_light = 0, max_light = 0, dark_time = 0, bright_time = 0;
  friend bool operator==(const DoomStrobe&, const DoomStrobe&) = default;
};
struct DoomGlow {
  int32_t sector = 0, min_light = 0, max_light = 0, direction = 0;
  friend bool operator==(const DoomGlow&, const DoomGlow&) = default;
};
// In the order of Doom's classes (tc_ceiling ... tc_glow).
using DoomSpecial = std::variant<DoomCeiling, DoomDoor, DoomFloor, DoomPlat, DoomFlash, DoomStrobe, DoomGlow>;

// A whole save as Doom reads it, and where each record began (for messages).
struct DoomSave {
  SaveHeader header;
  std::array<std::optional<DoomPlayer>, kMaxPlayers> players;  // those in the game
  std::vector<DoomSector> sectors;
  std::vector<DoomLine> lines;
  std::vector<DoomMobj> mobjs;
  std::vector<DoomSpecial> specials;
  size_t player_at = 0, world_at = 0, thinkers_at = 0, specials_at = 0;  // player_at: the first player's record
  std::vector<size_t> mobj_at, special_at;
  size_t end = 0;  // the byte after Doom's end marker: our extension, if any, starts here
};

// ---- Doom's numbers for a level's textures and flats (r_data.c's)

// Wall textures are numbered in TEXTURE1 then TEXTURE2 order (the first of a name wins;
// 0 is "no texture"), flats by their lump's place after F_START (the last lump of a
// name wins). The level's flats are told from its wall textures by use: the sectors'
// floors and ceilings, and the animations they belong to.
class DoomNumbers {
 public:
  // Throws Error when the WADs hold no Doom art (no TEXTURE1 or F_START).
  DoomNumbers(const wad::Stack& wads, const level::Level& level);
  // Doom's number of a level texture on a wall (kNone: 0) or on a floor (kSky: F_SKY1's);
  // nullopt for a texture Doom does not have.
  std::optional<int> texture_number(int level_texture) const;
  std::optional<int> flat_number(int level_texture) const;
  // The level's texture for Doom's number; nullopt when the level has no such texture.
  std::optional<int> level_texture(int number) const;
  std::optional<int> level_flat(int number) const;
  // Names for messages.
  std::string texture_name(int number) const;
  std::string flat_name(int number) const;

 private:
  std::vector<std::string> texture_names_;  // Doom's numbers
  std::vector<std::string> flat_lumps_;     // every lump from F_START + 1 to the directory's end
  std::vector<int> level_of_texture_, level_of_flat_;  // per Doom number: the level's texture, or kNone
  std::vector<int> texture_of_level_, flat_of_level_;  // per level texture: Doom's number, or -1
  int sky_flat_ = -1;
};

// ---- what the game keeps beside the World (our extension)

struct SaveExtras {
  uint64_t tics = 0;             // the game's tics on this level
  std::string message;           // the message on screen
  int message_tics = 0;          // and how long it stays
  uint8_t other_random = 0;      // Doom's M_Random index (the face's glances)
  Face::Memory face;
  std::array<double, 5> previous_pose{};  // the view one tic ago (x, y, z, view z, angle), for interpolation
};

// ---- writing

// Whether Doom's format can hold this World: a WAD map named MAPxx or ExMy. The reason
// it cannot, or empty.
std::string why_not_savable(const World& world);

// Doom's records of the World as it stands (what Chocolate Doom's P_Archive* write).
// Textures or flats Doom does not number are written as 0, each named once in `warnings`.
DoomSave doom_save_of(const World& world, const DoomNumbers& numbers, const std::string& description,
                      std::vector<std::string>* warnings = nullptr);
std::vector<uint8_t> encode_doom_save(const DoomSave& save);

// The whole file: Doom's part, then our extension. Throws Error (why_not_savable) for
// a World Doom's format cannot hold.
std::vector<uint8_t> write_save(const World& world, const DoomNumbers& numbers, const std::string& description,
                                const SaveExtras& extras, std::vector<std::string>* warnings = nullptr);

// ---- reading

// The header alone; throws Error("<what>: byte N: ...") for a file that is no Doom
// savegame of version 109, or of a netgame.
SaveHeader read_save_header(std::span<const uint8_t> bytes, const std::string& what);
// The description, or nullopt when the bytes are no savegame.
std::optional<std::string> save_description(std::span<const uint8_t> bytes);

// Doom's part, checked against the map it is loaded on (its sectors, lines and sides)
// and Doom's tables (states, types, sprites): every record in its place, every number
// in range. Throws Error("<what>: byte N: ...").
DoomSave parse_doom_save(std::span<const uint8_t> bytes, const std::string& what, const Map& map);

struct LoadedSave {
  SaveHeader header;
  bool extended = false;  // our extension was read (else the World is as Doom would load it)
  SaveExtras extras;
  std::vector<std::string> warnings;  // textures or flats the level lacks (each kept as it was)
};

// What Doom keeps from the game before across a load, into `fresh` (the save's level
// set up anew): G_InitNew within a load compares the save's skill with itself, so the
// monsters keep the game before's speeds (-fast and nightmare's halved tics); the
// globals play reads before it writes them again go on (p_user.c's onground, the boss
// brain's alternation); gametic goes on while the level time is the save's.
void carry_over(World& fresh, const World& before, const SaveHeader& header);

// G_DoLoadGame after its G_InitNew: `world` is the save's level freshly set up (Doom's
// random index cleared first, things spawned, specials started), with carry_over done
// from the game before. The save's player, world, things and
// specials replace the World's, as Doom's loader does; then, unless `doom_only` or the
// file has none, our extension puts back what Doom's format lost. Throws Error; the
// World is then half loaded and must be thrown away.
LoadedSave read_save(World& world, std::span<const uint8_t> bytes, const std::string& what, const DoomNumbers& numbers,
                     bool doom_only = false);

}  // namespace p3d::play
