// Doom's line specials as data: for each number a player can trigger (Doom and
// Doom II, 1..141), how it is triggered, whether it repeats, and what it does with
// which parameters. The simulation (lines.cpp, movers.cpp) reads this table; the
// automap reads it to colour doors, locks and teleporters.
#pragma once

#include <cstdint>

namespace p3d::sim {

enum class Trigger : uint8_t {
  kWalk,    // W: crossing the line
  kSwitch,  // S: using its front side
  kManual,  // D: using its front side opens the door behind it (the line's back sector)
  kShoot,   // G: shooting it (we have no weapons: never triggered)
};

// Lock colours; a lock opens with the card or the skull of its colour.
enum class Lock : uint8_t { kNone, kBlue, kYellow, kRed };

enum class Action : uint8_t {
  // Doors (ceilings that rise to the lowest neighbour ceiling - 4)
  kDoorRaise,       // open, wait, close
  kDoorOpen,        // open and stay
  kDoorClose,
  kDoorCloseWait,   // close, wait 30 s, reopen
  // Floors
  kFloorLowerToHighest,   // to the highest neighbour floor
  kFloorLowerToLowest,    // to the lowest neighbour floor (or its own)
  kFloorTurboLower,       // to the highest neighbour floor + 8
  kFloorLowerAndChange,   // to the lowest, taking that neighbour's flat and special
  kFloorRaise,            // to the lowest neighbour ceiling (at most its own ceiling); amount: subtracted
  kFloorRaiseToNearest,   // to the next higher neighbour floor
  kFloorRaiseBy,          // by `amount`
  kFloorRaiseByAndChange, // by `amount`, taking the line's front sector flat and special
  kFloorRaiseToTexture,   // by the shortest lower texture around it
  kStairs,                // a staircase of `amount`-high steps
  kDonut,
  // Lifts and moving platforms
  kPlatDownWaitUp,
  kPlatPerpetual,
  kPlatRaiseAndChange,          // by `amount`, taking the line's front sector flat
  kPlatRaiseToNearestAndChange, // to the next higher floor, taking the front flat, clearing the special
  kPlatStop,
  // Ceilings
  kCeilingLowerToFloor,
  kCeilingLowerAndCrush,  // to floor + 8
  kCeilingCrushAndRaise,  // a crusher: down to floor + 8, up, for ever
  kCeilingRaiseToHighest,
  kCeilingCrushStop,
  // Light
  kLightToBrightest,  // the brightest neighbour
  kLightTo,           // `amount`
  kLightToDarkest,    // the darkest neighbour
  kLightStrobe,
  // The player
  kTeleport,
  kExit,
  kSecretExit,
};

struct LineSpecial {
  int number = 0;
  Trigger trigger = Trigger::kWalk;
  bool repeat = false;  // R: stays; 1: the line's special is cleared once used
  Action action = Action::kDoorRaise;
  double speed = 0;     // map units per tic
  int amount = 0;       // a height (raise by, step height) or a light level, as the action says
  Lock lock = Lock::kNone;
  bool crush = false;   // Doom would crush; we stop at the player instead (only the slowdown differs)
  bool blaze = false;   // the fast doors (speed 8)
  bool monsters_only = false;
};

// The special of this number, or nullptr (0, unknown numbers, and the scrolling
// wall 48, which moves nothing).
const LineSpecial* line_special(int number);

// What the automap shows a line as.
enum class LineKind : uint8_t { kPlain, kDoor, kLockedDoor, kTeleporter, kExit };
LineKind line_kind(int number);

}  // namespace p3d::sim
