// Demos: how a walk started and every tic's command, in a small validated binary
// file. Replaying one gives the same player and level at every tic.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/play/doom_demo.h"
#include "engine/sim/sim.h"

namespace p3d::sim {

struct Demo {
  uint64_t level_fingerprint = 0;  // the level's geometry and specials, so a demo is not replayed on another
  Vec2 start;
  double angle = 0;
  int skill = level::kDefaultSkill;  // which things are present (keys!)
  uint8_t keys = 0;                  // KeyBits held at the start (--all-keys)
  std::vector<TicCommand> tics;
};

// A checksum of everything the simulation depends on (walls, sides, sectors, specials).
uint64_t fingerprint(const level::Level& level);

std::vector<uint8_t> encode_demo(const Demo& demo);
// Whether a file's bytes are our demo format (else perhaps Doom's: play/doom_demo.h).
bool is_our_demo(std::span<const uint8_t> bytes);

// A Doom demo walked by the simulation: its console player's moves, turns and use
// from the level's start at the demo's skill (weapons do not act yet: attack and
// weapon changes are left out, as are Doom's pause and save requests).
Demo demo_from_doom(const play::DoomDemo& doom, const level::Level& level);
// The demo as Doom v1.9 records it, for the map `episode`, `map` (turns to Doom's
// 256 units: record with Session's Doom rounding for a faithful copy).
play::DoomDemo doom_from_demo(const Demo& demo, int episode, int map);
// A turn as a Doom demo keeps it: rounded to 256 units of 1/65536 of a turn.
constexpr int16_t doom_demo_turn(int16_t turn) { return int16_t(((int(turn) + 128) >> 8) << 8); }
// Throws Error("<what>: message") for a truncated, corrupted or foreign file.
Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what);

}  // namespace p3d::sim
