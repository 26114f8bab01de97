// Doom's play simulation: collision as properties over thousands of random walks (the
// player never passes a wall, never climbs more than a step, never has a ceiling in its
// head; monsters never end a tic in a wall or in another thing), Doom's movement
// rules, and demos (the file format, replays that repeat exactly). The checks measure
// the geometry themselves, never by asking the World.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <unordered_map>

#include "engine/bsp/load.h"
#include "engine/map/source.h"
#include "engine/play/demo.h"
#include "engine/play/world.h"
#include "engine/util/bytes.h"
#include "engine/util/error.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

using geom::Vec2;

constexpr double kRadius = 16, kHeight = 56, kStep = 24;
constexpr double kSlack = 1.0 / 1024;  // Doom's fixed point, against exact geometry

// How far Doom may let a box into a line: its side of a sloped line (P_PointOnLineSide)
// compares two cross products truncated to whole square units, so a point within
// 1 / length of the line may count as on either side.
double doom_slack(Vec2 a, Vec2 b) { return a.x == b.x || a.y == b.y ? kSlack : kSlack + 1 / glm::length(b - a); }

Vec2 pos_of(const Mobj& mo) { return {to_double(mo.x), to_double(mo.y)}; }
Fixed fixed_units(double units) { return Fixed(std::lround(units * kFracUnit)); }
Angle binary_angle(double degrees) { return Angle(uint64_t(std::llround(degrees / 360.0 * 4294967296.0))); }

// Our own levels play as the game plays them: on a Map made from the level, no boss's map.
std::unique_ptr<World> world_on(const level::Level& level) {
  GameOptions options;
  options.map = 0;
  return std::make_unique<World>(map_from_level(level), level, options, Random{});
}

// The player elsewhere, standing still.
void put_player(World& world, Vec2 at, double degrees) {
  world.place_player(fixed_units(at.x), fixed_units(at.y), binary_angle(degrees));
  Mobj& mo = *world.player().mo;
  mo.mom_x = mo.mom_y = mo.mom_z = 0;
}

// Whether the straight path p -> q crosses the segment a-b.
bool path_crosses(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  auto side = [](Vec2 o, Vec2 d, Vec2 x) { return geom::cross(d, x - o); };
  const double s1 = side(a, b - a, p), s2 = side(a, b - a, q), s3 = side(p, q - p, a), s4 = side(p, q - p, b);
  return ((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0));
}

// Whether the segment a-b meets the open square of half-size r around c: Doom's test of
// a thing's box against a line (the boxes overlap, and the box's corners lie on both
// sides of the line).
bool segment_meets_box(Vec2 a, Vec2 b, Vec2 c, double r) {
  if (std::max(a.x, b.x) <= c.x - r || std::min(a.x, b.x) >= c.x + r || std::max(a.y, b.y) <= c.y - r ||
      std::min(a.y, b.y) >= c.y + r)
    return false;
  bool left = false, right = false;
  for (const Vec2 corner : {c + Vec2(-r, -r), c + Vec2(-r, r), c + Vec2(r, -r), c + Vec2(r, r)}) {
    const double s = geom::cross(b - a, corner - a);
    left = left || s > 0;
    right = right || s < 0;
  }
  return left && right;
}

// The highest floor and lowest ceiling under a thing's box (Doom's tmfloorz and
// tmceilingz): the sector at its centre and both sides of each two-sided wall crossing it.
struct Heights {
  double floor, ceiling;
};
Heights heights_under(const level::Level& level, const level::State& state, Vec2 c, double r) {
  const level::SectorState& at = state.sectors[size_t(level.sector_at(c))];
  Heights h{at.floor, at.ceiling};
  for (const level::Wall& w : level.walls) {
    if (!w.two_sided() || !segment_meets_box(w.a, w.b, c, r - doom_slack(w.a, w.b))) continue;
    for (const level::Side& side : w.sides) {
      h.floor = std::max(h.floor, state.sectors[size_t(side.sector)].floor);
      h.ceiling = std::min(h.ceiling, state.sectors[size_t(side.sector)].ceiling);
    }
  }
  return h;
}

TicCmd random_command(Rng& rng) {
  TicCmd c;
  const int mode = int(rng.below(10));
  c.forward = int8_t(mode < 6 ? 50 : int(rng.below(101)) - 50);
  c.side = int8_t(rng.below(3) == 0 ? int(rng.below(81)) - 40 : 0);
  c.turn = int16_t(int(rng.below(4001)) - 2000);
  return c;
}

// ---- the player's collision ------------------------------------------------------

struct WalkStats {
  size_t tics = 0, moved = 0, climbed = 0, max_speed_tics = 0;
};

