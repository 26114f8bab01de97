// What moves by itself in a Doom level: doors, lifts, floors, ceilings, stairs and
// crushers (Doom's sector thinkers, one per sector at a time), and flickering,
// glowing and strobing lights. They change only the level's State, never the level.
//
// Doom's rules, from its p_doors.c, p_plats.c, p_floor.c, p_ceilng.c and p_lights.c:
// a tagged action starts on every sector with the line's tag that no other mover
// owns; a plane moves by its speed each tic and lands exactly on its destination;
// a plane that would leave the player no room goes back where it was, and then a
// door reverses, a lift returns, a floor or crusher waits (crushers stop at the
// player rather than hurt: this is not a shooter). Deterministic: randomness (which
// way a perpetual lift starts, lights) comes from Doom's play stream, drawn as Doom
// draws it, so the lights flicker as Doom's do.
#pragma once

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/info.h"
#include "engine/play/random.h"
#include "engine/sim/specials.h"

namespace p3d::sim {

// A sound started during a tic: from the middle of a sector (doors, lifts,
// switches), or from the player when `sector` is kNone (pickups, a locked door).
struct SoundEvent {
  play::Sound sound;
  int sector = level::kNone;
  friend bool operator==(const SoundEvent&, const SoundEvent&) = default;
};

// Asked after a plane of `sector` moved: clip whatever stands in the sector to its new
// heights (the player rides floors) and answer whether it all still fits.
using FitsAfterMove = std::function<bool(int sector)>;

class Movers {
 public:
  // Starts the lights and the timed doors of the level's sector specials, in sector
  // order, drawing from Doom's play stream as Doom's P_SpawnSpecials does.
  Movers(const level::Level& level, level::State& state, play::Random& random);

  // A tagged special acting on every sector with the line's tag, as if the line
  // `wall` triggered it (some actions read the line's front sector). True if it
  // started or changed anything (switches flip only then).
  bool activate(const LineSpecial& special, uint32_t wall);
  // A manual door (D specials): the sector behind the line. A raise door used while
  // it moves reverses (closing) or closes at once (opening or waiting).
  bool use_door(const LineSpecial& special, uint32_t wall);

  // One tic of every mover, in the order they started, then every light.
  void tick(const FitsAfterMove& fits);

  bool busy(int sector) const { return busy_[size_t(sector)] != 0; }
  // The sounds started since the last clear, in order (Doom's, from p_doors.c etc.).
  const std::vector<SoundEvent>& sounds() const { return sounds_; }
  void clear_sounds() { sounds_.clear(); }
  size_t active() const { return movers_.size(); }

  // Neighbour queries (Doom's P_Find*Surrounding), over the sectors across the
  // sector's two-sided walls, at the current heights.
  double lowest_floor_around(int sector) const;    // including its own floor
  double highest_floor_around(int sector) const;   // -500 when it has no neighbour
  double next_higher_floor(int sector, double height) const;  // `height` when none is higher
  double lowest_ceiling_around(int sector) const;  // its own ceiling when it has no neighbour
  double highest_ceiling_around(int sector) const; // 0 when it has no neighbour
  int darkest_around(int sector, int start) const;
  int brightest_around(int sector) const;

 private:
  enum class Kind : uint8_t { kDoor, kFloor, kPlat, kCeiling };
  enum class Status : uint8_t { kUp, kDown, kWaiting, kStopped };
  struct Mover {
    Kind kind;
    Action action;       // which door, floor, plat or ceiling
    int sector;
    int tag = 0;
    int direction = 0;   // +1 up, -1 down, 0 waiting (doors, ceilings), 2 waiting before opening (doors)
    int old_direction = 0;  // a stopped crusher's
    Status status = Status::kUp, old_status = Status::kUp;  // plats
    double speed = 0, base_speed = 0;
    double low = 0, high = 0;  // destinations: floor (low) and ceiling or plat top (high)
    int wait = 0, count = 0;
    bool crush = false, blaze = false;
    int change_texture = level::kNone, change_special = -1;  // applied on arrival when set
    bool finished = false;
  };
  struct Light {
    enum class Kind : uint8_t { kFlash, kStrobe, kGlow, kFlicker } kind;
    int sector;
    int low, high;
    int low_time = 0, high_time = 0, count = 0, direction = -1;
  };
  enum class Plane : uint8_t { kFloor, kCeiling };
  enum class Moved : uint8_t { kOk, kBlocked, kArrived };

  Moved move_plane(Mover& m, Plane plane, double dest, int direction, const FitsAfterMove& fits);
  void tick_door(Mover& m, const FitsAfterMove& fits);
  void tick_floor(Mover& m, const FitsAfterMove& fits);
  void tick_plat(Mover& m, const FitsAfterMove& fits);
  void tick_ceiling(Mover& m, const FitsAfterMove& fits);
  void tick_light(Light& l);

  Mover& add(Kind kind, Action action, int sector, double speed);
  bool start_door(const LineSpecial& s, int sector);
  void door_sound(const Mover& m);  // as it starts opening or closing
  bool start_floor(const LineSpecial& s, int sector, uint32_t wall);
  bool start_plat(const LineSpecial& s, int sector, uint32_t wall);
  bool start_ceiling(const LineSpecial& s, int sector);
  bool build_stairs(const LineSpecial& s, int sector);
  bool start_donut(const LineSpecial& s, int sector);
  bool change_light(const LineSpecial& s, int sector);
  void start_lights_and_timers();
  void add_strobe(int sector, int dark_time, bool in_sync);

  int other_side(uint32_t wall, int sector) const;
  int next_random();  // 0..255, Doom's P_Random
  void sound(play::Sound s, int sector) { sounds_.push_back({s, sector}); }
  // Doom's grinding planes: a sound every 8 tics of level time while they move.
  void grind(const Mover& m) {
    if (time_ % 8 == 0) sound(play::Sound::kStnmov, m.sector);
  }

  const level::Level& level_;
  level::State& state_;
  play::Random& random_;
  std::vector<Mover> movers_;
  std::vector<Light> lights_;
  std::vector<uint8_t> busy_;
  std::vector<std::vector<uint32_t>> sector_walls_;  // two-sided walls touching each sector, in wall order
  std::unordered_map<int, std::vector<int>> tagged_;  // sectors by tag, in sector order
  const std::vector<int>& tagged(int tag) const;
  std::vector<SoundEvent> sounds_;
  uint64_t time_ = 0;  // tics run (Doom's leveltime)
};

}  // namespace p3d::sim
