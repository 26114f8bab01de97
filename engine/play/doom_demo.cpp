#include "engine/play/doom_demo.h"

#include <algorithm>

#include "engine/util/doom.h"
#include "engine/util/error.h"

namespace p3d::play {

namespace {
constexpr uint8_t kEndMarker = 0x80;
constexpr int kVersion19 = 109;
constexpr size_t kHeader19 = 13, kOldHeader = 7;
}  // namespace

int DoomDemo::player_count() const { return int(std::count(players.begin(), players.end(), true)); }

DoomTic DoomDemo::console_tic(size_t tic) const {
  int slot = 0;  // the console player's place among the players in the game
  for (int p = 0; p < console_player; ++p) slot += players[size_t(p)];
  return commands[tic * size_t(player_count()) + size_t(slot)];
}

std::string DoomDemo::map_name(bool commercial) const { return doom::map_name(commercial, episode, map); }

bool looks_like_doom_demo(std::span<const uint8_t> bytes) {
  if (bytes.empty()) return false;
  const int first = bytes[0];
  return (first >= 104 && first <= kVersion19) || first <= 4;  // Doom 1.4 to 1.9, or an old demo's skill
}

DoomDemo decode_doom_demo(std::span<const uint8_t> bytes, const std::string& what) {
  if (!looks_like_doom_demo(bytes)) throw Error(what + ": not a Doom demo (unknown version " + std::to_string(bytes.empty() ? -1 : bytes[0]) + ")");
  DoomDemo d;
  const bool old = bytes[0] <= 4;
  const size_t header = old ? kOldHeader : kHeader19;
  if (bytes.size() < header) throw Error(what + ": truncated demo header");
  size_t at = 0;
  d.version = old ? 0 : bytes[at++];
  d.skill = bytes[at++] + 1;
  d.episode = bytes[at++];
  d.map = bytes[at++];
  if (!old) {
    d.deathmatch = bytes[at++] != 0;
    d.respawn = bytes[at++] != 0;
    d.fast = bytes[at++] != 0;
    d.no_monsters = bytes[at++] != 0;
    d.console_player = bytes[at++];
  }
  for (bool& p : d.players) p = bytes[at++] != 0;
  if (d.skill < 1 || d.skill > 5) throw Error(what + ": skill " + std::to_string(d.skill - 1) + " is not Doom's 0..4");
  if (d.episode > 4 || d.map < 1 || d.map > 99)
    throw Error(what + ": no map E" + std::to_string(d.episode) + "M" + std::to_string(d.map) + " or MAP" + std::to_string(d.map));
  if (d.player_count() == 0) throw Error(what + ": no player is in the game");
  if (d.console_player >= DoomDemo::kPlayers || !d.players[size_t(d.console_player)])
    throw Error(what + ": the demo's view is of player " + std::to_string(d.console_player + 1) + ", who is not in the game");
  const size_t tic_bytes = 4 * size_t(d.player_count());
  while (at < bytes.size() && bytes[at] != kEndMarker) {
    if (bytes.size() - at < tic_bytes) throw Error(what + ": the last tic is cut short at byte " + std::to_string(at));
    for (int p = 0; p < d.player_count(); ++p, at += 4)
      d.commands.push_back({int8_t(bytes[at]), int8_t(bytes[at + 1]), int8_t(bytes[at + 2]), bytes[at + 3]});
  }
  d.truncated = at == bytes.size();
  return d;
}

std::vector<uint8_t> encode_doom_demo(const DoomDemo& d) {
  std::vector<uint8_t> out = {uint8_t(kVersion19), uint8_t(d.skill - 1), uint8_t(d.episode), uint8_t(d.map),
                              d.deathmatch, d.respawn, d.fast, d.no_monsters, uint8_t(d.console_player)};
  for (bool p : d.players) out.push_back(p);
  for (const DoomTic& t : d.commands) out.insert(out.end(), {uint8_t(t.forward), uint8_t(t.side), uint8_t(t.turn), t.buttons});
  out.push_back(kEndMarker);
  return out;
}

}  // namespace p3d::play
