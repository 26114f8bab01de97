#include <gtest/gtest.h>

#include <cmath>

#include "engine/bsp/build.h"
#include "engine/bsp/check.h"
#include "engine/level/io.h"
#include "engine/map/generate.h"
#include "tests/support/support.h"

namespace p3d::bsp {
namespace {

const Strategy kAll[] = {Strategy::kFirst, Strategy::kRandom, Strategy::kFreeSplit, Strategy::kGreedy};

std::string describe(Strategy s, uint64_t seed) { return std::string(strategy_name(s)) + " seed " + std::to_string(seed); }

void expect_sound(const level::Level& level, const std::string& what) {
  const auto problems = check_invariants(level);
  EXPECT_TRUE(problems.empty()) << what << ": " << (problems.empty() ? "" : problems.front());
  EXPECT_EQ(level.leaves.size(), level.nodes.size() + 1) << what;
  EXPECT_GE(level.fragments.size(), level.walls.size()) << what;
}

// Point location through the BSP agrees with crossing parity inside the (closed)
// sectors; outside them, Doom's rule gives a point its leaf's sector.
void expect_point_location(const level::Level& level, uint64_t seed, const std::string& what) {
  Rng rng(seed);
  int located = 0;
  for (int i = 0; i < 400; ++i) {
    const geom::Vec2 p{rng.uniform(level.bounds.min.x - 50, level.bounds.max.x + 50),
                       rng.uniform(level.bounds.min.y - 50, level.bounds.max.y + 50)};
    const int expected = level::sector_at_brute_force(level, p);
    const int leaf_sector = level.leaves[size_t(level.leaf_at(p))].sector;
    EXPECT_EQ(level.sector_at(p), leaf_sector) << what;
    if (expected == level::kNone) continue;
    EXPECT_EQ(level.sector_at(p), expected) << what << " at (" << p.x << ", " << p.y << ")";
    ++located;
  }
  EXPECT_GT(located, 0) << what;
}

TEST(Build, InvariantsOnRandomSoupsForEveryStrategy) {
  for (uint64_t seed : {1, 2, 3})
    for (Strategy s : kAll) {
      const map::Source src = test::random_soup(400, seed);
      const level::Level level = test::compile(src, s, seed);
      expect_sound(level, "soup " + describe(s, seed));
      expect_point_location(level, seed, "soup " + describe(s, seed));
    }
}

TEST(Build, InvariantsOnRandomRoomsForEveryStrategy) {
  for (uint64_t seed : {1, 2, 3})
    for (Strategy s : kAll) {
      const map::Source src = test::random_rooms(400, seed);
      const level::Level level = test::compile(src, s, seed);
      expect_sound(level, "rooms " + describe(s, seed));
      expect_point_location(level, seed + 100, "rooms " + describe(s, seed));
    }
}

// Long, nearly parallel segments: splitter lines meet them at grazing angles and
// close to their ends, where rounding would lose or duplicate pieces.
map::Source needle_soup(int count, uint64_t seed) {
  map::Source src = test::random_soup(1, 1);
  src.walls.clear();
  src.vertices.clear();
  Rng rng(seed);
  std::vector<std::pair<geom::IPoint, geom::IPoint>> placed;
  for (int attempt = 0; int(placed.size()) < count && attempt < 200000; ++attempt) {
    const double angle = rng.below(3) * 1e-4 + (rng.below(2) ? M_PI / 2 : 0);
    const double length = rng.uniform(50, 1500);
    geom::IPoint a, b;
    geom::to_fixed(rng.uniform(-3000, 3000), a.x);
    geom::to_fixed(rng.uniform(-3000, 3000), a.y);
    geom::to_fixed(a.x / geom::kFixedOne + length * std::cos(angle), b.x);
    geom::to_fixed(a.y / geom::kFixedOne + length * std::sin(angle), b.y);
    if (a == b) continue;
    bool clear = true;
    for (const auto& [p, q] : placed)
      if (geom::segment_contact(a, b, p, q) != geom::SegmentContact::kNone) clear = false;
    if (!clear) continue;
    placed.push_back({a, b});
    const int v = int(src.vertices.size());
    src.vertices.push_back({a});
    src.vertices.push_back({b});
    map::Wall w;
    w.v1 = v, w.v2 = v + 1, w.segment = true;
    w.front.middle = w.back.middle = 0;
    src.walls.push_back(w);
  }
  return src;
}

TEST(Build, NearDegenerateGeometryStaysExact) {
  for (uint64_t seed : {11, 12})
    for (Strategy s : kAll) {
      const level::Level level = test::compile(needle_soup(150, seed), s, seed);
      expect_sound(level, "needles " + describe(s, seed));
      for (const level::Fragment& f : level.fragments) EXPECT_LT(f.t0, f.t1);
    }
}

TEST(Build, CollinearWallsShareTheNodeOfTheirLine) {
  // A dashed line of 20 segments on y = 0 (alternating directions) among slanted
  // segments: wherever the line y = 0 splits a cell, every dash in that cell lands
  // on that node, so no splitter line repeats below itself (check_invariants).
  map::Source src = test::random_soup(1, 1);
  src.walls.clear();
  src.vertices.clear();
  auto add = [&](double ax, double ay, double bx, double by) {
    const int v = int(src.vertices.size());
    src.vertices.push_back({{int64_t(ax * 256), int64_t(ay * 256)}});
    src.vertices.push_back({{int64_t(bx * 256), int64_t(by * 256)}});
    map::Wall w;
    w.v1 = v, w.v2 = v + 1, w.segment = true;
    w.front.middle = w.back.middle = 0;
    src.walls.push_back(w);
  };
  for (int i = 0; i < 20; ++i) {
    if (i % 2) add(i * 20, 0, i * 20 + 10, 0);
    else add(i * 20 + 10, 0, i * 20, 0);
  }
  for (int i = 0; i < 10; ++i) add(i * 37 + 3, 5, i * 37 + 20, 50 + i);
  for (int i = 0; i < 10; ++i) add(i * 41 + 1, -7, i * 41 + 30, -60 - i);
  for (Strategy s : kAll)
    for (uint64_t seed : {1, 2, 3}) {
      const level::Level level = test::compile(src, s, seed);
      expect_sound(level, describe(s, seed));
    }
  // The first strategy takes dash 0 first: one node holds all twenty.
  const level::Level first = test::compile(src, Strategy::kFirst, 1);
  EXPECT_EQ(first.nodes[0].fragment_count, 20u);
}

TEST(Build, CheckerCatchesARepeatedSplitterLine) {
  level::Level level = test::compile(test::random_soup(50, 3));
  ASSERT_TRUE(check_invariants(level).empty());
  int32_t child = level.nodes[0].child[0];
  ASSERT_FALSE(level::is_leaf(child));
  level.nodes[child].splitter = level.nodes[0].splitter;  // a descendant reusing the root's line
  const auto problems = check_invariants(level);
  ASSERT_FALSE(problems.empty());
}

TEST(Build, SameSeedSameBytes) {
  const map::Source src = test::random_rooms(500, 4);
  for (Strategy s : kAll) {
    const auto a = level::encode(test::compile(src, s, 77));
    const auto b = level::encode(test::compile(src, s, 77));
    EXPECT_EQ(a, b) << strategy_name(s);
  }
  EXPECT_NE(level::encode(test::compile(src, Strategy::kRandom, 1)),
            level::encode(test::compile(src, Strategy::kRandom, 2)));
}

TEST(Build, StatsAndTheRandomBound) {
  const map::Source src = test::random_soup(1000, 8);
  for (Strategy s : kAll) {
    Stats stats;
    Options o;
    o.strategy = s;
    const level::Level level = build(src, o, &stats);
    EXPECT_EQ(stats.walls, 1000u);
    EXPECT_EQ(stats.fragments, level.fragments.size());
    EXPECT_EQ(stats.splits, stats.fragments - stats.walls);
    EXPECT_EQ(stats.leaves, stats.nodes + 1);
    EXPECT_GE(stats.max_depth, std::log2(double(stats.leaves)));
    EXPECT_GT(stats.shortest_fragment, 0);
    EXPECT_LT(double(stats.fragments), stats.random_bound()) << strategy_name(s);
  }
}

TEST(Build, FreeSplitsCutLessThanRandomAlone) {
  // Walls of a grid of rooms run along shared lines: free splits abound.
  for (uint64_t seed : {1, 2, 3}) {
    const map::Source src = test::random_rooms(800, seed);
    Stats random_stats, free_stats;
    Options o;
    o.seed = seed;
    o.strategy = Strategy::kRandom;
    build(src, o, &random_stats);
    o.strategy = Strategy::kFreeSplit;
    build(src, o, &free_stats);
    EXPECT_GT(free_stats.free_splits, 0u);
    EXPECT_LT(free_stats.fragments, random_stats.fragments) << "seed " << seed;
  }
}

map::Source shape(const std::string& kind, size_t walls, uint64_t seed = 3) {
  map::GenerateOptions o;
  o.walls = walls;
  o.seed = seed;
  o.textures = map::builtin_textures();
  return map::generate_shape(kind, o);
}

// mapgen's shapes on the 1/256 grid: nearly convex rooms (every wall's line peels a
// few walls off: before free splitters, a chain 153 deep for the circle of 4,000 walls,
// 506 for the ellipse, 411 for the spiral, 1,988 for the rings' arcs of walls between
// two sectors), stars, fans, combs. Sound trees, and shallow.
TEST(Build, HostileShapesStaySoundAndShallow) {
  for (const std::string& kind : map::shape_kinds()) {
    Stats stats;
    const level::Level level = build(shape(kind, 4000), Options{}, &stats);
    expect_sound(level, kind);
    expect_point_location(level, 5, kind);
    EXPECT_LE(stats.max_depth, 96u) << kind;  // log2(4000) = 12; the chains were 150 to 2,000 deep
    EXPECT_LE(stats.mean_depth, 48.0) << kind;
    if (kind == "circle" || kind == "ellipse" || kind == "spiral" || kind == "rings") {
      EXPECT_GT(stats.free_lines, 0u) << kind;
    }
  }
}

// Free splitters' lines survive the file, and the same input gives the same bytes.
TEST(Build, FreeLinesRoundTripAndRepeat) {
  const map::Source src = shape("ellipse", 3000);
  const level::Level level = test::compile(src);
  ASSERT_FALSE(level.free_lines.empty());
  const std::vector<uint8_t> bytes = level::encode(level);
  EXPECT_EQ(bytes, level::encode(test::compile(src)));
  const level::Level back = level::decode(bytes, "ellipse");
  ASSERT_EQ(back.free_lines.size(), level.free_lines.size());
  for (size_t i = 0; i < back.free_lines.size(); ++i) {
    EXPECT_EQ(back.free_lines[i].p1, level.free_lines[i].p1);
    EXPECT_EQ(back.free_lines[i].p2, level.free_lines[i].p2);
  }
  EXPECT_TRUE(check_invariants(back).empty());
}

TEST(Build, PlayerOutsideEverySectorIsAnError) {
  map::Source src = test::random_rooms(200, 1);
  src.player.pos = {-5000, -5000};
  src.player.loc = {"x.map", 42};
  try {
    test::compile(src);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "x.map:42: player start is outside every sector");
  }
}

}  // namespace
}  // namespace p3d::bsp
