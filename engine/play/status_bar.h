// Doom's status bar, drawn from the WAD's own art (STBAR, its numbers, the face, keys
// and arms) at Doom's places, scaled by a whole factor along the bottom of the
// frame: the ammo in hand, health, arms owned, the face, armor, keys, and every
// ammo count beside its maximum. A pure function of the values and the art.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/image/image.h"
#include "engine/play/random.h"
#include "engine/play/screen.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::play {

constexpr int kStatusBarHeight = 32;  // rows of Doom's 320x200 screen
constexpr int kNoAmmoShown = 1994;   // Doom's "no number" (fists, chainsaw)

// What the bar shows (Doom's player at a level's start by default).
struct StatusValues {
  int health = 100, armor = 0;
  int ready_ammo = 50;                          // the weapon in hand's, or kNoAmmoShown
  std::array<int, 4> ammo{50, 0, 0, 0};         // bullets, shells, cells, rockets (Doom's order)
  std::array<int, 4> max_ammo{200, 50, 300, 50};
  std::array<bool, 6> arms{true, false, false, false, false, false};  // weapons 2 to 7 owned
  uint8_t keys = 0;                             // blue, yellow, red cards, then the skulls (bits 0..5)
  int face = 0;                                 // Face::index()
  // A netgame: the face on its player's colour (STFB0..3), or -1; in deathmatch the
  // frag count stands where the arms were.
  int face_background = -1;
  bool deathmatch = false;
  int frags = 0;
};

// What Doom's face reads from the player each tic (ST_updateFaceWidget's plyr).
constexpr int kFaceWeapons = 9;  // Doom's NUMWEAPONS
struct FaceInput {
  int health = 100;
  int bonus_count = 0;    // a pickup's gold flash: only then is a new weapon grinned at
  int damage_count = 0;   // the red flash: only then does the face show pain
  bool attacked = false;  // hurt by a thing other than the player itself (Doom's attacker, not mo)
  uint32_t angle_to_attacker = 0, angle = 0;  // binary angles: player to attacker, and the player's facing
  bool attack_down = false;
  std::array<bool, kFaceWeapons> weapons{true, true};  // owned, in Doom's order (the fist and the pistol)
  bool god_mode = false;
  int invulnerability = 0;  // tics of the power left
};
struct Player;
// The face's input from the World's player.
FaceInput face_input(const Player& player);

// Doom's face (ST_updateFaceWidget): dead, then the grin at a new weapon, then pain
// turned toward the attacker, then a rampage while firing, then the god's face;
// otherwise a glance straight, left or right (Doom's other random stream, drawn every
// tic) every half second, each face as pained as the health is low.
class Face {
 public:
  // Vanilla Doom shows "ouch" when the health ROSE by more than 20 while hurt (its
  // test is inverted, so it almost never shows); kBigDamage shows it as meant, after
  // a fall of more than 20 in a tic.
  enum class Ouch : uint8_t { kDoom, kBigDamage };
  explicit Face(Ouch ouch = Ouch::kDoom) : ouch_(ouch) {}

  // Doom's ST_initData at a level's start: straight ahead, no health seen yet, the
  // weapons owned now not new. (The priority and the firing count carry on.)
  void start_level(const FaceInput& in);
  // Doom's ST_Ticker's part: one draw from `random` (M_Random), then the face.
  void tic(Random& random, const FaceInput& in);
  // Into Doom's faces: 5 pains x 8 (straight 0..2, right, left, ouch, grin, rampage), god, dead.
  int index() const { return index_; }
  // What the face remembers from tic to tic, for savegames (Doom's saves lose it).
  struct Memory {
    int index = 0, count = 0, priority = 0, old_health = -1, attack_countdown = -1;
    std::array<bool, kFaceWeapons> old_weapons{};
  };
  Memory memory() const { return {index_, count_, priority_, old_health_, attack_countdown_, old_weapons_}; }
  void restore(const Memory& m) {
    index_ = m.index, count_ = m.count, priority_ = m.priority, old_health_ = m.old_health;
    attack_countdown_ = m.attack_countdown, old_weapons_ = m.old_weapons;
  }

 private:
  int pain_offset(int health) const;
  void update(int random_number, const FaceInput& in);

  Ouch ouch_;
  int index_ = 0, count_ = 0, priority_ = 0;
  int old_health_ = -1;        // Doom's st_oldhealth: the health the last tic ended with
  int attack_countdown_ = -1;  // Doom's lastattackdown: tics of firing left before the rampage
  std::array<bool, kFaceWeapons> old_weapons_{true, true};
};

class StatusBarArt {
 public:
  // nullopt when the WADs hold no STBAR (not Doom's art); a missing or broken piece is
  // left out of the bar.
  static std::optional<StatusBarArt> load(const wad::Stack& wads);

  // The bar's height in the frame: 32 rows times the whole scale that fits.
  static int height_in(int frame_width, int frame_height);
  // Draws the bar at the bottom of the frame, centred, in the palette's colours.
  void draw(const StatusValues& values, image::Image& frame, const std::vector<uint32_t>& palette) const;

 private:
  using Picture = std::optional<wad::IndexedImage>;
  Picture bar_, percent_, minus_, arms_background_;
  std::array<Picture, 4> face_backgrounds_;  // STFB0..3
  std::array<Picture, 10> tall_, small_, grey_;
  std::array<Picture, 6> keys_;
  std::vector<Picture> faces_;  // Face::index() order: 5 pains x 8, then god, then dead
};

}  // namespace p3d::play
