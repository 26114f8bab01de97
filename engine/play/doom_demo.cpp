#include "engine/play/doom_demo.h"

#include <algorithm>

#include "engine/util/doom.h"
#include "engine/util/error.h"

namespace p3d::play {

namespace {
constexpr uint8_t kEndMarker = 0x80;
constexpr int kVersion19 = DoomDemo::kVersion19, kVersionLongTics = DoomDemo::kVersionLongTics;
constexpr size_t kHeader19 = 13, kOldHeader = 7;

// A short tic keeps the turn's high byte; a long one all of it, low byte first.
DoomTic read_tic(std::span<const uint8_t> b, bool long_tics) {
  if (!long_tics) return {int8_t(b[0]), int8_t(b[1]), int16_t(uint16_t(b[2] << 8)), b[3]};
  return {int8_t(b[0]), int8_t(b[1]), int16_t(uint16_t(b[2] | b[3] << 8)), b[4]};
}
}  // namespace

int DoomDemo::player_count() const { return int(std::count(players.begin(), players.end(), true)); }

DoomTic DoomDemo::console_tic(size_t tic) const { return player_tic(tic, console_player); }

DoomTic DoomDemo::player_tic(size_t tic, int player) const {
  int slot = 0;  // the player's place among the players in the game
  for (int p = 0; p < player; ++p) slot += players[size_t(p)];
  return commands[tic * size_t(player_count()) + size_t(slot)];
}

std::string DoomDemo::map_name(bool commercial) const { return doom::map_name(commercial, episode, map); }

bool looks_like_doom_demo(std::span<const uint8_t> bytes) {
  if (bytes.empty()) return false;
  const int first = bytes[0];
  // Doom 1.4 to 1.9, long tics, or an old demo's skill.
  return (first >= 104 && first <= kVersion19) || first == kVersionLongTics || first <= 4;
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
    d.deathmatch = bytes[at++];
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
  const size_t command_bytes = d.long_tics() ? 5 : 4, tic_bytes = command_bytes * size_t(d.player_count());
  while (at < bytes.size() && bytes[at] != kEndMarker) {
    if (bytes.size() - at < tic_bytes) throw Error(what + ": the last tic is cut short at byte " + std::to_string(at));
    for (int p = 0; p < d.player_count(); ++p, at += command_bytes)
      d.commands.push_back(read_tic(bytes.subspan(at, command_bytes), d.long_tics()));
  }
  d.truncated = at == bytes.size();
  return d;
}

std::vector<uint8_t> encode_doom_demo(const DoomDemo& d) {
  std::vector<uint8_t> out = {uint8_t(d.long_tics() ? kVersionLongTics : kVersion19), uint8_t(d.skill - 1), uint8_t(d.episode), uint8_t(d.map),
                              uint8_t(d.deathmatch), d.respawn, d.fast, d.no_monsters, uint8_t(d.console_player)};
  for (bool p : d.players) out.push_back(p);
  for (const DoomTic& t : d.commands) {
    const uint16_t turn = uint16_t(t.turn);
    out.insert(out.end(), {uint8_t(t.forward), uint8_t(t.side)});
    if (d.long_tics()) out.push_back(uint8_t(turn));
    out.insert(out.end(), {uint8_t(turn >> 8), t.buttons});
  }
  out.push_back(kEndMarker);
  return out;
}

}  // namespace p3d::play
