// A thing's place in the state table and the tics it has left there, advanced as
// Doom advances it (P_SetMobjState and the end of P_MobjThinker). The actions are
// the caller's: the machine only says when a state is entered.
#pragma once

#include "engine/play/info.h"

namespace p3d::play {

struct StateClock {
  StateId state = StateId::kNull;
  int tics = kInfiniteTics;
  const StateInfo& info() const { return state_info(state); }
};

// A thing just spawned: in its first state, whose action does not run (as Doom's
// P_SpawnMobj sets the state without entering it).
inline StateClock spawn_clock(StateId state) { return {state, state_info(state).tics}; }

// Enters `state` and, as Doom does, passes at once through each following state
// of zero tics; act(clock, action) runs on entering each state with an action (it
// may itself move the clock). Returns false when the chain reaches kNull: the thing
// is to be removed.
template <typename Act>
bool enter_state(StateClock& clock, StateId state, Act&& act) {
  do {
    if (state == StateId::kNull) {
      clock = {StateId::kNull, kInfiniteTics};
      return false;
    }
    const StateInfo& s = state_info(state);
    clock = {state, s.tics};
    if (s.action != Action::kNone) act(clock, s.action);
    // Doom moves on from the state entered here even if its action changed the
    // clock; only the tics left decide whether to go on.
    state = s.next;
  } while (clock.tics == 0);
  return true;
}

// One tic: counts down and enters the next state when the time is up. False when
// the thing is to be removed.
template <typename Act>
bool advance_state(StateClock& clock, Act&& act) {
  if (clock.tics == kInfiniteTics) return true;
  if (--clock.tics > 0) return true;
  return enter_state(clock, clock.info().next, act);
}

}  // namespace p3d::play
