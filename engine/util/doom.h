// Doom's conventions that the map source, the compiled level and the WAD importer share.
#pragma once

#include <cstdint>

namespace p3d::doom {

// Thing flags, as Doom's THINGS lump stores them: the skills a thing appears at, and more.
enum ThingFlags : uint32_t {
  kThingEasy = 1,        // skills 1 and 2
  kThingMedium = 2,      // skill 3
  kThingHard = 4,        // skills 4 and 5
  kThingAmbush = 8,
  kThingNotSingle = 16,  // multiplayer only
  kThingAllSkills = kThingEasy | kThingMedium | kThingHard,
};

// The skill bit of a skill 1..5 (Doom's -skill).
constexpr uint32_t skill_bit(int skill) { return skill <= 2 ? kThingEasy : skill == 3 ? kThingMedium : kThingHard; }

}  // namespace p3d::doom