// Random walks from random starts: after every tic the player is never across a
// one-sided wall or a plain segment from where it was, its box never crosses one,
// it is never in the void, never a step of more than 24 units above the last tic, and
// the ceiling over its box leaves room for its height.
void random_walks(const level::Level& level, uint64_t seed, int walks, int tics, WalkStats& stats,
                  const std::string& what) {
  std::unique_ptr<World> world = world_on(level);
  const Mobj& mo = *world->player().mo;
  Rng rng(seed);
  for (int w = 0; w < walks; ++w) {
    if (w > 0) {  // elsewhere: a random spot whose box is clear of every wall, with room to stand
      for (int attempt = 0; attempt < 1000; ++attempt) {
        const Vec2 q{rng.uniform(level.bounds.min.x, level.bounds.max.x),
                     rng.uniform(level.bounds.min.y, level.bounds.max.y)};
        const int sector = level::sector_at_brute_force(level, q);  // inside a sector, not the void
        if (sector == level::kNone) continue;
        bool clear = true;
        for (const level::Wall& wall : level.walls) clear = clear && !segment_meets_box(wall.a, wall.b, q, kRadius + 1);
        const level::SectorState& s = world->state().sectors[size_t(sector)];
        if (!clear || s.ceiling - s.floor < kHeight) continue;
        put_player(*world, q, rng.uniform(0, 360));
        break;
      }
    }
    for (int t = 0; t < tics; ++t) {
      const Vec2 from = pos_of(mo);
      const double z_from = to_double(mo.z);
      world->tick(random_command(rng));
      const Vec2 to = pos_of(mo);
      const double z = to_double(mo.z);
      ++stats.tics;
      stats.moved += to != from;
      stats.climbed += z > z_from;
      stats.max_speed_tics += std::hypot(to_double(mo.mom_x), to_double(mo.mom_y)) > 10;
      const std::string where = what + " walk " + std::to_string(w) + " tic " + std::to_string(t);
      ASSERT_LE(z - z_from, kStep) << where << ": climbed too high";
      ASSERT_NE(level.sector_at(to), level::kNone) << where << ": in the void";
      for (const level::Wall& wall : level.walls) {
        if (wall.two_sided()) continue;
        ASSERT_FALSE(path_crosses(from, to, wall.a, wall.b))
            << where << ": through the wall at (" << wall.a.x << "," << wall.a.y << ")";
        ASSERT_FALSE(segment_meets_box(wall.a, wall.b, to, kRadius - doom_slack(wall.a, wall.b)))
            << where << ": the box crosses the wall at (" << wall.a.x << "," << wall.a.y << ")";
      }
      ASSERT_GE(heights_under(level, world->state(), to, kRadius).ceiling - z, kHeight)
          << where << ": head in the ceiling";
    }
  }
}

