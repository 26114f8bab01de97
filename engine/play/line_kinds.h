// What a line's Doom special means to someone reading the map (the automap's colours):
// a door opened by hand, a locked door and its key, a teleporter, an exit.
#pragma once

#include <cstdint>

namespace p3d::play {

enum class LineKind : uint8_t { kPlain, kDoor, kLockedDoor, kTeleporter, kExit };
enum class Lock : uint8_t { kNone, kBlue, kYellow, kRed };

LineKind line_kind(int special);
// The key a locked door of this special needs (kNone for every other special).
Lock line_lock(int special);

}  // namespace p3d::play
