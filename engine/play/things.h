// The things of a level as Doom spawns them, each on its state clock, advanced a
// tic at a time; the frame each shows goes into the level state for the renderers.
// Actions do not run yet, so every thing walks the loop it starts in: torches
// flicker, barrels bubble, pickups blink, monsters stand breathing. And the frames
// a level must carry for what its things may show (idle, reachable, always).
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/random.h"
#include "engine/play/state_machine.h"
#include "engine/wad/import.h"

namespace p3d::play {

// The frames a thing of this editor number shows from its first state on, following
// each state's next (Doom's idle loops: torches flicker, monsters breathe, pickups
// blink): what ThingClocks shows.
std::vector<wad::FrameName> idle_frames(int editor_number);
// Every frame a thing of this editor number may ever show, or make shown: the frames
// of every state reachable from its spawn, see, pain, melee, missile, death, extreme
// death and raise states (following next), and the same for every type its states'
// actions spawn (missiles, smoke, puffs, fire, lost souls, the boss's cubes and the
// monsters they make, the brain's explosions), blood for whatever bleeds and the
// weapon or clip a dead trooper drops, closed recursively. Its own frames first;
// each frame once. Empty for an editor number that is not Doom's.
std::vector<wad::FrameName> reachable_frames(int editor_number);
// The frames any level may show whatever things it holds: the player's, bullet
// puffs, blood, teleport and item fog, and the player's missiles (rockets, plasma,
// the BFG's ball and its spray), with their explosions.
std::vector<wad::FrameName> always_frames();

class ThingClocks {
 public:
  // Spawns the things present in `state` in the level's order (Doom's THINGS order),
  // drawing from `random` as Doom's spawning does: one number for each thing made
  // (player 1's start included), one more for each whose first state is timed,
  // which starts it a random number of tics into that state. Things Doom draws as
  // shadows (spectres, MF_SHADOW) are marked so in `state`.
  ThingClocks(const level::Level& level, level::State& state, Random& random);

  // One tic: every clock advances (of the placed things still in state.things, which
  // the ShownThing::placed of each entry names); their entries show where they are.
  void tick(level::State& state);
  // Writes the frames shown now into the entries of state.things.
  void show(level::State& state);

  size_t size() const { return clocks_.size(); }

 private:
  struct Clock {
    uint32_t thing;
    StateClock clock;
    std::string drop_key;  // the thing's hanging drop, which picks its frames among equal names
  };
  int32_t frame_for(const Clock& c, int32_t fallback) const;

  // entry_[thing]: the entry of placed thing `thing` in state.things, or kNone (gone).
  void find_entries(const level::State& state);

  const level::Level& level_;
  std::vector<Clock> clocks_;
  std::vector<int32_t> entry_;
  std::unordered_map<std::string, int32_t> frames_;  // frame_key -> Level::sprite_frames index
};

}  // namespace p3d::play
