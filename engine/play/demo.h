// Our demos: how a game started (the level, skill and options, where the player stood)
// and every tic's command, in a small validated binary file. Replaying one gives the
// same game at every tic. Doom's own .lmp demos are play/doom_demo.h; both convert.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/geom/geom.h"
#include "engine/level/level.h"
#include "engine/play/doom_demo.h"
#include "engine/play/world.h"

namespace p3d::play {

// What a tic may do beside Doom's command: our cheats, which Doom's demos cannot hold.
enum DemoCheat : uint8_t {
  kToggleNoclip = 1,  // idclip typed
  kToggleGod = 2,     // iddqd
  kGiveAll = 4,       // idkfa: every weapon, full ammo, armor and keys
};
constexpr uint8_t kDemoCheats = kToggleNoclip | kToggleGod | kGiveAll;

struct DemoTic {
  TicCmd cmd;
  uint8_t cheats = 0;  // DemoCheat bits, applied before the tic
  friend bool operator==(const DemoTic&, const DemoTic&) = default;
};

struct Demo {
  uint64_t level_fingerprint = 0;  // the level's geometry and specials, so a demo is not replayed on another
  int skill = level::kDefaultSkill;
  bool fast = false, respawn = false, no_monsters = false;
  bool custom_start = false;  // the player starts at `start`, not the map's player 1 start
  geom::Vec2 start{0, 0};     // (GLM leaves a vector unset by default)
  double angle = 0;           // degrees, counter-clockwise from east
  uint8_t keys = 0;           // the six keys held at the start (--all-keys)
  std::vector<DemoTic> tics;
};

// A checksum of everything the simulation depends on (walls, sides, sectors, specials, things).
uint64_t fingerprint(const level::Level& level);

std::vector<uint8_t> encode_demo(const Demo& demo);
// Whether a file's bytes are our demo format (else perhaps Doom's).
bool is_our_demo(std::span<const uint8_t> bytes);
// Throws Error("<what>: message") for a truncated, corrupted, outdated or foreign file.
Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what);

// Every player's command of a Doom demo's tic (zero for players not in the game).
std::array<TicCmd, kMaxPlayers> players_tic(const DoomDemo& doom, size_t tic);
// A Doom demo's console player as our demo (Doom's pause and save requests dropped).
Demo demo_from_doom(const DoomDemo& doom, const level::Level& level);
// Our demo as Doom v1.9 records it, for map `episode`, `map` (turns rounded to Doom's
// 256 units: record with doom_demo_turn for a faithful copy), or with long tics (v1.91:
// turns kept whole).
DoomDemo doom_from_demo(const Demo& demo, int episode, int map, bool long_tics = false);
// A turn as a Doom demo keeps it: rounded to 256 units of 1/65536 of a turn.
constexpr int16_t doom_demo_turn(int16_t turn) { return int16_t(((int(turn) + 128) >> 8) << 8); }

}  // namespace p3d::play
