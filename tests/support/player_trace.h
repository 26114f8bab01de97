// The console player after a tic, as the traced Chocolate Doom writes it
// (tests/golden/doom_demos/*.trace: "tic x y z angle momx momy health prndindex viewz",
// 16.16 fixed point and binary angles), and the same read from our World.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
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

// Chocolate Doom's trace of every player (P3D_TRACE_ALL, condensed by
// tools/peers/netgame_trace.py): each tic's lines hashed, some tics in full.
struct NetTrace {
  std::vector<uint64_t> hashes;                     // per tic
  std::map<size_t, std::vector<std::string>> full;  // tic -> its player lines
};
NetTrace read_net_trace(const std::filesystem::path& path);

// Our players after tic `tic`, in the trace's words ("tic player x y z angle momx momy
// health armor frags0..3 prndindex viewz"), and the hash of a tic's lines.
std::vector<std::string> net_lines(const play::World& w, size_t tic);
uint64_t net_hash(const std::vector<std::string>& lines);

}  // namespace p3d::test
