// Doom's intermission as it runs, tic by tic (wi_stuff.c's WI_Ticker): the tally
// counted up with its sounds, hurried on by any player's fresh press of fire or use,
// then Doom's map of the episode for four seconds (not on Doom II), then ten tics
// before the next level. Every player's commands drive it, so that every node of a
// netgame (and a demo that crosses levels) leaves the tally at the same tic.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "engine/play/intermission.h"
#include "engine/play/world.h"

namespace p3d::play {

class TallyCount {
 public:
  enum class Stage : uint8_t { kCounting, kNextLocation, kLeaving, kOver };

  // The tally of the level left; `commercial`: Doom II (no episode map after the count).
  // `frags_before`: the last netgame tally showed frags (Doom's dofrags, never cleared).
  TallyCount(const Tally& tally, bool commercial, bool frags_before = false);
  // One tic (Doom's WI_Ticker) with each player's command: a fresh press of fire or use
  // by any player in the game hurries the count on (WI_checkForAccelerate). Doom keeps
  // whether each button was down in the players themselves, so the next level starts
  // with them as the tally left them.
  void tic(World& world, const std::array<TicCmd, kMaxPlayers>& cmds);
  Stage stage() const { return stage_; }
  // The next level is due (Doom's G_WorldDone was called).
  bool over() const { return stage_ == Stage::kOver; }
  const TallyShown& shown() const { return shown_; }
  int tics() const { return tics_; }  // Doom's bcnt
  // The sounds of the tics since the last call (from nowhere, at full volume).
  std::vector<Sound> take_sounds() { return std::exchange(sounds_, {}); }

 private:
  void hurry(World& world, const std::array<TicCmd, kMaxPlayers>& cmds);
  void count_single();
  void count_netgame();
  void count_deathmatch();
  void after_count();
  void leave_soon();
  void wait_or_pause(int done, Sound on_press);
  int percent_kills(int p) const;
  int percent_items(int p) const;
  int percent_secrets(int p) const;
  void show_final_counts();
  void sound(Sound s) { sounds_.push_back(s); }

  Tally tally_;
  bool commercial_ = false;
  Stage stage_ = Stage::kCounting;
  int state_ = 1;  // sp_state, ng_state or dm_state: odd ones pause, even ones count (the last waits for a press)
  int pause_ = 35;
  int countdown_ = 0;  // Doom's cnt: of the episode's map, then of the last ten tics
  int tics_ = 0;
  bool hurried_ = false;  // Doom's acceleratestage
  TallyShown shown_;
  std::vector<Sound> sounds_;
};

}  // namespace p3d::play
