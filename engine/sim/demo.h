// Demos: how a walk started and every tic's command, in a small validated binary
// file. Replaying one gives the same player and level at every tic.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

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
// Throws Error("<what>: message") for a truncated, corrupted or foreign file.
Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what);

}  // namespace p3d::sim
