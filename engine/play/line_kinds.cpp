#include "engine/play/line_kinds.h"

namespace p3d::play {

Lock line_lock(int special) {
  switch (special) {
    case 26: case 32: case 99: case 133: return Lock::kBlue;     // DR, D1, SR, S1 blue
    case 27: case 34: case 136: case 137: return Lock::kYellow;  // DR, D1, SR, S1 yellow
    case 28: case 33: case 134: case 135: return Lock::kRed;     // DR, D1, SR, S1 red
    default: return Lock::kNone;
  }
}

LineKind line_kind(int special) {
  if (line_lock(special) != Lock::kNone) return LineKind::kLockedDoor;
  switch (special) {
    case 1: case 31: case 117: case 118: return LineKind::kDoor;  // opened by hand (DR, D1, fast)
    case 39: case 97: return LineKind::kTeleporter;               // the player's (125, 126 are monsters')
    case 11: case 51: case 52: case 124: return LineKind::kExit;  // normal and secret, switched or walked
    default: return LineKind::kPlain;
  }
}

}  // namespace p3d::play
