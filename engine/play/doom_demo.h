// Doom's demo files: .lmp files and the IWAD's DEMO1..DEMO4 lumps. A demo names the
// game it starts (skill, episode, map, options, players) and holds each tic's
// commands for each player, as Doom v1.9 writes them (version 109) or with the turn
// kept whole (version 111: Doom v1.91's long tics, Chocolate Doom's -longtics); the
// headerless demos of Doom 1.2 and older are read too.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace p3d::play {

// One player's command for one tic, as a demo stores it (Doom's ticcmd_t without its
// consistency check and chat).
struct DoomTic {
  int8_t forward = 0;      // walk 25, run 50
  int8_t side = 0;         // > 0 to the right
  int16_t turn = 0;        // 1/65536 of a turn, > 0 to the left; a multiple of 256 but in long tics
  uint8_t buttons = 0;     // DoomButton bits
  friend bool operator==(const DoomTic&, const DoomTic&) = default;
};
enum DoomButton : uint8_t {
  kButtonAttack = 1,
  kButtonUse = 2,
  kButtonChangeWeapon = 4,  // to the weapon in bits 3..5
  kButtonWeaponShift = 3,
  kButtonWeaponMask = 7 << 3,
  kButtonSpecial = 128,     // pause or save instead of the above (ignored when played back)
};

struct DoomDemo {
  static constexpr int kPlayers = 4;
  static constexpr int kVersion19 = 109, kVersionLongTics = 111;
  int version = kVersion19;  // or kVersionLongTics; 0 for the old headerless format
  int skill = 3;      // 1..5, as -skill
  int episode = 1, map = 1;
  int deathmatch = 0;  // Doom's byte: 0 none, 2 altdeath, any other deathmatch
  bool respawn = false, fast = false, no_monsters = false;
  int console_player = 0;
  std::array<bool, kPlayers> players{true, false, false, false};
  // Tic by tic, one command for each player in the game, in player order.
  std::vector<DoomTic> commands;
  bool truncated = false;  // the file ended before Doom's end marker (what is there is played)

  bool long_tics() const { return version == kVersionLongTics; }
  int player_count() const;
  size_t tic_count() const { return player_count() ? commands.size() / size_t(player_count()) : 0; }
  // The command of the console player (the one whose view the demo shows) at a tic.
  DoomTic console_tic(size_t tic) const;
  // Player p's command at a tic (p in the game).
  DoomTic player_tic(size_t tic, int p) const;
  // Doom's netgame for a demo: a second player is in it (G_DoPlayDemo's test).
  bool netgame() const { return players[1]; }
  // The map's lump name: MAPxx for Doom II's games (commercial), else ExMy.
  std::string map_name(bool commercial) const;
};

// True when the bytes start as a Doom demo does (a known version, or an old header).
bool looks_like_doom_demo(std::span<const uint8_t> bytes);
// Throws Error("<what>: ...") for a header Doom could not play or tics cut mid-way.
DoomDemo decode_doom_demo(std::span<const uint8_t> bytes, const std::string& what);
// Version 109 (each turn's high byte), or 111 when long_tics(); with the end marker.
std::vector<uint8_t> encode_doom_demo(const DoomDemo& demo);

}  // namespace p3d::play
