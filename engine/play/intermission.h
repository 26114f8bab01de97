// Doom's intermission, drawn from the WAD's own art (wi_stuff.c): the finished level's
// name, kills, items and secrets as percentages, the time and Doom's par time (or a
// netgame's table, or a deathmatch's frags), over the episode's map (WIMAPn) or Doom
// II's INTERPIC; then the level entered next, on Doom's episode map with the levels
// taken and a "you are here" pointer. Scaled by a whole factor and centred. The counts
// shown at each tic are engine/play/tally_count.h's.
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
  int total_kills = 0, total_items = 0, total_secrets = 0;
  int seconds = 0;
  // Doom's par time as Chocolate Doom counts it (g_game.c's tables), and whether the
  // tally shows it (not on Doom's fourth episode).
  int par = 0;
  bool show_par = true;
  // The level's number (MAPxx or ExMy's y), the level after it (Doom's wminfo.next
  // + 1; 0 for none), and whether the secret level was done (Doom's didsecret: its
  // splat on the episode map).
  int map = 0, next_map = 0;
  bool did_secret = false;
  // A deathmatch's frag table (Doom's WI_drawDeathmatchStats) instead of the counts:
  // frags[killer][victim] of the players in the game, `me` the console player.
  bool deathmatch = false;
  std::array<bool, 4> in_game{true, false, false, false};
  int me = 0;
  std::array<std::array<int, 4>, 4> frags{};
  // Each player's kills, items and secrets (the console player's alone, but for a
  // co-op netgame's table: Doom's WI_drawNetgameStats, with frags if anyone has any).
  bool netgame = false;
  std::array<int, 4> player_kills{}, player_items{}, player_secrets{};
};

// What the screen shows at a tic of the intermission: Doom's cnt_* and dm_* counters
// (percentages and seconds of -1 are not drawn yet), then the next level's page.
struct TallyShown {
  std::array<int, 4> kills{-1, -1, -1, -1}, items{-1, -1, -1, -1}, secrets{-1, -1, -1, -1};
  std::array<int, 4> frags{};  // a co-op netgame's frag column (Doom's cnt_frags)
  int seconds = -1, par = -1;
  std::array<std::array<int, 4>, 4> deathmatch_frags{};  // dm_frags
  std::array<int, 4> deathmatch_totals{};                // dm_totals
  bool show_frags = false;      // Doom's dofrags: a co-op table's frag column
  bool next_location = false;   // the count is over: the level entered next
  bool pointer_on = false;      // the "you are here" pointer blinks (snl_pointeron)
};

// Doom's par time of a map in seconds as Chocolate Doom counts it (G_DoCompleted's
// tables; it reads no BEX [PARS]): Doom II's MAPxx (`episode` 0), Doom's ExMy, and
// for the fourth episode, which has none, the Doom II entry past its map. 0 elsewhere.
int par_seconds(int episode, int map);

class IntermissionArt {
 public:
  // nullopt when the WADs hold no intermission art. episode 0: Doom II's MAPxx maps;
  // next_map: the level after (its name is shown on entering it), 0 for none.
  static std::optional<IntermissionArt> load(const wad::Stack& wads, int episode, int map, int next_map);
  void draw(const Tally& tally, const TallyShown& shown, image::Image& frame, const std::vector<uint32_t>& palette) const;

 private:
  using Picture = std::optional<wad::IndexedImage>;
  Picture background_, level_name_, finished_, kills_, items_, secret_, time_, par_label_, percent_, colon_, minus_, sucks_;
  Picture killers_, victims_, total_, star_, dead_star_;  // the deathmatch table's
  Picture netgame_secret_, netgame_frags_;               // the co-op table's WIOSTS and WIFRGS
  std::array<Picture, 4> player_faces_;                  // STPB0..3: each player's colour
  std::vector<Picture> digits_;
  Picture next_name_, entering_, splat_;  // the next level's page: WIENTER, WISPLAT
  std::array<Picture, 2> you_are_here_;   // WIURH0, WIURH1: the first that fits the screen
  int episode_ = 0;
};

}  // namespace p3d::play
