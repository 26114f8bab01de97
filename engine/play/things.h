// The things of a level as Doom spawns them, each on its state clock, advanced a
// tic at a time; the frame each shows goes into the level state for the renderers.
// Actions do not run yet, so every thing walks the loop it starts in: torches
// flicker, barrels bubble, pickups blink, monsters stand breathing.
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
// blink): what the importer embeds for ThingClocks to show.
std::vector<wad::FrameName> idle_frames(int editor_number);

class ThingClocks {
 public:
  // Spawns the things present in `state` in the level's order (Doom's THINGS order),
  // drawing from `random` as Doom's spawning does: one number for each thing made
  // (player 1's start included), one more for each whose first state is timed,
  // which starts it a random number of tics into that state.
  ThingClocks(const level::Level& level, const level::State& state, Random& random);

  // One tic: every clock advances; state.thing_sprites shows where they are.
  void tick(level::State& state);
  // Writes the frames shown now into state.thing_sprites.
  void show(level::State& state) const;

  size_t size() const { return clocks_.size(); }

 private:
  struct Clock {
    uint32_t thing;
    StateClock clock;
    std::string drop_key;  // the thing's hanging drop, which picks its frames among equal names
  };
  int32_t frame_for(const Clock& c, int32_t fallback) const;

  const level::Level& level_;
  std::vector<Clock> clocks_;
  std::unordered_map<std::string, int32_t> frames_;  // frame_key -> Level::sprite_frames index
};

}  // namespace p3d::play
