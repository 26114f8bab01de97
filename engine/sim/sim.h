// The game simulation: fixed 35 Hz tics, Doom's movement (thrust, friction,
// gravity) and a player circle that slides along walls, climbs steps of at most
// 24 units and needs 56 units of headroom; and Doom's level mechanics, which move
// the player through a level: the use key, lines walked over, switches, doors,
// lifts, floors, crushers, stairs, teleporters, keys and locks, secrets, exits.
// Deterministic: the same level, start and tic commands give the same player and
// level state at every tic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/inventory.h"
#include "engine/play/random.h"
#include "engine/play/things.h"
#include "engine/sim/movers.h"

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
  kUse = 1,     // act on the line in front (doors, switches): on the tic it goes down
  kNoclip = 2,  // the idclip cheat: walls stop blocking, or start again
};
constexpr uint8_t kButtons = kUse | kNoclip;

// Doom's six keys; a lock opens with the card or the skull of its colour.
enum KeyBits : uint8_t {
  kBlueCard = 1,
  kYellowCard = 2,
  kRedCard = 4,
  kBlueSkull = 8,
  kYellowSkull = 16,
  kRedSkull = 32,
  kAllKeys = 63,
};

struct Player {
  Vec2 pos;
  double angle = 0;      // degrees, counter-clockwise from east
  double z = 0;          // feet
  double momz = 0;       // vertical speed, units per tic
  Vec2 momentum{0, 0};   // units per tic
  double view_offset = 0;  // squat after a step up, recovering to 0
  uint8_t keys = 0;      // KeyBits
  bool noclip = false;
  bool use_held = false;   // use was down last tic
  bool dead = false;       // its view sinks; use starts the level again (World::reborn)
  int frozen = 0;          // tics left without control (after a teleport, as Doom's)
  play::Inventory inventory;  // health, armor, ammo, weapons, powers (Doom's player_t)
  double view_z() const { return z + kViewHeight + view_offset; }
};

// What happened during a tic, for messages and tests.
struct Event {
  enum class Kind : uint8_t { kKey, kPickup, kLocked, kSecret, kTeleport, kSwitch, kExit, kCheat };
  Kind kind;
  std::string message;  // Doom's words where Doom has them; empty when nothing is said
};

enum class Exit : uint8_t { kNone, kNormal, kSecret };

// Walls listed by 128-unit cells (Doom's blockmap): the collision queries. Its size
// grows with the walls, not the level's area: a huge sparse level gets bigger cells.
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
  // Clamped before the cast: a position far outside the level maps to the border.
  int cell_x(double x) const { return int(std::clamp(std::floor((x - origin_.x) / cell_), -1.0, double(cols_))); }
  int cell_y(double y) const { return int(std::clamp(std::floor((y - origin_.y) / cell_), -1.0, double(rows_))); }
  double cell_ = 128;  // Doom's 128 units, doubled until the cells number about the walls
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

  // Advances the player and the level by one tic; events() tells what happened.
  void tick(Player& player, const TicCommand& cmd);
  const std::vector<Event>& events() const { return events_; }
  // The sounds the tic started, in order.
  const std::vector<SoundEvent>& sounds() const { return sounds_; }
  // Set once the player takes an exit; the level keeps running.
  Exit exit() const { return exit_; }
  // Set once a dead player presses use: the level is to start again (Doom's PST_REBORN).
  bool reborn() const { return reborn_; }
  int secrets_found() const { return secrets_found_; }
  int secrets_total() const { return secrets_total_; }
  const Movers& movers() const { return movers_; }
  uint64_t level_time() const { return level_time_; }
  // Where Doom's play stream of random numbers stands (its P_Random index).
  uint8_t random_index() const { return random_.play_index(); }
  // Starts what a line's special does to sectors, as if its trigger fired, with no
  // lock, player or side involved (tests and tools set levels moving so). True if
  // anything started; teleporters, exits and unknown specials do nothing.
  bool trigger(uint32_t wall);

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
  // Movement and collision (sim.cpp)
  void move(Player& p);
  bool step(Player& p, Vec2 delta);
  void fall(Player& p);
  bool fits_after_move(Player& p, int sector);
  std::vector<uint32_t> walls_near(const geom::BBox& box) const;
  std::vector<int> sectors_under(Vec2 pos) const;

  // Lines, things and sectors the player acts on (lines.cpp)
  void use_lines(Player& p);
  void use_line(Player& p, uint32_t wall);
  void cross_lines(Player& p, Vec2 from);
  void cross_line(Player& p, uint32_t wall, int side);
  bool unlocked(const Player& p, Lock lock, bool door);
  void flip_switch(uint32_t wall, bool repeat);
  void clear_special(uint32_t wall);
  bool teleport(Player& p, uint32_t wall);
  void pick_up(Player& p);
  void dead_tic(Player& p, const TicCommand& cmd);
  void player_tic(Player& p, const TicCommand& cmd);
  void in_special_sector(Player& p);  // secrets and damaging floors (Doom's P_PlayerInSpecialSector)
  void hurt(Player& p, int amount);
  void tick_buttons();
  void say(Event::Kind kind, std::string message = {});

  const level::Level& level_;
  Blockmap blockmap_;
  level::State state_;
  // Doom's order at a level's start: the things spawn, then the sector specials;
  // both draw from the play stream.
  play::Random random_;
  play::ThingClocks things_;  // what the things show
  Movers movers_;
  std::vector<std::vector<uint32_t>> pieces_;  // per wall: every wall of its LINEDEF (or statement)
  std::vector<int> switch_partner_;            // per texture: its switch pair, or kNone
  struct Button {
    uint32_t wall;
    int part, texture, tics;
  };
  std::vector<Button> buttons_;  // repeatable switches flipping back
  std::vector<Event> events_;
  std::vector<SoundEvent> sounds_;
  Exit exit_ = Exit::kNone;
  bool teleported_ = false;  // during a move
  bool reborn_ = false;
  double player_floor_ = 0;  // the floor the player last stood on or over (Doom's floorz)
  int secrets_found_ = 0, secrets_total_ = 0;
  uint64_t level_time_ = 0;  // tics played (Doom's leveltime)
  int skill_;
  std::vector<play::ThingType> pickup_types_;  // per thing: its type if the player can pick it up, else kCount
  std::vector<uint32_t> scrolling_;  // walls of Doom's special 48
  void scroll_walls();
};

}  // namespace p3d::sim
