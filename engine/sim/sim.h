// The game simulation: fixed 35 Hz tics, Doom's movement (thrust, friction,
// gravity) and a player circle that slides along walls, climbs steps of at most
// 24 units and needs 56 units of headroom. Deterministic: the same level, start
// and tic commands give the same player at every tic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/level/level.h"

namespace p3d::sim {

using geom::Vec2;

constexpr int kTicRate = 35;
constexpr double kPlayerRadius = 16;
constexpr double kPlayerHeight = 56;
constexpr double kMaxStep = 24;
constexpr double kViewHeight = 41;

// One tic of input, as in Doom's ticcmd_t. forward and side are Doom's move units
// (walk 25 / run 50 forward, 24 / 40 sideways; side > 0 is to the right); turn is in
// 1/65536 of a full turn, counter-clockwise; buttons as Button.
struct TicCommand {
  int8_t forward = 0;
  int8_t side = 0;
  int16_t turn = 0;
  uint8_t buttons = 0;
  friend bool operator==(const TicCommand&, const TicCommand&) = default;
};
enum Button : uint8_t {
  kUse = 1,  // act on the line in front (doors, switches)
};

struct Player {
  Vec2 pos;
  double angle = 0;      // degrees, counter-clockwise from east
  double z = 0;          // feet
  double momz = 0;       // vertical speed, units per tic
  Vec2 momentum{0, 0};   // units per tic
  double view_offset = 0;  // squat after a step up, recovering to 0
  double view_z() const { return z + kViewHeight + view_offset; }
};

// Walls listed by 128-unit cells (Doom's blockmap): the collision queries.
class Blockmap {
 public:
  explicit Blockmap(const level::Level& level);
  // Calls f(wall index) for each wall whose cells meet the box; a wall may repeat.
  template <typename F>
  void for_each_near(const geom::BBox& box, F&& f) const {
    const int c0 = std::max(0, cell_x(box.min.x)), c1 = std::min(cols_ - 1, cell_x(box.max.x));
    const int r0 = std::max(0, cell_y(box.min.y)), r1 = std::min(rows_ - 1, cell_y(box.max.y));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        for (uint32_t k = start_[size_t(r) * cols_ + c]; k < start_[size_t(r) * cols_ + c + 1]; ++k) f(walls_[k]);
  }

 private:
  int cell_x(double x) const { return int(std::floor((x - origin_.x) / kCell)); }
  int cell_y(double y) const { return int(std::floor((y - origin_.y) / kCell)); }
  static constexpr double kCell = 128;
  Vec2 origin_;
  int cols_ = 1, rows_ = 1;
  std::vector<uint32_t> start_, walls_;
};

class World {
 public:
  // The level as it starts at a skill (level::start_state); the world owns that state
  // and changes it as the level is played.
  explicit World(const level::Level& level, int skill = level::kDefaultSkill);

  // The player at the level's start, or at a given place (feet on the floor there).
  Player spawn() const;
  Player spawn_at(Vec2 pos, double angle) const;

  // Advances the player by one tic.
  void tick(Player& player, const TicCommand& cmd);

  // Floor and ceiling under a circle of the player's radius at pos: the highest floor
  // and the lowest ceiling of every sector it touches.
  struct Heights {
    double floor, ceiling;
  };
  Heights heights_at(Vec2 pos) const;

  // Whether the wall stops a player standing at feet height z on the side of `from`.
  bool blocks(uint32_t wall, Vec2 from, double z) const;

  const level::Level& level() const { return level_; }
  // What the level looks like now: renderers draw it.
  const level::State& state() const { return state_; }

 private:
  void move(Player& p) const;
  bool step(Player& p, Vec2 delta) const;
  void fall(Player& p) const;
  std::vector<uint32_t> walls_near(const geom::BBox& box) const;

  const level::Level& level_;
  Blockmap blockmap_;
  level::State state_;
};

// Demos: the start state and the tic commands, in a small validated binary file.
struct Demo {
  uint64_t level_fingerprint = 0;  // the level's geometry, so a demo is not replayed on another
  Vec2 start;
  double angle = 0;
  std::vector<TicCommand> tics;
};

// A checksum of everything the simulation depends on (walls, sides, sector heights).
uint64_t fingerprint(const level::Level& level);

std::vector<uint8_t> encode_demo(const Demo& demo);
// Throws Error("<what>: message") for a truncated, corrupted or foreign file.
Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what);

}  // namespace p3d::sim
