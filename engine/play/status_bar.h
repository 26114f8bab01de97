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
};

// The face looking about as Doom's does when nothing happens to it: a new glance
// (straight, left or right, by Doom's other random stream) every half second, its
// pain shown by the health.
class Face {
 public:
  void tic(Random& random, int health);
  int index() const { return index_; }

 private:
  int index_ = 0, count_ = 0;
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
  std::array<Picture, 10> tall_, small_, grey_;
  std::array<Picture, 6> keys_;
  std::vector<Picture> faces_;  // Face::index() order: 5 pains x 8, then god, then dead
};

}  // namespace p3d::play
