// The console player after a tic, as the traced Chocolate Doom writes it
// (tests/golden/doom_demos/*.trace: "tic x y z angle momx momy health prndindex viewz",
// 16.16 fixed point and binary angles), and the same read from our World.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/play/world.h"

namespace p3d::test {

struct PlayerTic {
  int64_t tic, x, y, z, angle, momx, momy, health, random_index, view_z;
  bool operator==(const PlayerTic&) const = default;
};

// A trace file's lines ('#' lines are comments).
std::vector<PlayerTic> read_player_trace(const std::filesystem::path& path);

// The world's console player after tic `tic`.
PlayerTic player_tic(const play::World& world, int64_t tic);

std::string describe(const PlayerTic& t);

}  // namespace p3d::test
