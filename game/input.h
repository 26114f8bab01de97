// Keys and mouse held during a tic -> a tic command, with Doom's speeds, buttons and
// weapon keys. No SDL here: the platform fills Controls, the World receives Doom's
// TicCmd, and typed cheats become our demos' cheat bits.
#pragma once

#include <string>

#include "engine/play/demo.h"

namespace p3d::game {

struct Controls {
  bool forward = false, back = false;           // W / S, Up / Down
  bool turn_left = false, turn_right = false;   // Left / Right
  bool strafe_left = false, strafe_right = false;  // A / D
  bool use = false;                             // Space, E
  bool attack = false;                          // Ctrl, the left mouse button
  int weapon = 0;                               // 1..7: the weapon key pressed this tic (Doom's), 0: none
  bool strafe_modifier = false;                 // Alt: the turn keys strafe instead
  bool run = false;                             // Shift
  int mouse_dx = 0;                             // pixels moved right since the last tic
  uint8_t cheats = 0;                           // play::DemoCheat bits typed since the last tic
};

struct InputSettings {
  double mouse_sensitivity = 24;  // turn units (1/65536 of a turn) per pixel
};

// Doom's typed cheats: letters typed in sequence, whatever keys they also are.
class Cheats {
 public:
  // Feeds one typed letter; the DemoCheat it completes (idclip or idspispopd, iddqd,
  // idkfa), or 0.
  uint8_t type(char letter);

 private:
  std::string typed_;
};

// Doom's speeds: forward 25 (walk) / 50 (run), sideways 24 / 40; keyboard turns
// 640 / 1280 units a tic, 320 for the first 6 tics a turn key is held.
play::DemoTic make_command(const Controls& c, int turn_held_tics, const InputSettings& settings = {});

}  // namespace p3d::game
