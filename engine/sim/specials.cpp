// The table follows Doom's p_spec.c dispatch (EV_* calls and their arguments), as
// described in the Doom wiki's linedef type list; speeds are Doom's in map units per
// tic (doors 2, fast doors 8, floors 1, turbo floors 4, lifts 4, fast lifts 8,
// crushers 1, fast crushers 2, raising platforms 1/2, stairs 1/4 or 4).
#include "engine/sim/specials.h"

#include <algorithm>
#include <array>

namespace p3d::sim {

namespace {

using enum Trigger;
using enum Action;

struct Row {
  int number;
  Trigger trigger;
  bool repeat;
  Action action;
  double speed = 0;
  int amount = 0;
  Lock lock = Lock::kNone;
  bool crush = false, blaze = false, monsters_only = false;
};

constexpr bool kOnce = false, kRepeat = true;

// clang-format off
constexpr Row kRows[] = {
    {1, kManual, kRepeat, kDoorRaise, 2},
    {2, kWalk, kOnce, kDoorOpen, 2},
    {3, kWalk, kOnce, kDoorClose, 2},
    {4, kWalk, kOnce, kDoorRaise, 2},
    {5, kWalk, kOnce, kFloorRaise, 1},
    {6, kWalk, kOnce, kCeilingCrushAndRaise, 2, 0, Lock::kNone, true, true},
    {7, kSwitch, kOnce, kStairs, 0.25, 8},
    {8, kWalk, kOnce, kStairs, 0.25, 8},
    {9, kSwitch, kOnce, kDonut, 0.5},
    {10, kWalk, kOnce, kPlatDownWaitUp, 4},
    {11, kSwitch, kOnce, kExit},
    {12, kWalk, kOnce, kLightToBrightest},
    {13, kWalk, kOnce, kLightTo, 0, 255},
    {14, kSwitch, kOnce, kPlatRaiseAndChange, 0.5, 32},
    {15, kSwitch, kOnce, kPlatRaiseAndChange, 0.5, 24},
    {16, kWalk, kOnce, kDoorCloseWait, 2},
    {17, kWalk, kOnce, kLightStrobe},
    {18, kSwitch, kOnce, kFloorRaiseToNearest, 1},
    {19, kWalk, kOnce, kFloorLowerToHighest, 1},
    {20, kSwitch, kOnce, kPlatRaiseToNearestAndChange, 0.5},
    {21, kSwitch, kOnce, kPlatDownWaitUp, 4},
    {22, kWalk, kOnce, kPlatRaiseToNearestAndChange, 0.5},
    {23, kSwitch, kOnce, kFloorLowerToLowest, 1},
    {24, kShoot, kOnce, kFloorRaise, 1},
    {25, kWalk, kOnce, kCeilingCrushAndRaise, 1, 0, Lock::kNone, true},
    {26, kManual, kRepeat, kDoorRaise, 2, 0, Lock::kBlue},
    {27, kManual, kRepeat, kDoorRaise, 2, 0, Lock::kYellow},
    {28, kManual, kRepeat, kDoorRaise, 2, 0, Lock::kRed},
    {29, kSwitch, kOnce, kDoorRaise, 2},
    {30, kWalk, kOnce, kFloorRaiseToTexture, 1},
    {31, kManual, kOnce, kDoorOpen, 2},
    {32, kManual, kOnce, kDoorOpen, 2, 0, Lock::kBlue},
    {33, kManual, kOnce, kDoorOpen, 2, 0, Lock::kRed},
    {34, kManual, kOnce, kDoorOpen, 2, 0, Lock::kYellow},
    {35, kWalk, kOnce, kLightTo, 0, 35},
    {36, kWalk, kOnce, kFloorTurboLower, 4},
    {37, kWalk, kOnce, kFloorLowerAndChange, 1},
    {38, kWalk, kOnce, kFloorLowerToLowest, 1},
    {39, kWalk, kOnce, kTeleport},
    {40, kWalk, kOnce, kCeilingRaiseToHighest, 1},
    {41, kSwitch, kOnce, kCeilingLowerToFloor, 1},
    {42, kSwitch, kRepeat, kDoorClose, 2},
    {43, kSwitch, kRepeat, kCeilingLowerToFloor, 1},
    {44, kWalk, kOnce, kCeilingLowerAndCrush, 1},
    {45, kSwitch, kRepeat, kFloorLowerToHighest, 1},
    {46, kShoot, kRepeat, kDoorOpen, 2},
    {47, kShoot, kOnce, kPlatRaiseToNearestAndChange, 0.5},
    {49, kSwitch, kOnce, kCeilingCrushAndRaise, 1, 0, Lock::kNone, true},
    {50, kSwitch, kOnce, kDoorClose, 2},
    {51, kSwitch, kOnce, kSecretExit},
    {52, kWalk, kOnce, kExit},
    {53, kWalk, kOnce, kPlatPerpetual, 1},
    {54, kWalk, kOnce, kPlatStop},
    {55, kSwitch, kOnce, kFloorRaise, 1, 8, Lock::kNone, true},
    {56, kWalk, kOnce, kFloorRaise, 1, 8, Lock::kNone, true},
    {57, kWalk, kOnce, kCeilingCrushStop},
    {58, kWalk, kOnce, kFloorRaiseBy, 1, 24},
    {59, kWalk, kOnce, kFloorRaiseByAndChange, 1, 24},
    {60, kSwitch, kRepeat, kFloorLowerToLowest, 1},
    {61, kSwitch, kRepeat, kDoorOpen, 2},
    {62, kSwitch, kRepeat, kPlatDownWaitUp, 4},
    {63, kSwitch, kRepeat, kDoorRaise, 2},
    {64, kSwitch, kRepeat, kFloorRaise, 1},
    {65, kSwitch, kRepeat, kFloorRaise, 1, 8, Lock::kNone, true},
    {66, kSwitch, kRepeat, kPlatRaiseAndChange, 0.5, 24},
    {67, kSwitch, kRepeat, kPlatRaiseAndChange, 0.5, 32},
    {68, kSwitch, kRepeat, kPlatRaiseToNearestAndChange, 0.5},
    {69, kSwitch, kRepeat, kFloorRaiseToNearest, 1},
    {70, kSwitch, kRepeat, kFloorTurboLower, 4},
    {71, kSwitch, kOnce, kFloorTurboLower, 4},
    {72, kWalk, kRepeat, kCeilingLowerAndCrush, 1},
    {73, kWalk, kRepeat, kCeilingCrushAndRaise, 1, 0, Lock::kNone, true},
    {74, kWalk, kRepeat, kCeilingCrushStop},
    {75, kWalk, kRepeat, kDoorClose, 2},
    {76, kWalk, kRepeat, kDoorCloseWait, 2},
    {77, kWalk, kRepeat, kCeilingCrushAndRaise, 2, 0, Lock::kNone, true, true},
    {79, kWalk, kRepeat, kLightTo, 0, 35},
    {80, kWalk, kRepeat, kLightToBrightest},
    {81, kWalk, kRepeat, kLightTo, 0, 255},
    {82, kWalk, kRepeat, kFloorLowerToLowest, 1},
    {83, kWalk, kRepeat, kFloorLowerToHighest, 1},
    {84, kWalk, kRepeat, kFloorLowerAndChange, 1},
    {86, kWalk, kRepeat, kDoorOpen, 2},
    {87, kWalk, kRepeat, kPlatPerpetual, 1},
    {88, kWalk, kRepeat, kPlatDownWaitUp, 4},
    {89, kWalk, kRepeat, kPlatStop},
    {90, kWalk, kRepeat, kDoorRaise, 2},
    {91, kWalk, kRepeat, kFloorRaise, 1},
    {92, kWalk, kRepeat, kFloorRaiseBy, 1, 24},
    {93, kWalk, kRepeat, kFloorRaiseByAndChange, 1, 24},
    {94, kWalk, kRepeat, kFloorRaise, 1, 8, Lock::kNone, true},
    {95, kWalk, kRepeat, kPlatRaiseToNearestAndChange, 0.5},
    {96, kWalk, kRepeat, kFloorRaiseToTexture, 1},
    {97, kWalk, kRepeat, kTeleport},
    {98, kWalk, kRepeat, kFloorTurboLower, 4},
    {99, kSwitch, kRepeat, kDoorOpen, 8, 0, Lock::kBlue, false, true},
    {100, kWalk, kOnce, kStairs, 4, 16},
    {101, kSwitch, kOnce, kFloorRaise, 1},
    {102, kSwitch, kOnce, kFloorLowerToHighest, 1},
    {103, kSwitch, kOnce, kDoorOpen, 2},
    {104, kWalk, kOnce, kLightToDarkest},
    {105, kWalk, kRepeat, kDoorRaise, 8, 0, Lock::kNone, false, true},
    {106, kWalk, kRepeat, kDoorOpen, 8, 0, Lock::kNone, false, true},
    {107, kWalk, kRepeat, kDoorClose, 8, 0, Lock::kNone, false, true},
    {108, kWalk, kOnce, kDoorRaise, 8, 0, Lock::kNone, false, true},
    {109, kWalk, kOnce, kDoorOpen, 8, 0, Lock::kNone, false, true},
    {110, kWalk, kOnce, kDoorClose, 8, 0, Lock::kNone, false, true},
    {111, kSwitch, kOnce, kDoorRaise, 8, 0, Lock::kNone, false, true},
    {112, kSwitch, kOnce, kDoorOpen, 8, 0, Lock::kNone, false, true},
    {113, kSwitch, kOnce, kDoorClose, 8, 0, Lock::kNone, false, true},
    {114, kSwitch, kRepeat, kDoorRaise, 8, 0, Lock::kNone, false, true},
    {115, kSwitch, kRepeat, kDoorOpen, 8, 0, Lock::kNone, false, true},
    {116, kSwitch, kRepeat, kDoorClose, 8, 0, Lock::kNone, false, true},
    {117, kManual, kRepeat, kDoorRaise, 8, 0, Lock::kNone, false, true},
    {118, kManual, kOnce, kDoorOpen, 8, 0, Lock::kNone, false, true},
    {119, kWalk, kOnce, kFloorRaiseToNearest, 1},
    {120, kWalk, kRepeat, kPlatDownWaitUp, 8},
    {121, kWalk, kOnce, kPlatDownWaitUp, 8},
    {122, kSwitch, kOnce, kPlatDownWaitUp, 8},
    {123, kSwitch, kRepeat, kPlatDownWaitUp, 8},
    {124, kWalk, kOnce, kSecretExit},
    {125, kWalk, kOnce, kTeleport, 0, 0, Lock::kNone, false, false, true},
    {126, kWalk, kRepeat, kTeleport, 0, 0, Lock::kNone, false, false, true},
    {127, kSwitch, kOnce, kStairs, 4, 16},
    {128, kWalk, kRepeat, kFloorRaiseToNearest, 1},
    {129, kWalk, kRepeat, kFloorRaiseToNearest, 4},
    {130, kWalk, kOnce, kFloorRaiseToNearest, 4},
    {131, kSwitch, kOnce, kFloorRaiseToNearest, 4},
    {132, kSwitch, kRepeat, kFloorRaiseToNearest, 4},
    {133, kSwitch, kOnce, kDoorOpen, 8, 0, Lock::kBlue, false, true},
    {134, kSwitch, kRepeat, kDoorOpen, 8, 0, Lock::kRed, false, true},
    {135, kSwitch, kOnce, kDoorOpen, 8, 0, Lock::kRed, false, true},
    {136, kSwitch, kRepeat, kDoorOpen, 8, 0, Lock::kYellow, false, true},
    {137, kSwitch, kOnce, kDoorOpen, 8, 0, Lock::kYellow, false, true},
    {138, kSwitch, kRepeat, kLightTo, 0, 255},
    {139, kSwitch, kRepeat, kLightTo, 0, 35},
    {140, kSwitch, kOnce, kFloorRaiseBy, 1, 512},
    {141, kWalk, kOnce, kCeilingCrushAndRaise, 1, 0, Lock::kNone, true},
};
// clang-format on

constexpr int kHighest = 141;

std::array<LineSpecial, kHighest + 1> make_table() {
  std::array<LineSpecial, kHighest + 1> table{};
  for (const Row& r : kRows)
    table[size_t(r.number)] = {r.number, r.trigger, r.repeat, r.action, r.speed, r.amount, r.lock, r.crush, r.blaze,
                               r.monsters_only};
  return table;
}

const std::array<LineSpecial, kHighest + 1> kTable = make_table();

}  // namespace

const LineSpecial* line_special(int number) {
  if (number <= 0 || number > kHighest || kTable[size_t(number)].number == 0) return nullptr;
  return &kTable[size_t(number)];
}

LineKind line_kind(int number) {
  const LineSpecial* s = line_special(number);
  if (!s || s->monsters_only) return LineKind::kPlain;
  if (s->lock != Lock::kNone) return LineKind::kLockedDoor;
  if (s->trigger == kManual) return LineKind::kDoor;
  if (s->action == kTeleport) return LineKind::kTeleporter;
  if (s->action == kExit || s->action == kSecretExit) return LineKind::kExit;
  return LineKind::kPlain;
}

}  // namespace p3d::sim
