// Keys and mouse held during a tic -> a tic command, with Doom's speeds. No SDL
// here: the platform fills Controls, the simulation receives TicCommands.
#pragma once

#include <string>

#include "engine/sim/sim.h"

namespace p3d::game {

struct Controls {
  bool forward = false, back = false;           // W / S, Up / Down
  bool turn_left = false, turn_right = false;   // Left / Right
  bool strafe_left = false, strafe_right = false;  // A / D
  bool use = false;                             // Space, E
  bool noclip = false;                          // the idclip cheat was just typed
  bool strafe_modifier = false;                 // Alt: the turn keys strafe instead
  bool run = false;                             // Shift
  int mouse_dx = 0;                             // pixels moved right since the last tic
};

struct InputSettings {
  double mouse_sensitivity = 24;  // turn units (1/65536 of a turn) per pixel
};

// Doom's typed cheats: letters typed in sequence, whatever keys they also are.
class Cheats {
 public:
  // Feeds one typed letter; true when it completes idclip (or Doom 1's idspispopd).
  bool noclip(char letter);

 private:
  std::string typed_;
};

// Doom's speeds: forward 25 (walk) / 50 (run), sideways 24 / 40; keyboard turns
// 640 / 1280 units a tic, 320 for the first 6 tics a turn key is held.
sim::TicCommand make_command(const Controls& c, int turn_held_tics, const InputSettings& settings = {});

}  // namespace p3d::game
