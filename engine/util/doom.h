// Doom's conventions that the map source, the compiled level and the WAD importer share.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

// Thing types (editor numbers) the simulation acts on.
enum ThingType : int {
  kPlayerOneStart = 1,
  kBlueCardThing = 5,
  kYellowCardThing = 6,
  kRedCardThing = 13,
  kTeleportDestination = 14,
  kRedSkullThing = 38,
  kYellowSkullThing = 39,
  kBlueSkullThing = 40,
};

// Line specials the world acts on every tic.
enum LineSpecialNumber : int {
  kScrollLeft = 48,  // the front side's texture scrolls left
};

// Sector specials (SECTORS' special field) that the simulation acts on.
enum SectorSpecial : int {
  kLightFlicker = 1,
  kStrobeFast = 2,
  kStrobeSlow = 3,
  kStrobeHurt = 4,     // strobes, and hurts 20% as super slime does
  kSlimeHurt = 5,      // 10% every 32 tics without the radiation suit
  kNukageHurt = 7,     // 5%
  kExitHurt = 11,      // E1M8's end: 20%, never to death, and the level ends at 10% health
  kGlow = 8,
  kSecretSector = 9,   // counts as found when the player stands on its floor
  kDoorCloseIn30 = 10,
  kStrobeSlowSync = 12,
  kStrobeFastSync = 13,
  kDoorRaiseIn5Min = 14,
  kSuperSlimeHurt = 16,  // 20%, even through the suit now and then
  kFireFlicker = 17,
};

// The skill bit of a skill 1..5 (Doom's -skill).
constexpr uint32_t skill_bit(int skill) { return skill <= 2 ? kThingEasy : skill == 3 ? kThingMedium : kThingHard; }

// The texture a switch texture flips to when the switch is used, by Doom's naming
// (SW1xxx <-> SW2xxx: Doom's own pairs follow it, as do most PWADs'); empty if the
// name is not a switch's.
inline std::string switch_partner(std::string_view name) {
  if (name.size() <= 3 || name[0] != 'S' || name[1] != 'W' || (name[2] != '1' && name[2] != '2')) return {};
  std::string partner(name);
  partner[2] = name[2] == '1' ? '2' : '1';
  return partner;
}

// An animated texture or flat (Doom's nukage, water, lava, fire walls...): the
// textures of its frames in Doom's order, each shown `tics` tics in turn in place of
// any of them. `phase` is Doom's number of the first frame modulo the frame count:
// Doom starts each frame's cycle at its own number, so frame k shows
// frames[(t / tics + phase + k) % n] at level time t.
struct TextureAnimation {
  std::vector<int32_t> frames;
  int32_t tics = 8;
  int32_t phase = 0;
  friend bool operator==(const TextureAnimation&, const TextureAnimation&) = default;
};

// Doom's animated ranges, by the names of their first and last frames (the frames
// are every texture or flat between them in the WADs' order). A range whose first
// frame is not in the WADs is not there (another game's or episode's).
struct AnimatedRange {
  bool texture;  // a wall texture's range, else a flat's
  const char* first;
  const char* last;
  int tics;
};
std::span<const AnimatedRange> animated_ranges();

// A map's lump name: Doom II's MAPxx (commercial games), else Doom's ExMy.
std::string map_name(bool commercial, int episode, int map);
// The map an exit leads to, in Doom's order (ExMy: M8 ends the episode, a secret
// exit goes to M9, M9 returns where its episode's secret exit left; MAPxx: MAP15's
// secret exit goes to MAP31, MAP31's to MAP32, both return to MAP16, MAP30 ends the
// game, other secret exits are normal ones). Empty when the game or episode ends,
// the name is not Doom's, or `exists` says the map is not there.
std::string next_map(std::string_view map, bool secret, const std::function<bool(const std::string&)>& exists);

}  // namespace p3d::doom
