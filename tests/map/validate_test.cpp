// The crossing check against brute force, on the inputs that defeat a uniform grid:
// many walls meeting at one point (stars and fans), overlapping spokes, and walls
// crossing the spokes.
#include <gtest/gtest.h>

#include <map>

#include "engine/map/generate.h"
#include "engine/map/source.h"
#include "engine/util/rng.h"

namespace p3d::map {
namespace {

int add_vertex(Source& s, geom::IPoint p) {
  s.vertices.push_back({p});
  return int(s.vertices.size()) - 1;
}
void add_segment(Source& s, int a, int b) {
  Wall w;
  w.v1 = a, w.v2 = b, w.segment = true;
  s.walls.push_back(w);
}

std::vector<Contact> brute_force(const Source& s) {
  std::vector<Contact> out;
  for (uint32_t b = 0; b < s.walls.size(); ++b)
    for (uint32_t a = 0; a < b; ++a) {
      const auto kind = geom::segment_contact(s.point(s.walls[a].v1), s.point(s.walls[a].v2), s.point(s.walls[b].v1),
                                              s.point(s.walls[b].v2));
      if (kind == geom::SegmentContact::kCross || kind == geom::SegmentContact::kOverlap) out.push_back({a, b, kind});
    }
  return out;  // in (b, a) order
}

// A few hubs, each with up to 150 spokes in a handful of directions (so some spokes
// overlap), at either end of the spoke, plus stray walls that cross some of them.
Source hubs_and_strays(uint64_t seed) {
  Rng rng(seed);
  Source s;
  const auto coord = [&](int64_t range) { return (int64_t(rng.below(uint64_t(2 * range + 1))) - range) * int64_t(geom::kFixedOne); };
  for (int h = 0; h < 3; ++h) {
    const int hub = add_vertex(s, {coord(2000), coord(2000)});
    const int spokes = 40 + int(rng.below(110));
    for (int k = 0; k < spokes; ++k) {
      const int64_t dx = coord(6), dy = coord(6), len = 1 + int64_t(rng.below(40));
      if (dx == 0 && dy == 0) continue;
      const int tip = add_vertex(s, {s.point(hub).x + dx * len, s.point(hub).y + dy * len});
      rng.below(2) ? add_segment(s, hub, tip) : add_segment(s, tip, hub);
    }
  }
  for (int k = 0; k < 30; ++k)
    add_segment(s, add_vertex(s, {coord(2200), coord(2200)}), add_vertex(s, {coord(2200), coord(2200)}));
  return s;
}

TEST(Crossings, AgreeWithBruteForceAroundCrowdedPoints) {
  int crossings = 0, overlaps = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Source s = hubs_and_strays(seed);
    const std::vector<Contact> expected = brute_force(s);
    const std::vector<Contact> found = find_contacts(s, SIZE_MAX);
    ASSERT_EQ(found.size(), expected.size()) << "seed " << seed;
    for (size_t i = 0; i < found.size(); ++i) {
      EXPECT_EQ(found[i].a, expected[i].a) << "seed " << seed << " contact " << i;
      EXPECT_EQ(found[i].b, expected[i].b) << "seed " << seed << " contact " << i;
      EXPECT_EQ(found[i].kind, expected[i].kind) << "seed " << seed << " contact " << i;
      (found[i].kind == geom::SegmentContact::kCross ? crossings : overlaps)++;
    }
    // The first few only, as validate asks for one.
    const std::vector<Contact> first = find_contacts(s, 3);
    ASSERT_EQ(first.size(), std::min<size_t>(3, expected.size()));
    for (size_t i = 0; i < first.size(); ++i) EXPECT_EQ(std::tie(first[i].a, first[i].b), std::tie(expected[i].a, expected[i].b));
  }
  EXPECT_GT(crossings, 100);  // the cases exercise both kinds
  EXPECT_GT(overlaps, 100);
}

// The sweep line against brute force where degenerate cases abound: segments between
// the points of a 7x7 lattice (shared ends, ends on other segments, collinear runs,
// verticals), most of them added only if they meet the others at ends at most (the
// layout of a valid level), a few anywhere.
TEST(Crossings, SweepLineFindsTheFirstContactAmongDegenerateSegments) {
  int with_contact = 0, without = 0;
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    Rng rng(seed);
    Source s;
    const int64_t one = int64_t(geom::kFixedOne);
    const auto lattice = [&] { return geom::IPoint{int64_t(rng.below(7)) * one, int64_t(rng.below(7)) * one}; };
    const int walls = 4 + int(rng.below(40));
    const bool stray = rng.below(2) == 0;
    for (int k = 0; k < walls; ++k) {
      const geom::IPoint a = lattice(), b = lattice();
      if (a == b) continue;
      add_segment(s, add_vertex(s, a), add_vertex(s, b));
      const bool bad = !brute_force(s).empty();
      if (bad && !(stray && rng.below(8) == 0)) s.walls.pop_back();
    }
    const std::vector<Contact> expected = brute_force(s);
    const std::optional<Contact> found = first_contact_by_sweep(s);
    ASSERT_EQ(found.has_value(), !expected.empty()) << "seed " << seed;
    (found ? with_contact : without)++;
    if (!found) continue;
    EXPECT_EQ(std::tie(found->a, found->b, found->kind), std::tie(expected[0].a, expected[0].b, expected[0].kind)) << "seed " << seed;
  }
  EXPECT_GT(with_contact, 50);
  EXPECT_GT(without, 50);
}

