#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "engine/render/plane_spans.h"
#include "engine/util/rng.h"

namespace p3d::render {
namespace {

const PlaneKey kKeys[] = {{0, 1, 8}, {0, 1, 12}, {128, 1, 8}, {0, 2, 8}, {-0.0, 1, 8}};

// Every column of [x0, x1) cut into random runs, each of a random key or of none, filed
// in a random order: every filed pixel comes back exactly once, in its own key's spans.
// One PlaneSpans serves every seed, as a canvas's serves every frame: nothing of an
// earlier frame's runs shows.
TEST(PlaneSpans, GivesBackEveryFiledPixelOnceUnderItsKey) {
  PlaneSpans planes;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    const int height = 1 + int(rng.below(60)), x0 = int(rng.below(20)), x1 = x0 + 1 + int(rng.below(50));
    struct Filed { int key, x, y0, y1; };
    std::vector<Filed> runs;
    for (int x = x0; x < x1; ++x)
      for (int y = 0; y < height;) {
        const int y1 = std::min(height, y + 1 + int(rng.below(12)));
        const int key = int(rng.below(std::size(kKeys) + 1)) - 1;  // -1: a wall there
        if (key >= 0) runs.push_back({key, x, y, y1});
        y = y1;
      }
    for (size_t i = runs.size(); i > 1; --i) std::swap(runs[i - 1], runs[rng.below(i)]);
    std::map<std::pair<int, int>, int> filed;  // (x, y) -> key
    planes.begin(x0, x1, height);
    for (const Filed& r : runs) {
      planes.add(kKeys[r.key], r.x, r.y0, r.y1);
      for (int y = r.y0; y < r.y1; ++y) filed[{r.x, y}] = r.key;
    }
    std::map<std::pair<int, int>, int> given;
    planes.for_each_span([&](const PlaneKey& key, int y, int xa, int xb) {
      ASSERT_LT(xa, xb);
      ASSERT_GE(xa, x0);
      ASSERT_LE(xb, x1);
      for (int x = xa; x < xb; ++x) {
        ASSERT_TRUE(given.emplace(std::pair{x, y}, 0).second) << "pixel " << x << "," << y << " twice, seed " << seed;
        ASSERT_TRUE(filed.count(std::pair{x, y})) << "pixel " << x << "," << y << " never filed, seed " << seed;
        const PlaneKey& expected = kKeys[filed[std::pair{x, y}]];
        EXPECT_TRUE(key == expected) << "seed " << seed;
      }
    });
    EXPECT_EQ(given.size(), filed.size()) << "seed " << seed;
  }
}

// A floor filed as two runs per column that touch (over a two-sided line at the same
// height), column by column, is one plane: one span per row, across every column.
TEST(PlaneSpans, JoinsTouchingRunsIntoOneSpanPerRow) {
  PlaneSpans planes;
  planes.begin(10, 90, 100);
  for (int x = 10; x < 90; ++x) {
    planes.add(kKeys[0], x, 70, 100);
    planes.add(kKeys[0], x, 50 + x % 7, 70);
  }
  std::map<int, int> spans_per_row;
  planes.for_each_span([&](const PlaneKey&, int y, int xa, int xb) {
    ++spans_per_row[y];
    if (y >= 57) {
      EXPECT_EQ(xa, 10) << "row " << y;
      EXPECT_EQ(xb, 90) << "row " << y;
    }
  });
  for (int y = 57; y < 100; ++y) EXPECT_EQ(spans_per_row[y], 1) << "row " << y;
}

// Planes differ by height, picture and light; a plane seen twice in a column (a floor
// behind a raised platform) needs a second plane of the same key, and gets it.
TEST(PlaneSpans, SeparatesKeysAndRepeatsAKeyWithinAColumn) {
  PlaneSpans planes;
  planes.begin(0, 4, 20);
  for (int x = 0; x < 4; ++x) {
    planes.add(kKeys[0], x, 15, 20);
    planes.add(kKeys[2], x, 10, 12);
    planes.add(kKeys[0], x, 5, 8);
  }
  std::map<std::tuple<double, int, int>, int> pixels;
  planes.for_each_span([&](const PlaneKey& k, int, int xa, int xb) { pixels[{k.height, k.texture, k.light}] += xb - xa; });
  EXPECT_EQ(pixels[std::tuple(0.0, 1, 8)], 4 * (5 + 3));
  EXPECT_EQ(pixels[std::tuple(128.0, 1, 8)], 4 * 2);
  EXPECT_EQ(pixels.size(), 2u);
}

}  // namespace
}  // namespace p3d::render
