// Doom's random numbers: one table of 256 bytes read in order by two streams.
// The play stream decides everything a demo depends on (damage, spread, monster
// choices); the other (menus, screen wipes, sounds' pitch) must never touch it.
#pragma once

#include <cstdint>

namespace p3d::play {

extern const uint8_t kRandomTable[256];

class Random {
 public:
  // P_Random: the next byte of the play stream, 0..255.
  int play() { return kRandomTable[play_index_ = uint8_t(play_index_ + 1)]; }
  // P_Random() - P_Random(), the left call first (as Doom's compiler ordered it).
  int play_difference() {
    const int first = play();
    return first - play();
  }
  // M_Random: the stream that does not affect play.
  int other() { return kRandomTable[other_index_ = uint8_t(other_index_ + 1)]; }
  // M_ClearRandom: both streams back to their start (at each level's start).
  void clear() { play_index_ = other_index_ = 0; }
  uint8_t play_index() const { return play_index_; }
  uint8_t other_index() const { return other_index_; }
  // Both streams where a savegame left them.
  static Random at(uint8_t play_index, uint8_t other_index) {
    Random r;
    r.play_index_ = play_index;
    r.other_index_ = other_index;
    return r;
  }

 private:
  uint8_t play_index_ = 0, other_index_ = 0;
};

}  // namespace p3d::play
