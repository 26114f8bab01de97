// Doom's intermission tally, drawn from the WAD's own art (wi_stuff.c): the finished
// level's name, kills, items and secrets as percentages, the time and Doom's par time,
// over the episode's map (WIMAPn) or Doom II's INTERPIC, scaled by a whole factor and
// centred. Shown with the final counts (Doom counts them up; a key press skips there).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/play/screen.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::play {

struct Tally {
  int kills = 0, total_kills = 0;
  int items = 0, total_items = 0;
  int secrets = 0, total_secrets = 0;
  int seconds = 0;
  // A deathmatch's frag table (Doom's WI_drawDeathmatchStats) instead of the counts:
  // frags[killer][victim] of the players in the game, `me` the console player.
  bool deathmatch = false;
  std::array<bool, 4> in_game{true, false, false, false};
  int me = 0;
  std::array<std::array<int, 4>, 4> frags{};
  // A co-op netgame's table (Doom's WI_drawNetgameStats, when `netgame` and not
  // deathmatch): each player's kills, items and secrets, and frags if anyone has any.
  bool netgame = false;
  std::array<int, 4> player_kills{}, player_items{}, player_secrets{};
};
// A player's total on the frag table: the others killed less its own deaths by its own
// hand, of the players in the game, between -99 and 99 (Doom's WI_fragSum).
int frag_sum(const Tally& tally, int player);

// Doom's par time of a map in seconds (its g_game.c tables), or -1 for none: Doom II's
// MAPxx (`episode` 0), Doom's ExMy for the first three episodes.
int par_seconds(int episode, int map);

class IntermissionArt {
 public:
  // nullopt when the WADs hold no intermission art. episode 0: Doom II's MAPxx maps.
  static std::optional<IntermissionArt> load(const wad::Stack& wads, int episode, int map);
  void draw(const Tally& tally, image::Image& frame, const std::vector<uint32_t>& palette) const;

 private:
  using Picture = std::optional<wad::IndexedImage>;
  Picture background_, level_name_, finished_, kills_, items_, secret_, time_, par_label_, percent_, colon_, minus_, sucks_;
  Picture killers_, victims_, total_, star_, dead_star_;  // the deathmatch table's
  Picture netgame_secret_, netgame_frags_;               // the co-op table's WIOSTS and WIFRGS
  std::array<Picture, 4> player_faces_;                  // STPB0..3: each player's colour
  std::vector<Picture> digits_;
  int par_ = -1;  // seconds, or -1: none shown
};

}  // namespace p3d::play
