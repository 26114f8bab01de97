// The simulation: collision as a property over thousands of random walks, demos
// (determinism, the file format), and the movement rules.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/bsp/load.h"
#include "engine/map/source.h"
#include "engine/sim/demo.h"
#include "tests/support/support.h"

namespace p3d::sim {
namespace {

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + ab * t));
}

// Whether the straight path p -> q crosses the segment a-b.
bool path_crosses(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  auto side = [](Vec2 o, Vec2 d, Vec2 x) { return geom::cross(d, x - o); };
  const double s1 = side(a, b - a, p), s2 = side(a, b - a, q), s3 = side(p, q - p, a), s4 = side(p, q - p, b);
  return ((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0));
}

TicCommand random_command(Rng& rng) {
  TicCommand c;
  const int mode = int(rng.below(10));
  c.forward = int8_t(mode < 6 ? 50 : int(rng.below(101)) - 50);
  c.side = int8_t(rng.below(3) == 0 ? int(rng.below(81)) - 40 : 0);
  c.turn = int16_t(int(rng.below(4001)) - 2000);
  return c;
}

struct WalkStats {
  size_t tics = 0, moved = 0, climbed = 0, max_speed_tics = 0;
};

// Random walks from random starts: after every tic the player is never across a
// one-sided wall or a plain segment from where it was, never inside a segment,
// never in the void, and never a step of more than 24 units above the last tic.
void random_walks(const level::Level& level, uint64_t seed, int walks, int tics, WalkStats& stats, const std::string& what) {
  World world(level);
  Rng rng(seed);
  for (int w = 0; w < walks; ++w) {
    Player p = world.spawn();
    if (w > 0) {  // elsewhere: a random spot inside a sector, at least a radius from every wall
      for (int attempt = 0; attempt < 1000; ++attempt) {
        const Vec2 q{rng.uniform(level.bounds.min.x, level.bounds.max.x), rng.uniform(level.bounds.min.y, level.bounds.max.y)};
        if (level.sector_at(q) == level::kNone) continue;
        bool clear = true;
        for (const level::Wall& wall : level.walls) clear = clear && distance_to_segment(q, wall.a, wall.b) >= kPlayerRadius;
        if (!clear) continue;
        const World::Heights h = world.heights_at(q);
        if (h.ceiling - h.floor < kPlayerHeight) continue;
        p = world.spawn_at(q, rng.uniform(0, 360));
        break;
      }
    }
    for (int t = 0; t < tics; ++t) {
      const Player before = p;
      world.tick(p, random_command(rng));
      ++stats.tics;
      stats.moved += p.pos != before.pos;
      stats.climbed += p.z > before.z;
      stats.max_speed_tics += glm::length(p.momentum) > 10;
      ASSERT_LE(p.z - before.z, kMaxStep) << what << " walk " << w << " tic " << t << ": climbed too high";
      ASSERT_NE(level.sector_at(p.pos), level::kNone) << what << " walk " << w << " tic " << t << ": in the void";
      for (const level::Wall& wall : level.walls) {
        if (wall.two_sided()) continue;
        ASSERT_FALSE(path_crosses(before.pos, p.pos, wall.a, wall.b))
            << what << " walk " << w << " tic " << t << ": through the wall at (" << wall.a.x << "," << wall.a.y << ")";
        if (wall.segment()) {
          ASSERT_GE(distance_to_segment(p.pos, wall.a, wall.b), kPlayerRadius - 1e-3)
              << what << " walk " << w << " tic " << t << ": inside a segment";
        }
      }
      const World::Heights h = world.heights_at(p.pos);
      ASSERT_GE(h.ceiling - p.z, kPlayerHeight - 1e-9) << what << " walk " << w << " tic " << t << ": head in the ceiling";
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
  size_t walks = 0;
  for (const Case& c : cases) {
    WalkStats s;
    random_walks(c.level, std::hash<std::string>()(c.name), 250, 120, s, c.name);
    walks += 250;
    std::printf("[ stats    ] %s: %zu tics, %zu moved, %zu climbed, %zu at full speed\n", c.name.c_str(), s.tics, s.moved,
                s.climbed, s.max_speed_tics);
    EXPECT_GT(s.moved, s.tics / 2) << c.name << ": the walks should mostly move";
    if (c.name.find("stairs") != std::string::npos || c.name == "rooms") {
      EXPECT_GT(s.climbed, 0u) << c.name;
    }
  }
  EXPECT_GE(walks, 1000u);
}

// Freedoom maps with every door, lift, floor and crusher set moving at the start, and
// random walks that press use: the player never passes a wall, never lands in the
// void, never has a ceiling in its head, and climbs more than a step only riding a
// floor that rose. The sanitizer build walks a sample.
TEST(Collision, FreedoomWalksWithSectorsMoving) {
  struct Stats {
    size_t tics = 0, moving = 0, rode = 0, teleports = 0;
  } stats;
  int maps = 0;
  for (const auto& [iwad, names] : {std::pair{"freedoom1.wad", std::vector<std::string>{"E1M1", "E1M5", "E2M2", "E3M3", "E4M4"}},
                                    std::pair{"freedoom2.wad", std::vector<std::string>{"MAP01", "MAP05", "MAP09", "MAP13",
                                                                                        "MAP18", "MAP22", "MAP27", "MAP31"}}}) {
    const wad::Stack wads = bsp::read_wads({test::freedoom_path(iwad)});
    for (size_t k = 0; k < names.size(); ++k) {
#ifdef P3D_SANITIZE
      if (k % 3 != 0) continue;
#endif
      const std::string what = std::string(iwad) + ":" + names[k];
      const level::Level level = bsp::build_wad_map(wads, names[k], {}, nullptr);
      World world(level);
      int started = 0;
      Rng rng(std::hash<std::string>()(what));
      Player p = world.spawn();
      for (int t = 0; t < 3000; ++t) {
        if (t % 400 == 0)  // everything again, as the doors have closed
          for (uint32_t w = 0; w < level.walls.size(); ++w) started += world.trigger(w);
        TicCommand cmd = random_command(rng);
        if (rng.below(10) == 0) cmd.buttons = kUse;
        const Player before = p;
        const double floor_then = world.heights_at(before.pos).floor;
        world.tick(p, cmd);
        ++stats.tics;
        stats.moving += world.movers().active() > 0;
        bool teleported = false;
        for (const Event& e : world.events()) teleported = teleported || e.kind == Event::Kind::kTeleport;
        stats.teleports += teleported;
        const World::Heights h = world.heights_at(p.pos);
        if (!teleported && p.z > before.z + kMaxStep) {  // only a floor rising under the player lifts it more
          ++stats.rode;
          const double lift = world.heights_at(before.pos).floor - floor_then;
          ASSERT_LE(p.z - before.z, kMaxStep + lift) << what << " tic " << t << ": climbed too high";
        }
        ASSERT_NE(level.sector_at(p.pos), level::kNone) << what << " tic " << t << ": in the void";
        ASSERT_GE(h.ceiling - p.z, kPlayerHeight - 1e-9) << what << " tic " << t << ": head in the ceiling";
        if (teleported) continue;
        for (const level::Wall& wall : level.walls) {
          if (!wall.two_sided()) {
            ASSERT_FALSE(path_crosses(before.pos, p.pos, wall.a, wall.b))
                << what << " tic " << t << ": through the wall at (" << wall.a.x << "," << wall.a.y << ")";
          }
        }
      }
      EXPECT_GT(started, 0) << what;
      ++maps;
    }
  }
  std::printf("[ stats    ] %d maps, %zu tics, %zu with sectors moving, %zu climbs riding a floor, %zu teleports\n", maps,
              stats.tics, stats.moving, stats.rode, stats.teleports);
  EXPECT_GT(stats.moving, stats.tics / 2);
}

// A 4-wall room 2 million units across: the blockmap grows with the walls, not the area
// (Doom's 128-unit cells would need 270 million of them), and a position far outside
// any level is no trouble.
TEST(Collision, AHugeSparseLevelNeedsASmallBlockmap) {
  const std::string text =
      "texture brick textures/brick.png\nsector room floor=0 ceiling=128 floor_tex=brick ceiling_tex=brick\n"
      "vertex a -1048576 -1048576\nvertex b -1048576 1048576\nvertex c 1048576 1048576\nvertex d 1048576 -1048576\n"
      "wall a b front=room middle=brick\nwall b c front=room middle=brick\nwall c d front=room middle=brick\n"
      "wall d a front=room middle=brick\nplayer 0 0 0\n";
  const level::Level level = test::compile(map::parse_map(text, test::source_dir() / "maps/huge.map"));
  World world(level);
  Player p = world.spawn();
  for (int t = 0; t < 35; ++t) world.tick(p, {50, 0, 0, 0});
  EXPECT_GT(p.pos.x, 100);
  EXPECT_EQ(world.heights_at({1e12, -1e12}).floor, 0) << "far outside: the border cells, the default heights";
}

TEST(Collision, HighSpeedIntoAWallStops) {
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"));
  World world(level);
  for (double angle = 0; angle < 360; angle += 7.5) {
    Player p = world.spawn();
    p.momentum = Vec2(std::cos(angle * M_PI / 180), std::sin(angle * M_PI / 180)) * 1000.0;  // absurd speed
    for (int t = 0; t < 20; ++t) world.tick(p, {});
    EXPECT_NE(level.sector_at(p.pos), level::kNone) << angle;
    for (const level::Wall& w : level.walls) ASSERT_GE(distance_to_segment(p.pos, w.a, w.b), kPlayerRadius - 1e-3) << angle;
  }
}

TEST(Movement, StepsUpTheStairsButNotOntoTheWindowSill) {
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  World world(level);
  Player p = world.spawn_at({460, 192}, 0);  // in the hall, facing the six 16-unit steps
  ASSERT_EQ(p.z, 0);
  double lowest_eye = kViewHeight;  // above the feet
  for (int t = 0; t < 60; ++t) {
    world.tick(p, {50, 0, 0});
    lowest_eye = std::min(lowest_eye, p.view_z() - p.z);
  }
  EXPECT_EQ(p.z, 96) << "at the top of the stairs, on the gallery floor";
  EXPECT_LT(lowest_eye, kViewHeight) << "the eye dips on each step and recovers";
  for (int t = 0; t < 20; ++t) world.tick(p, {});
  EXPECT_NEAR(p.view_z(), 96 + kViewHeight, 0.1);

  Player q = world.spawn_at({256, 300}, 90);  // facing the window: its sill is 48 up
  for (int t = 0; t < 60; ++t) world.tick(q, {50, 0, 0});
  EXPECT_EQ(q.z, 0);
  EXPECT_LT(q.pos.y, 384 - kPlayerRadius + 1e-3);
}

TEST(Movement, TurningAFullCircleIsExact) {
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/labyrinth.grid"));
  World world(level);
  Player p = world.spawn();
  // Turning 65536 units is a full turn.
  for (int t = 0; t < 32; ++t) world.tick(p, {0, 0, 2048});
  EXPECT_NEAR(p.angle, world.spawn().angle, 1e-9);
}

TEST(Movement, RunningReachesDoomsTerminalSpeed) {
  // Across the open yard: thrust T = 50/32 a tic against friction f = 0.90625 gives
  // T f (1 - f^n) / (1 - f) after n tics, approaching about 15.1 units a tic.
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  World world(level);
  Player p = world.spawn_at({40, 500}, 0);
  const double thrust = 50.0 / 32, f = 0xE800 / 65536.0;
  for (int t = 0; t < 45; ++t) world.tick(p, {50, 0, 0});
  EXPECT_NEAR(glm::length(p.momentum), thrust * f * (1 - std::pow(f, 45)) / (1 - f), 1e-9);
  EXPECT_NEAR(thrust * f / (1 - f), 15.1, 0.01);
  EXPECT_NEAR(p.pos.y, 500, 1e-9);
  for (int t = 0; t < 60; ++t) world.tick(p, {});
  EXPECT_EQ(p.momentum, Vec2(0, 0)) << "friction stops the player";
}

TEST(Demo, RecordingThenReplayingGivesTheSamePlayerAtEveryTic) {
  const level::Level level = test::compile(test::random_rooms(500, 6));
  World world(level);
  Rng rng(11);
  Demo demo{fingerprint(level), level.player_start, level.player_angle, level::kDefaultSkill, 0, {}};
  std::vector<Player> trail;
  Player p = world.spawn();
  for (int t = 0; t < 700; ++t) {
    demo.tics.push_back(random_command(rng));
    world.tick(p, demo.tics.back());
    trail.push_back(p);
  }
  const Demo back = decode_demo(encode_demo(demo), "d.demo");
  EXPECT_EQ(back.tics, demo.tics);
  Player q = world.spawn_at(back.start, back.angle);
  for (size_t t = 0; t < back.tics.size(); ++t) {
    world.tick(q, back.tics[t]);
    ASSERT_EQ(q.pos, trail[t].pos) << "tic " << t;
    ASSERT_EQ(q.angle, trail[t].angle) << "tic " << t;
    ASSERT_EQ(q.z, trail[t].z) << "tic " << t;
  }
}

TEST(Demo, DamagedFilesAreRejected) {
  Demo demo{42, {1, 2}, 90, 4, kBlueSkull, {{50, 0, 100, 0}, {-25, 24, -640, kUse}}};
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
  flipped[40] ^= 4;
  EXPECT_EQ(error(flipped), "x.demo: checksum mismatch (the demo is corrupted)");
  std::vector<uint8_t> cut(good.begin(), good.end() - 9);
  EXPECT_NE(error(cut).find("x.demo:"), std::string::npos);
  std::vector<uint8_t> version = good;
  version[8] = 7;
  EXPECT_EQ(error(version), "x.demo: demo version 7 is not supported (expected 3)");
  const Demo back = decode_demo(good, "x.demo");
  EXPECT_EQ(back.tics, demo.tics);
  EXPECT_EQ(back.skill, 4);
  EXPECT_EQ(back.keys, kBlueSkull);
  Demo bad_skill = demo;
  bad_skill.skill = 9;
  EXPECT_EQ(error(encode_demo(bad_skill)), "x.demo: demo skill 9 is not 1..5");
  Demo bad_button = demo;
  bad_button.tics[0].buttons = 0x80;
  EXPECT_EQ(error(encode_demo(bad_button)), "x.demo: unknown buttons in a tic");
}

TEST(Demo, FingerprintFollowsTheGeometry) {
  const level::Level a = test::compile(test::random_rooms(300, 1));
  level::Level b = a;
  EXPECT_EQ(fingerprint(a), fingerprint(b));
  b.sectors[3].floor += 8;
  EXPECT_NE(fingerprint(a), fingerprint(b));
}

}  // namespace
}  // namespace p3d::sim