// Long parallel walls side by side share every cell of the grid: the crossing check
// takes the sweep line there, and still names the first contact.
TEST(Crossings, DenseParallelWallsAreCheckedBySweep) {
  const int64_t one = int64_t(geom::kFixedOne);
  Source s;
  for (int i = 0; i < 3000; ++i)
    add_segment(s, add_vertex(s, {0, 4 * i * one}), add_vertex(s, {100000 * one, (4 * i + 1) * one}));
  EXPECT_TRUE(find_contacts(s, 1).empty());
  add_segment(s, add_vertex(s, {50000 * one, -10 * one}),
              add_vertex(s, {50001 * one, 30 * one}));  // crosses the first few
  add_segment(s, add_vertex(s, {0, 8 * one}), add_vertex(s, {50000 * one, 8 * one + one / 2}));  // overlaps wall 2
  const std::vector<Contact> expected = brute_force(s);
  const std::vector<Contact> found = find_contacts(s, 1);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(std::tie(found[0].a, found[0].b, found[0].kind), std::tie(expected[0].a, expected[0].b, expected[0].kind));
}

// Open sectors against a plain count per (sector, point), on generated rooms with walls
// dropped and vertices duplicated (two vertices at one point are one point).
std::vector<OpenSector> open_sectors_brute_force(const Source& s) {
  std::map<std::tuple<int, int64_t, int64_t>, int> balance;
  for (const Wall& w : s.walls) {
    if (w.segment) continue;
    balance[{w.front.sector, s.point(w.v1).x, s.point(w.v1).y}] += 1;
    balance[{w.front.sector, s.point(w.v2).x, s.point(w.v2).y}] -= 1;
    if (!w.two_sided()) continue;
    balance[{w.back.sector, s.point(w.v2).x, s.point(w.v2).y}] += 1;
    balance[{w.back.sector, s.point(w.v1).x, s.point(w.v1).y}] -= 1;
  }
  std::vector<OpenSector> out;
  for (const auto& [key, b] : balance) {
    const auto& [sector, x, y] = key;
    if (b != 0 && (out.empty() || out.back().sector != sector)) out.push_back({sector, {x, y}});
  }
  return out;
}

TEST(OpenSectors, AgreeWithACountPerPoint) {
  size_t open = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    GenerateOptions options;
    options.walls = 600;
    options.seed = seed;
    options.textures = builtin_textures();
    Source s = generate_rooms(options);
    EXPECT_TRUE(find_open_sectors(s).empty()) << "generated rooms are closed";
    Rng rng(seed);
    for (int k = 0; k < 8; ++k) s.walls.erase(s.walls.begin() + ptrdiff_t(rng.below(s.walls.size())));
    for (int k = 0; k < 40; ++k) {  // a wall's end moved to a twin vertex at the same point
      Wall& w = s.walls[rng.below(s.walls.size())];
      s.vertices.push_back(s.vertices[size_t(w.v1)]);
      w.v1 = int(s.vertices.size()) - 1;
    }
    const std::vector<OpenSector> expected = open_sectors_brute_force(s), found = find_open_sectors(s);
    ASSERT_EQ(found.size(), expected.size()) << "seed " << seed;
    for (size_t i = 0; i < found.size(); ++i) {
      EXPECT_EQ(found[i].sector, expected[i].sector) << "seed " << seed;
      EXPECT_EQ(found[i].at, expected[i].at) << "seed " << seed;
    }
    open += found.size();
  }
  EXPECT_GT(open, 40u);  // most dropped walls open a sector or two
}

}  // namespace
}  // namespace p3d::map
