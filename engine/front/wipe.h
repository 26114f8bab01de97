// Doom's screen melt (f_wipe.c's wipe_initMelt and wipe_doMelt): when the screen
// changes from one state to another (title to demo, menu to game, level to tally),
// the old screen's columns slide down, each pair of Doom's 320 a little after its
// neighbour, uncovering the new one. The world waits meanwhile.
#pragma once

#include <array>

#include "engine/image/image.h"
#include "engine/play/random.h"

namespace p3d::front {

class Melt {
 public:
  // Where each column starts (rows above the screen's top: its delay), from Doom's
  // M_Random as wipe_initMelt draws it (320 numbers).
  explicit Melt(play::Random& m_random);
  // One tic of wipe_doMelt; true once every column has slid off the screen.
  bool tic();
  bool done() const { return done_; }
  // The screen between `start` (the old) and `end` (the new), both of out's size:
  // Doom's 320x200 scaled to it.
  void draw(const image::Image& start, const image::Image& end, image::Image& out) const;

 private:
  static constexpr int kPairs = 160, kHeight = 200;
  std::array<int, kPairs> y_{};  // rows each column pair has slid; < 0: still waiting
  bool done_ = false;
};

}  // namespace p3d::front
