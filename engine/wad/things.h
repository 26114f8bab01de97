// Doom's and Doom II's things, by editor number: what each looks like when a map
// starts (its spawn sprite and frame, full bright or not, standing or hanging from
// the ceiling) and what kind of thing it is. Player starts and other editor-only
// things (deathmatch starts, teleport destinations, the boss's targets) are absent:
// they are never drawn.
#pragma once

#include <span>

namespace p3d::wad {

enum class ThingKind { kDecoration, kPickup, kKey, kMonster };

struct ThingInfo {
  int type;          // editor number
  char sprite[5];    // the sprite's lump prefix
  char frame;        // its spawn frame, 'A'...
  bool bright;       // full bright
  bool hanging;      // hangs from the ceiling (Doom's MF_SPAWNCEILING)
  int height, radius;  // map units; a hanging thing's origin lies `height` below the ceiling
  ThingKind kind;
};

// nullptr for a thing that is never drawn or unknown.
const ThingInfo* thing_info(int type);
// Editor-only things: player starts (1-4), deathmatch starts (11), teleport destinations (14), boss targets (87, 89).
bool editor_only_thing(int type);
std::span<const ThingInfo> thing_table();

}  // namespace p3d::wad