TEST(Collision, RandomWalksNeverPassWallsOrClimbTooHigh) {
  struct Case {
    std::string name;
    level::Level level;
  };
  std::vector<Case> cases;
  cases.push_back({"outpost (stairs)", test::compile(map::load_map(test::source_dir() / "maps/outpost.map"))});
  cases.push_back({"soup", test::compile(test::random_soup(400, 3))});
  cases.push_back({"dense soup", test::compile(test::random_soup(1500, 9))});
  cases.push_back({"rooms", test::compile(test::random_rooms(600, 4))});
  cases.push_back({"bunker (grid)", test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"))});
  const int walks_per_level = test::kSanitized ? 25 : 250;
  size_t walks = 0;
  for (const Case& c : cases) {
    WalkStats s;
    const uint64_t seed = std::hash<std::string>()(c.name);
    random_walks(c.level, seed, walks_per_level, 120, s, c.name);
    walks += size_t(walks_per_level);
    std::printf("[ stats    ] %s (seed %llu): %zu tics, %zu moved, %zu climbed, %zu at full speed\n", c.name.c_str(),
                static_cast<unsigned long long>(seed), s.tics, s.moved, s.climbed, s.max_speed_tics);
    EXPECT_GT(s.moved, s.tics / 2) << c.name << ": the walks should mostly move";
    EXPECT_GT(s.max_speed_tics, 0u) << c.name << ": running reaches full speed";
    if (c.name.find("stairs") != std::string::npos || c.name == "rooms") {
      EXPECT_GT(s.climbed, 0u) << c.name;
    }
  }
  EXPECT_GE(walks, test::kSanitized ? 125u : 1000u);
}

// ---- Freedoom maps, with everything moving ----------------------------------------

struct FreedoomMap {
  std::string iwad, name;
};


// A Freedoom map as the game plays it.
struct Freedoom {
  explicit Freedoom(const FreedoomMap& m)
      : wads(bsp::read_wads({test::freedoom_path(m.iwad)})),
        level(bsp::build_wad_map(wads, m.name, {}, nullptr)),
        world(map_from_wads(wads, m.name, level), level, game_options_for(wads, m.name, 3), Random{}) {}
  wad::Stack wads;
  level::Level level;
  World world;
};

bool teleports_or_exits(int special) {
  switch (special) {
    case 39: case 97: case 125: case 126:  // teleporters
    case 11: case 51: case 52: case 124:   // exits
      return true;
    default:
      return false;
  }
}
bool opens_a_door_behind(int special) {  // Doom's EV_VerticalDoor: the sector behind the line
  switch (special) {
    case 1: case 26: case 27: case 28: case 31: case 32: case 33: case 34: case 117: case 118:
      return true;
    default:
      return false;
  }
}

// Every line's special set going as if the player had walked over, used or shot it
// (teleporters and exits left out), with every key held. Returns the sectors then moving.
int trigger_everything(World& world) {
  Mobj* mo = world.player().mo;
  world.player().cards = 63;
  for (Line& line : world.map_.lines) {
    if (!line.special || teleports_or_exits(line.special)) continue;
    if (opens_a_door_behind(line.special) && line.side[1] < 0) continue;
    world.cross_special_line(line.index, 0, mo);
    if (line.special) world.use_special_line(mo, &line, 0);
    if (line.special) world.shoot_special_line(mo, &line);
  }
  return int(std::count_if(world.map().sectors.begin(), world.map().sectors.end(),
                           [](const Sector& s) { return s.special_data != nullptr; }));
}

// A mover crushing sector `s` (its ceiling may come down into what stands there).
bool crushing(const Sector& s) {
  const Thinker* t = s.special_data;
  if (!t || t->removed) return false;
  switch (t->kind) {
    case Thinker::Kind::kCeiling: return static_cast<const Ceiling*>(t)->crush;
    case Thinker::Kind::kFloor: return static_cast<const Floor*>(t)->crush;
    case Thinker::Kind::kPlat: return static_cast<const Plat*>(t)->crush;
    default: return false;
  }
}

// The level's sectors that a box at c touches: its centre's and both sides of each
// two-sided wall crossing it.
std::vector<int> sectors_under(const level::Level& level, Vec2 c, double r) {
  std::vector<int> out{level.sector_at(c)};
  for (const level::Wall& w : level.walls)
    if (w.two_sided() && segment_meets_box(w.a, w.b, c, r - doom_slack(w.a, w.b)))
      for (const level::Side& side : w.sides) out.push_back(side.sector);
  return out;
}

// Freedoom maps with every door, lift, floor and crusher set going every 400 tics, and
// random walks that press use, in god mode among the monsters: the player never passes
// a wall, never lands in the void, never has a ceiling in its head but under a crusher,
// and climbs more than a step only riding a floor that rose.
TEST(Collision, FreedoomWalksWithSectorsMoving) {
  struct Stats {
    size_t tics = 0, moving = 0, rode = 0, teleports = 0, crushed = 0;
  } stats;
  int maps = 0;
  std::vector<FreedoomMap> all;
  for (const char* name : {"E1M1", "E1M5", "E2M2", "E3M3", "E4M4"}) all.push_back({"freedoom1.wad", name});
  for (const char* name : {"MAP01", "MAP05", "MAP09", "MAP13", "MAP18", "MAP22", "MAP27", "MAP31"})
    all.push_back({"freedoom2.wad", name});
  for (size_t k = 0; k < all.size(); ++k) {
#ifdef P3D_SANITIZE
    if (k % 4 != 0) continue;  // a sample: E1M1, E4M4, MAP13, MAP31
#endif
    const std::string what = all[k].iwad + ":" + all[k].name;
    Freedoom f(all[k]);
    World& world = f.world;
    const level::Level& level = f.level;
    world.apply_cheats(kToggleGod);
    const Mobj& mo = *world.player().mo;
    int started = 0;
    const uint64_t seed = std::hash<std::string>()(what);
    Rng rng(seed);
    for (int t = 0; t < 3000; ++t) {
      if (t % 400 == 0) started += trigger_everything(world);  // everything again, as the doors have closed
      TicCmd cmd = random_command(rng);
      if (rng.below(10) == 0) cmd.buttons = kBtUse;
      const Vec2 from = pos_of(mo);
      const double z_from = to_double(mo.z);
      const std::vector<level::SectorState> sectors_then = world.state().sectors;
      world.tick(cmd);
      ASSERT_GT(mo.health, 0) << what << " tic " << t << ": god mode keeps the player alive";
      const Vec2 to = pos_of(mo);
      const double z = to_double(mo.z);
      ++stats.tics;
      bool moving = false;
      for (size_t s = 0; s < sectors_then.size(); ++s)
        moving = moving || sectors_then[s].floor != world.state().sectors[s].floor ||
                 sectors_then[s].ceiling != world.state().sectors[s].ceiling;
      stats.moving += moving;
      const bool teleported = mo.reaction_time == 18 || glm::length(to - from) > 64;
      stats.teleports += teleported;
      const std::string where = what + " (seed " + std::to_string(seed) + ") tic " + std::to_string(t);
      ASSERT_NE(level.sector_at(to), level::kNone) << where << ": in the void";
      if (teleported) continue;
      if (z > z_from + kStep) {  // only a floor rising under the player lifts it more
        ++stats.rode;
        double lift = 0;
        for (const Vec2 at : {from, to})
          for (int s : sectors_under(level, at, kRadius))
            lift = std::max(lift, world.state().sectors[size_t(s)].floor - sectors_then[size_t(s)].floor);
        ASSERT_LE(z - z_from, kStep + lift) << where << ": climbed too high";
      }
      bool crushed = false;
      for (int s : sectors_under(level, to, kRadius)) crushed = crushed || crushing(world.map().sectors[size_t(s)]);
      stats.crushed += crushed;
      if (!crushed) {
        ASSERT_GE(heights_under(level, world.state(), to, kRadius).ceiling - z, kHeight)
            << where << ": head in the ceiling";
      }
      for (const level::Wall& wall : level.walls) {
        if (wall.two_sided()) continue;
        ASSERT_FALSE(path_crosses(from, to, wall.a, wall.b))
            << where << ": through the wall at (" << wall.a.x << "," << wall.a.y << ")";
        ASSERT_FALSE(segment_meets_box(wall.a, wall.b, to, kRadius - doom_slack(wall.a, wall.b)))
            << where << ": the box crosses the wall at (" << wall.a.x << "," << wall.a.y << ")";
      }
    }
    EXPECT_GT(started, 0) << what;
    ++maps;
  }
  std::printf(
      "[ stats    ] %d maps, %zu tics, %zu with sectors moving, %zu climbs riding a floor, %zu teleports, "
      "%zu tics under a crusher\n",
      maps, stats.tics, stats.moving, stats.rode, stats.teleports, stats.crushed);
  EXPECT_GT(stats.moving, stats.tics / 3) << "doors open and close again between the triggers";
}

// A room as wide as Doom's fixed point allows (30000 units: Doom's coordinates end at
// 32767): the blockmap covers it and the player runs across it.
TEST(Collision, ARoomAsWideAsDoomAllows) {
  const std::string text =
      "texture brick textures/brick.png\nsector room floor=0 ceiling=128 floor_tex=brick ceiling_tex=brick\n"
      "vertex a -15000 -15000\nvertex b -15000 15000\nvertex c 15000 15000\nvertex d 15000 -15000\n"
      "wall a b front=room middle=brick\nwall b c front=room middle=brick\nwall c d front=room middle=brick\n"
      "wall d a front=room middle=brick\nplayer 0 0 0\n";
  const level::Level level = test::compile(map::parse_map(text, test::source_dir() / "maps/huge.map"));
  std::unique_ptr<World> world = world_on(level);
  const Blockmap& bm = world->map().blockmap;
  EXPECT_GE(int64_t(bm.width) * 128, 30000);
  EXPECT_GE(int64_t(bm.height) * 128, 30000);
  for (int t = 0; t < 35; ++t) world->tick({50, 0, 0, 0});
  EXPECT_GT(to_double(world->player().mo->x), 100);
  put_player(*world, {14900, -14900}, 0);  // into the far corner
  for (int t = 0; t < 35; ++t) world->tick({50, 0, 0, 0});
  EXPECT_LE(world->player().mo->x, to_fixed(15000 - 16)) << "stopped by the east wall";
  EXPECT_GT(world->player().mo->x, to_fixed(15000 - 17));
}

TEST(Collision, HighSpeedIntoAWallStops) {
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"));
  for (double angle = 0; angle < 360; angle += 7.5) {
    std::unique_ptr<World> world = world_on(level);
    Mobj& mo = *world->player().mo;
    mo.mom_x = fixed_units(std::cos(angle * M_PI / 180) * 1000);  // absurd speed: Doom clamps it to 30 a tic
    mo.mom_y = fixed_units(std::sin(angle * M_PI / 180) * 1000);
    for (int t = 0; t < 20; ++t) world->tick({});
    const Vec2 p = pos_of(mo);
    EXPECT_NE(level.sector_at(p), level::kNone) << angle;
    for (const level::Wall& w : level.walls) {
      if (w.two_sided()) continue;
      ASSERT_FALSE(segment_meets_box(w.a, w.b, p, kRadius - doom_slack(w.a, w.b))) << angle;
    }
  }
}

// ---- monsters --------------------------------------------------------------------

// Whether a thing's box at (x, y) would find `other` in P_CheckPosition: Doom looks for
// things only in the blockmap cells of the box widened by MAXRADIUS, by their centres,
// so a thing wider than that (a mancubus, a spider) can be overlapped from beyond.
bool within_reach(const Blockmap& bm, const Mobj& mover, const Mobj& other) {
  const int xl = (mover.x - mover.radius - bm.origin_x - kMaxRadius) >> kMapBlockShift;
  const int xh = (mover.x + mover.radius - bm.origin_x + kMaxRadius) >> kMapBlockShift;
  const int yl = (mover.y - mover.radius - bm.origin_y - kMaxRadius) >> kMapBlockShift;
  const int yh = (mover.y + mover.radius - bm.origin_y + kMaxRadius) >> kMapBlockShift;
  const int bx = (other.x - bm.origin_x) >> kMapBlockShift, by = (other.y - bm.origin_y) >> kMapBlockShift;
  return bx >= xl && bx <= xh && by >= yl && by <= yh;
}

bool boxes_overlap(const Mobj& a, const Mobj& b) {
  const int64_t reach = int64_t(a.radius) + b.radius;
  return std::abs(int64_t(a.x) - b.x) < reach && std::abs(int64_t(a.y) - b.y) < reach;
}

// What P_CheckPosition would refuse of a thing's box where it stands, by the lines'
// geometry: a one-sided line, a line blocking it (monsters: also the lines that block
// monsters), or a two-sided line whose opening is lower than the thing is tall (unless
// a mover works on either side: a crusher comes down on what it crushes).
std::string line_trouble(const World& world, const Mobj& mo) {
  const Vec2 c = pos_of(mo);
  for (const Line& line : world.map().lines) {
    const Vec2 a{to_double(line.v1->x), to_double(line.v1->y)}, b{to_double(line.v2->x), to_double(line.v2->y)};
    if (!segment_meets_box(a, b, c, to_double(mo.radius) - doom_slack(a, b))) continue;
    const std::string at = "line " + std::to_string(line.index) + " at (" + std::to_string(a.x) + "," +
                           std::to_string(a.y) + ")-(" + std::to_string(b.x) + "," + std::to_string(b.y) + ")";
    if (!line.back) return "one-sided " + at;
    if (line.flags & kMlBlocking) return "blocking " + at;
    if (!mo.player && (line.flags & kMlBlockMonsters)) return "monster-blocking " + at;
    if (line.front->special_data || line.back->special_data) continue;
    const Fixed top = std::min(line.front->ceiling_height, line.back->ceiling_height);
    const Fixed bottom = std::max(line.front->floor_height, line.back->floor_height);
    if (top - bottom < mo.height) return "too low an opening at " + at;
  }
  return "";
}

// Whether a one-sided line passes within `margin` of the thing's box.
bool beside_a_wall(const World& world, const Mobj& mo, double margin) {
  for (const Line& line : world.map().lines) {
    const Vec2 a{to_double(line.v1->x), to_double(line.v1->y)}, b{to_double(line.v2->x), to_double(line.v2->y)};
    if (!line.back && segment_meets_box(a, b, pos_of(mo), to_double(mo.radius) + margin)) return true;
  }
  return false;
}

struct Seen {
  Fixed x, y;
  bool solid;
};

// Every monster of a few Freedoom maps awake and after the player (who plays at random,
// in god mode): after every tic no solid thing that moved (but by a teleporter) has its
// box across a line it may not cross, and no two solid things whose boxes were apart
// overlap. (Doom leaves things overlapping that were placed so, and a thing wider than
// its blockmap search may be walked into: both are left out.)
TEST(Collision, AMonsterNeverEndsATicInsideAWallOrAnotherThing) {
  const uint64_t seed = 20240611;
  std::printf("[ seed     ] %llu\n", static_cast<unsigned long long>(seed));
  Rng rng(seed);
  std::vector<FreedoomMap> maps{{"freedoom1.wad", "E1M1"}};
  for (const char* name : {"MAP01", "MAP02", "MAP03", "MAP04", "MAP05"}) maps.push_back({"freedoom2.wad", name});
  if (test::kSanitized) maps.resize(2);  // a sample: E1M1 and MAP01
  struct {
    size_t tics = 0, monster_moves = 0, beside_walls = 0, close_pairs = 0, pairs_checked = 0, attacks = 0;
  } stats;
  for (const FreedoomMap& m : maps) {
    const std::string what = m.iwad + ":" + m.name;
    Freedoom f(m);
    World& world = f.world;
    world.apply_cheats(kToggleGod | kGiveAll);
    Mobj* player = world.player().mo;
    int awake = 0;
    for (const auto& t : world.thinkers_) {
      if (t->kind != Thinker::Kind::kMobj || t->removed) continue;
      Mobj* mo = static_cast<Mobj*>(t.get());
      if (!(mo->flags & kCountkill) || mo->health <= 0 || mo->info->see == StateId::kNull) continue;
      mo->target = player;
      world.set_mobj_state(mo, mo->info->see);
      ++awake;
    }
    ASSERT_GT(awake, 0) << what;
    std::unordered_map<const Mobj*, Seen> before;
    for (const Mobj* mo : world.things()) before[mo] = {mo->x, mo->y, bool(mo->flags & kSolid)};
    for (int t = 0; t < 400; ++t) {
      TicCmd cmd = random_command(rng);
      if (rng.below(8) == 0) cmd.buttons |= kBtAttack;
      if (rng.below(16) == 0) cmd.buttons |= kBtUse;
      world.tick(cmd);
      ++stats.tics;
      const std::string where = what + " tic " + std::to_string(t);
      const std::vector<const Mobj*> things = world.things();
      std::vector<const Mobj*> solid;
      std::unordered_map<const Mobj*, bool> jumped;
      for (const Mobj* mo : things) {
        if (!(mo->flags & kSolid) || (mo->flags & kNoclip)) continue;
        solid.push_back(mo);
        const auto then = before.find(mo);
        if (then == before.end() || (then->second.x == mo->x && then->second.y == mo->y)) continue;
        // A teleporter moves a thing without regard to lines (Doom's P_TeleportMove).
        jumped[mo] = approx_distance(mo->x - then->second.x, mo->y - then->second.y) > 64 * kFracUnit;
        if (jumped[mo]) continue;
        stats.monster_moves += mo != player;
        stats.beside_walls += mo != player && beside_a_wall(world, *mo, 2);
        const std::string trouble = line_trouble(world, *mo);
        ASSERT_EQ(trouble, "") << where << ": thing " << mo->id << " (type " << int(mo->type) << ") at ("
                               << to_double(mo->x) << "," << to_double(mo->y) << "), from ("
                               << to_double(then->second.x) << "," << to_double(then->second.y) << ")";
      }
      for (size_t i = 0; i < solid.size(); ++i)
        for (size_t j = i + 1; j < solid.size(); ++j) {
          const Mobj &a = *solid[i], &b = *solid[j];
          const auto ta = before.find(&a), tb = before.find(&b);
          if (ta == before.end() || tb == before.end() || !ta->second.solid || !tb->second.solid) continue;
          if (jumped[&a] || jumped[&b]) continue;  // a telefrag leaves the dying one where it stood
          const int64_t near = int64_t(a.radius) + b.radius + 4 * kFracUnit;
          stats.close_pairs += std::abs(int64_t(a.x) - b.x) < near && std::abs(int64_t(a.y) - b.y) < near;
          if (!boxes_overlap(a, b)) continue;
          ++stats.pairs_checked;
          const int64_t reach = int64_t(a.radius) + b.radius;
          const bool apart_before = std::abs(int64_t(ta->second.x) - tb->second.x) >= reach ||
                                    std::abs(int64_t(ta->second.y) - tb->second.y) >= reach;
          if (!apart_before) continue;
          const Blockmap& bm = world.map().blockmap;
          if (!within_reach(bm, a, b) || !within_reach(bm, b, a)) continue;  // beyond Doom's search
          ADD_FAILURE() << where << ": things " << a.id << " (type " << int(a.type) << ") and " << b.id << " (type "
                        << int(b.type) << ") overlap at (" << to_double(a.x) << "," << to_double(a.y) << ") and ("
                        << to_double(b.x) << "," << to_double(b.y) << ")";
          return;
        }
      before.clear();
      for (const Mobj* mo : things) before[mo] = {mo->x, mo->y, bool(mo->flags & kSolid)};
      for (const SoundEvent& s : world.sounds())
        stats.attacks += s.sound == Sound::kPistol || s.sound == Sound::kShotgn;
    }
  }
  std::printf(
      "[ stats    ] %zu tics, %zu monster moves checked (%zu within 2 units of a wall), %zu solid pairs within "
      "4 units, %zu overlapping, %zu shots heard\n",
      stats.tics, stats.monster_moves, stats.beside_walls, stats.close_pairs, stats.pairs_checked, stats.attacks);
  EXPECT_GT(stats.monster_moves, 1000u) << "the monsters came";
  EXPECT_GT(stats.beside_walls, 100u) << "along the walls";
  EXPECT_GT(stats.close_pairs, 100u) << "and against each other";
}

// ---- movement --------------------------------------------------------------------

TEST(Movement, StepsUpTheStairsButNotOntoTheWindowSill) {
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  std::unique_ptr<World> world = world_on(level);
  const Player& p = world->player();
  put_player(*world, {460, 192}, 0);  // in the hall, facing the six 16-unit steps
  ASSERT_EQ(p.mo->z, 0);
  Fixed lowest_eye = kViewHeight;  // above the feet, bob aside
  for (int t = 0; t < 60; ++t) {
    world->tick({50, 0, 0, 0});
    lowest_eye = std::min(lowest_eye, p.view_height);
  }
  EXPECT_EQ(p.mo->z, to_fixed(96)) << "at the top of the stairs, on the gallery floor";
  EXPECT_LT(lowest_eye, kViewHeight) << "the eye dips on each step and recovers";
  for (int t = 0; t < 60; ++t) world->tick({});
  EXPECT_EQ(p.view_height, kViewHeight);
  EXPECT_NEAR(to_double(p.view_z), 96 + 41, 0.1);

  std::unique_ptr<World> other = world_on(level);
  put_player(*other, {256, 300}, 90);  // facing the window: its sill is 48 up
  for (int t = 0; t < 60; ++t) other->tick({50, 0, 0, 0});
  EXPECT_EQ(other->player().mo->z, 0);
  EXPECT_LE(to_double(other->player().mo->y), 384 - kRadius);
  EXPECT_GT(to_double(other->player().mo->y), 384 - kRadius - 1) << "stopped at the wall below the sill";
}

// Doom draws its first frame after the first tic; a frame drawn before it sees from
// where that tic puts a player standing still (the eye above the floor, not at it),
// while view_z stays as Doom leaves it (0 for a new player).
TEST(Movement, TheEyeBeforeTheFirstTicIsWhereTheFirstTicPutsIt) {
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  std::unique_ptr<World> world = world_on(level);
  const Player& p = world->player();
  EXPECT_EQ(p.view_z, 0);
  EXPECT_EQ(world->eye_z(), p.mo->z + kViewHeight);
  const Fixed before = world->eye_z();
  world->tick({});
  EXPECT_EQ(p.view_z, before);
  EXPECT_EQ(world->eye_z(), p.view_z);
}

TEST(Movement, TurningAFullCircleIsExact) {
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/labyrinth.grid"));
  std::unique_ptr<World> world = world_on(level);
  const Angle start = world->player().mo->angle;
  // Turning 65536 units is a full turn.
  for (int t = 0; t < 32; ++t) world->tick({0, 0, 2048, 0});
  EXPECT_EQ(world->player().mo->angle, start);
  world->tick({0, 0, 16384, 0});
  EXPECT_EQ(world->player().mo->angle, start + kAngle90);
}

// Doom's thrust and friction in fixed point: forward 50 thrusts 50 * 2048 a tic along
// the facing, then the momentum is multiplied by 0xE800 (0.90625), approaching about 15.1
// units a tic; without a command it stops once under 1/16 of a unit.
TEST(Movement, RunningReachesDoomsTerminalSpeed) {
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  std::unique_ptr<World> world = world_on(level);
  const Mobj& mo = *world->player().mo;
  put_player(*world, {40, 500}, 0);  // across the open yard
  constexpr Fixed kFriction = 0xE800;
  Fixed expected_x = 0, expected_y = 0;
  for (int t = 0; t < 45; ++t) {
    world->tick({50, 0, 0, 0});
    expected_x = fixed_mul(expected_x + fixed_mul(50 * 2048, cosine(0)), kFriction);
    expected_y = fixed_mul(expected_y + fixed_mul(50 * 2048, sine(0)), kFriction);
    ASSERT_EQ(mo.mom_x, expected_x) << "tic " << t;
    ASSERT_EQ(mo.mom_y, expected_y) << "tic " << t;
  }
  const double thrust = 50.0 / 32, f = 0xE800 / 65536.0;
  EXPECT_NEAR(to_double(mo.mom_x), thrust * f * (1 - std::pow(f, 45)) / (1 - f), 0.01);
  EXPECT_NEAR(thrust * f / (1 - f), 15.1, 0.01);
  EXPECT_EQ(sine(0), 25) << "Doom's sine table starts half a step up";
  EXPECT_GT(mo.mom_y, 0) << "so facing east drifts north";
  EXPECT_LT(mo.y - to_fixed(500), kFracUnit);
  for (int t = 0; t < 60; ++t) world->tick({});
  EXPECT_EQ(mo.mom_x, 0) << "friction stops the player";
  EXPECT_EQ(mo.mom_y, 0);
}

// ---- demos -----------------------------------------------------------------------

struct Pose {
  Fixed x, y, z;
  Angle angle;
  friend bool operator==(const Pose&, const Pose&) = default;
};
Pose pose_of(const World& w) {
  const Mobj& mo = *w.player().mo;
  return {mo.x, mo.y, mo.z, mo.angle};
}

TEST(Demo, RecordingThenReplayingGivesTheSamePlayerAtEveryTic) {
  const level::Level level = test::compile(test::random_rooms(500, 6));
  Rng rng(11);
  Demo demo;
  demo.level_fingerprint = fingerprint(level);
  std::vector<Pose> trail;
  {
    std::unique_ptr<World> world = world_on(level);
    for (int t = 0; t < 700; ++t) {
      demo.tics.push_back({random_command(rng), 0});
      world->tick(demo.tics.back().cmd);
      trail.push_back(pose_of(*world));
    }
  }
  const Demo back = decode_demo(encode_demo(demo), "d.demo");
  EXPECT_EQ(back.tics, demo.tics);
  EXPECT_EQ(back.level_fingerprint, fingerprint(level));
  std::unique_ptr<World> world = world_on(level);
  std::set<std::pair<Fixed, Fixed>> places;
  for (size_t t = 0; t < back.tics.size(); ++t) {
    world->tick(back.tics[t].cmd);
    ASSERT_EQ(pose_of(*world), trail[t]) << "tic " << t;
    places.insert({trail[t].x, trail[t].y});
  }
  EXPECT_GT(places.size(), 300u) << "the walk went places";
}

TEST(Demo, DamagedFilesAreRejected) {
  Demo demo;
  demo.level_fingerprint = 42;
  demo.skill = 4;
  demo.custom_start = true;
  demo.start = {1, 2};
  demo.angle = 90;
  demo.keys = 1 << 3;  // the blue skull
  demo.tics = {{{50, 0, 100, 0}, 0}, {{-25, 24, -640, kBtUse}, kToggleNoclip}, {{0, 0, 0, kBtAttack}, kGiveAll}};
  const std::vector<uint8_t> good = encode_demo(demo);
  auto error = [](std::vector<uint8_t> bytes) {
    try {
      decode_demo(bytes, "x.demo");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error({}), "x.demo: not a demo (bad magic)");
  EXPECT_EQ(error(std::vector<uint8_t>(good.begin(), good.begin() + 20)), "x.demo: truncated demo");
  std::vector<uint8_t> flipped = good;
  flipped[40] ^= 4;  // in the start's angle
  EXPECT_EQ(error(flipped), "x.demo: checksum mismatch (the demo is corrupted)");
  std::vector<uint8_t> cut(good.begin(), good.end() - 9);
  EXPECT_NE(error(cut).find("x.demo:"), std::string::npos);
  std::vector<uint8_t> version = good;
  version[8] = 7;
  EXPECT_EQ(error(version), "x.demo: demo version 7 is not supported (expected 4)");
  version[8] = 3;
  EXPECT_EQ(error(version),
            "x.demo: demo version 3 was recorded before the game played by Doom's rules: record it again");
  const Demo back = decode_demo(good, "x.demo");
  EXPECT_EQ(back.tics, demo.tics);
  EXPECT_EQ(back.skill, 4);
  EXPECT_EQ(back.keys, 1 << 3);
  EXPECT_TRUE(back.custom_start);
  EXPECT_EQ(back.start, geom::Vec2(1, 2));
  EXPECT_EQ(back.angle, 90);
  Demo bad_skill = demo;
  bad_skill.skill = 9;
  EXPECT_EQ(error(encode_demo(bad_skill)), "x.demo: demo skill 9 is not 1..5");
  Demo bad_cheat = demo;
  bad_cheat.tics[0].cheats = 0x80;
  EXPECT_EQ(error(encode_demo(bad_cheat)), "x.demo: unknown cheats in a tic");
  Demo bad_keys = demo;
  bad_keys.keys = 0x40;
  EXPECT_EQ(error(encode_demo(bad_keys)), "x.demo: unknown keys at the demo's start");
  Demo far = demo;
  far.start = {40000, 0};
  EXPECT_EQ(error(encode_demo(far)), "x.demo: demo start is out of range");
}

TEST(Demo, FingerprintFollowsTheGeometry) {
  const level::Level a = test::compile(test::random_rooms(300, 1));
  level::Level b = a;
  EXPECT_EQ(fingerprint(a), fingerprint(b));
  b.sectors[3].floor += 8;
  EXPECT_NE(fingerprint(a), fingerprint(b));
  level::Level c = a;
  c.walls[5].special = 1;
  EXPECT_NE(fingerprint(a), fingerprint(c)) << "specials count too";
}

// Everything a tic leaves that play and drawing depend on, as bytes: every thing's
// fields, what the renderers are shown, the player and the random index.
std::vector<uint8_t> snapshot(const World& w) {
  ByteWriter out;
  out.u8(w.random().play_index());
  out.i32(w.level_time());
  for (const Mobj* m : w.things()) {
    out.u32(m->id), out.u32(uint32_t(m->type)), out.i32(m->x), out.i32(m->y), out.i32(m->z), out.u32(m->angle);
    out.i32(m->mom_x), out.i32(m->mom_y), out.i32(m->mom_z), out.u32(uint32_t(m->state)), out.i32(m->tics);
    out.i32(m->health), out.u32(m->flags), out.i32(m->move_dir), out.i32(m->move_count), out.i32(m->reaction_time);
    out.i32(m->threshold), out.u32(m->target ? m->target->id : 0), out.u32(m->tracer ? m->tracer->id : 0);
    out.i32(m->floor_z), out.i32(m->ceiling_z), out.i32(m->frame), out.u32(uint32_t(m->sprite));
  }
  for (const level::ShownThing& t : w.state().things) {
    out.f64(t.pos.x), out.f64(t.pos.y), out.f64(t.z), out.f64(t.angle);
    out.i32(t.frame), out.i32(t.sector), out.u8(t.flags), out.i32(t.placed);
  }
  for (const level::SectorState& s : w.state().sectors) {
    out.f64(s.floor), out.f64(s.ceiling), out.i32(s.light), out.i32(s.floor_texture), out.i32(s.ceiling_texture);
  }
  for (int32_t t : w.state().textures) out.i32(t);
  const Player& p = w.player();
  out.i32(p.view_z), out.i32(p.view_height), out.i32(p.bob), out.u8(uint8_t(p.state)), out.u8(p.cards);
  out.i32(p.inv.health), out.i32(p.inv.armor), out.i32(p.inv.armor_type);
  for (int a : p.inv.ammo) out.i32(a);
  out.u8(uint8_t(p.inv.ready)), out.u8(uint8_t(p.inv.pending)), out.i32(p.inv.damage_count), out.i32(p.inv.bonus_count);
  for (const Psprite& ps : p.psprites) out.u32(uint32_t(ps.state)), out.i32(ps.tics), out.i32(ps.sx), out.i32(ps.sy);
  out.i32(p.kill_count), out.i32(p.secret_count), out.i32(p.inv.items);
  for (const SoundEvent& s : w.sounds()) out.u8(uint8_t(s.sound)), out.u64(s.origin);
  return out.release();
}

// A Freedoom demo played twice from the start: after every tic the two worlds are the
// same to the byte (things, what is drawn, the player, the sounds).
TEST(Demo, AFreedoomDemoReplaysByteForByte) {
  const auto path = test::freedoom_path("freedoom2.wad");
  const wad::Stack wads = bsp::read_wads({path});
  const DoomDemo demo = decode_doom_demo(wads.find("DEMO1")->bytes, "DEMO1");
  const std::string map_name = demo.map_name(true);
  bsp::LevelSource source;
  source.wads = {path};
  source.map = map_name;
  const level::Level level = bsp::open_level(source).level;
  GameOptions options = game_options_for(wads, map_name, 3);
  options.skill = demo.skill;
  options.fast = demo.fast;
  options.respawn = demo.respawn;
  options.no_monsters = demo.no_monsters;
  std::vector<uint64_t> first;
  std::vector<uint8_t> last;
  // A sample under the sanitizers: the first 600 tics, snapshots of every one.
  const size_t tics = test::kSanitized ? std::min<size_t>(demo.tic_count(), 600) : demo.tic_count();
  for (int pass = 0; pass < 2; ++pass) {
    World world(map_from_wads(wads, map_name, level), level, options, Random{});
    for (size_t t = 0; t < tics; ++t) {
      const DoomTic d = demo.console_tic(t);
      world.tick(TicCmd{d.forward, d.side, d.turn, d.buttons});
      const std::vector<uint8_t> bytes = snapshot(world);
      const uint64_t hash = fnv1a64(bytes);
      if (pass == 0) {
        first.push_back(hash);
        if (t + 1 == tics) last = bytes;
        continue;
      }
      ASSERT_EQ(hash, first[t]) << "tic " << t;
      if (t + 1 == tics) {
        EXPECT_EQ(bytes, last);
      }
    }
  }
  EXPECT_GT(first.size(), test::kSanitized ? 500u : 1000u);
}

}  // namespace
}  // namespace p3d::play
