#include "engine/play/tally_count.h"

#include <algorithm>

namespace p3d::play {

namespace {

constexpr int kPauseTics = 35;                // TICRATE between the counts
constexpr int kNextLocationTics = 4 * 35;     // SHOWNEXTLOCDELAY seconds
constexpr int kLeavingTics = 10;              // WI_initNoState's cnt
constexpr int kSingleDone = 10, kNetgameDone = 10, kDeathmatchDone = 4;

// Doom's WI_fragSum: unbounded (the deathmatch count bounds what it shows).
int frag_total(const Tally& t, int player) {
  int sum = 0;
  for (int j = 0; j < kMaxPlayers; ++j)
    if (t.in_game[size_t(j)] && j != player) sum += t.frags[size_t(player)][size_t(j)];
  return sum - t.frags[size_t(player)][size_t(player)];
}

}  // namespace

TallyCount::TallyCount(const Tally& tally, bool commercial, bool frags_before) : tally_(tally), commercial_(commercial) {
  // Doom's WI_initVariables: totals of at least 1, for the percentages.
  tally_.total_kills = std::max(tally_.total_kills, 1);
  tally_.total_items = std::max(tally_.total_items, 1);
  tally_.total_secrets = std::max(tally_.total_secrets, 1);
  if (tally_.deathmatch) return;  // WI_initDeathmatchStats: every count at 0
  if (!tally_.netgame) return;    // WI_initStats: nothing shown yet
  // WI_initNetgameStats: the counts at 0. Doom adds the frag totals to its static
  // dofrags without clearing it first, so a netgame's earlier tally can leave it on
  // (or a sum of opposite totals turn it off).
  int frags = frags_before ? 1 : 0;
  for (int i = 0; i < kMaxPlayers; ++i) {
    if (!tally_.in_game[size_t(i)]) continue;
    shown_.kills[size_t(i)] = shown_.items[size_t(i)] = shown_.secrets[size_t(i)] = 0;
    frags += frag_total(tally_, i);
  }
  shown_.show_frags = frags != 0;
}

int TallyCount::percent_kills(int p) const { return tally_.player_kills[size_t(p)] * 100 / tally_.total_kills; }
int TallyCount::percent_items(int p) const { return tally_.player_items[size_t(p)] * 100 / tally_.total_items; }
int TallyCount::percent_secrets(int p) const { return tally_.player_secrets[size_t(p)] * 100 / tally_.total_secrets; }

void TallyCount::tic(World& world, const std::array<TicCmd, kMaxPlayers>& cmds) {
  ++tics_;
  hurry(world, cmds);
  switch (stage_) {
    case Stage::kCounting:
      if (tally_.deathmatch) count_deathmatch();
      else if (tally_.netgame) count_netgame();
      else count_single();
      break;
    case Stage::kNextLocation:  // WI_updateShowNextLoc
      if (!--countdown_ || hurried_) leave_soon();
      else shown_.pointer_on = (countdown_ & 31) < 20;
      break;
    case Stage::kLeaving:  // WI_updateNoState
      if (!--countdown_) stage_ = Stage::kOver;
      break;
    case Stage::kOver: break;
  }
}

// WI_checkForAccelerate: a button newly down, of any player in the game.
void TallyCount::hurry(World& world, const std::array<TicCmd, kMaxPlayers>& cmds) {
  for (int i = 0; i < kMaxPlayers; ++i) {
    if (!tally_.in_game[size_t(i)]) continue;
    Player& p = world.player(i);
    const uint8_t buttons = cmds[size_t(i)].buttons;
    if (buttons & kBtAttack) {
      if (!p.attack_down) hurried_ = true;
      p.attack_down = true;
    } else {
      p.attack_down = false;
    }
    if (buttons & kBtUse) {
      if (!p.use_down) hurried_ = true;
      p.use_down = true;
    } else {
      p.use_down = false;
    }
  }
}

// The count's last state waits for a press (then its sound, and on); an odd one
// pauses a second before the next count.
void TallyCount::wait_or_pause(int done, Sound on_press) {
  if (state_ == done) {
    if (!hurried_) return;
    sound(on_press);
    after_count();
  } else if ((state_ & 1) && !--pause_) {
    pause_ = kPauseTics;
    ++state_;
  }
}

// The counting is over and a press came: Doom's map of the episode, or Doom II's last tics.
void TallyCount::after_count() {
  hurried_ = false;
  if (commercial_) {
    leave_soon();
    return;
  }
  stage_ = Stage::kNextLocation;  // WI_initShowNextLoc
  shown_.next_location = true;
  countdown_ = kNextLocationTics;
}

void TallyCount::leave_soon() {  // WI_initNoState
  stage_ = Stage::kLeaving;
  hurried_ = false;
  countdown_ = kLeavingTics;
  shown_.next_location = true;
  shown_.pointer_on = true;  // WI_drawNoState shows the pointer
}

void TallyCount::show_final_counts() {
  for (int i = 0; i < kMaxPlayers; ++i) {
    if (!tally_.in_game[size_t(i)]) continue;
    shown_.kills[size_t(i)] = percent_kills(i);
    shown_.items[size_t(i)] = percent_items(i);
    shown_.secrets[size_t(i)] = percent_secrets(i);
  }
}

// WI_updateStats: the console player's kills, items, secrets, then time and par.
void TallyCount::count_single() {
  const int me = tally_.me;
  if (hurried_ && state_ != kSingleDone) {
    hurried_ = false;
    shown_.kills[size_t(me)] = percent_kills(me);
    shown_.items[size_t(me)] = percent_items(me);
    shown_.secrets[size_t(me)] = percent_secrets(me);
    shown_.seconds = tally_.seconds;
    shown_.par = tally_.par;
    sound(Sound::kBarexp);
    state_ = kSingleDone;
  }
  const bool tick_sound = !(tics_ & 3);
  auto count = [&](int& shown, int final_value) {
    shown += 2;
    if (tick_sound) sound(Sound::kPistol);
    if (shown < final_value) return;
    shown = final_value;
    sound(Sound::kBarexp);
    ++state_;
  };
  if (state_ == 2) {
    count(shown_.kills[size_t(me)], percent_kills(me));
  } else if (state_ == 4) {
    count(shown_.items[size_t(me)], percent_items(me));
  } else if (state_ == 6) {
    count(shown_.secrets[size_t(me)], percent_secrets(me));
  } else if (state_ == 8) {
    if (tick_sound) sound(Sound::kPistol);
    shown_.seconds = std::min(shown_.seconds + 3, tally_.seconds);
    shown_.par += 3;
    if (shown_.par >= tally_.par) {
      shown_.par = tally_.par;
      if (shown_.seconds >= tally_.seconds) {
        sound(Sound::kBarexp);
        ++state_;
      }
    }
  } else {
    wait_or_pause(kSingleDone, Sound::kSgcock);
  }
}

// WI_updateNetgameStats: every player's kills, items, secrets, then frags if any.
void TallyCount::count_netgame() {
  if (hurried_ && state_ != kNetgameDone) {
    hurried_ = false;
    show_final_counts();
    if (shown_.show_frags)
      for (int i = 0; i < kMaxPlayers; ++i)
        if (tally_.in_game[size_t(i)]) shown_.frags[size_t(i)] = frag_total(tally_, i);
    sound(Sound::kBarexp);
    state_ = kNetgameDone;
  }
  // Each in-game player's count up by `step` to its final value; true while any is short.
  auto count_all = [&](std::array<int, kMaxPlayers>& shown, int step, auto final_value) {
    if (!(tics_ & 3)) sound(Sound::kPistol);
    bool ticking = false;
    for (int i = 0; i < kMaxPlayers; ++i) {
      if (!tally_.in_game[size_t(i)]) continue;
      shown[size_t(i)] += step;
      const int last = final_value(i);
      if (shown[size_t(i)] >= last) shown[size_t(i)] = last;
      else ticking = true;
    }
    return ticking;
  };
  if (state_ == 2) {
    if (!count_all(shown_.kills, 2, [&](int i) { return percent_kills(i); })) sound(Sound::kBarexp), ++state_;
  } else if (state_ == 4) {
    if (!count_all(shown_.items, 2, [&](int i) { return percent_items(i); })) sound(Sound::kBarexp), ++state_;
  } else if (state_ == 6) {
    if (!count_all(shown_.secrets, 2, [&](int i) { return percent_secrets(i); }))
      sound(Sound::kBarexp), state_ += shown_.show_frags ? 1 : 3;
  } else if (state_ == 8) {
    if (!count_all(shown_.frags, 1, [&](int i) { return frag_total(tally_, i); })) sound(Sound::kPldeth), ++state_;
  } else {
    wait_or_pause(kNetgameDone, Sound::kSgcock);
  }
}

// WI_updateDeathmatchStats: each frag of the table a step a tic toward its value.
void TallyCount::count_deathmatch() {
  auto& frags = shown_.deathmatch_frags;
  auto& totals = shown_.deathmatch_totals;
  if (hurried_ && state_ != kDeathmatchDone) {
    hurried_ = false;
    for (int i = 0; i < kMaxPlayers; ++i) {
      if (!tally_.in_game[size_t(i)]) continue;
      for (int j = 0; j < kMaxPlayers; ++j)
        if (tally_.in_game[size_t(j)]) frags[size_t(i)][size_t(j)] = tally_.frags[size_t(i)][size_t(j)];
      totals[size_t(i)] = frag_total(tally_, i);
    }
    sound(Sound::kBarexp);
    state_ = kDeathmatchDone;
  }
  if (state_ == 2) {
    if (!(tics_ & 3)) sound(Sound::kPistol);
    bool ticking = false;
    for (int i = 0; i < kMaxPlayers; ++i) {
      if (!tally_.in_game[size_t(i)]) continue;
      for (int j = 0; j < kMaxPlayers; ++j) {
        const int last = tally_.frags[size_t(i)][size_t(j)];
        int& shown = frags[size_t(i)][size_t(j)];
        if (!tally_.in_game[size_t(j)] || shown == last) continue;
        shown = std::clamp(last < 0 ? shown - 1 : shown + 1, -99, 99);  // held at 99: it never arrives
        ticking = true;
      }
      totals[size_t(i)] = std::clamp(frag_total(tally_, i), -99, 99);
    }
    if (!ticking) sound(Sound::kBarexp), ++state_;
  } else {
    wait_or_pause(kDeathmatchDone, Sound::kSlop);
  }
}

}  // namespace p3d::play
