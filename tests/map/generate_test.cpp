#include <gtest/gtest.h>

#include "engine/map/generate.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d::map {
namespace {

TEST(Generate, SoupsAreValidExactAndNested) {
  const Source small = test::random_soup(300, 5), large = test::random_soup(2000, 5);
  EXPECT_NO_THROW(validate(small));
  EXPECT_NO_THROW(validate(large));
  ASSERT_EQ(small.walls.size(), 300u);
  ASSERT_EQ(large.walls.size(), 2000u);
  for (size_t i = 0; i < small.walls.size(); ++i) {  // the small soup is the middle of the large one
    EXPECT_EQ(small.point(small.walls[i].v1), large.point(large.walls[i].v1));
    EXPECT_EQ(small.point(small.walls[i].v2), large.point(large.walls[i].v2));
  }
  EXPECT_NE(test::random_soup(300, 6).point(0), small.point(0));
}

TEST(Generate, RoomsAreValidClosedAndSeeded) {
  for (uint64_t seed : {1, 2, 3}) {
    const Source s = test::random_rooms(600, seed);
    EXPECT_NO_THROW(validate(s)) << "seed " << seed;
    EXPECT_GE(s.walls.size(), 600u);
    EXPECT_GT(s.sectors.size(), 40u);
    EXPECT_TRUE(std::any_of(s.walls.begin(), s.walls.end(), [](const Wall& w) { return w.two_sided(); }));
  }
}

TEST(Generate, MapTextRoundTrips) {
  const auto dir = test::temp_dir("generate");
  const Source s = test::random_rooms(300, 9);
  std::vector<std::string> files;
  for (size_t i = 0; i < s.textures.size(); ++i) {
    files.push_back("t" + std::to_string(i) + ".png");
    image::save_png(s.textures[i].image, dir / files.back());
  }
  write_file_atomically(dir / "rooms.map", to_map_text(s, files));
  const Source back = load_map(dir / "rooms.map");
  ASSERT_EQ(back.walls.size(), s.walls.size());
  ASSERT_EQ(back.sectors.size(), s.sectors.size());
  for (size_t i = 0; i < s.walls.size(); ++i) {
    EXPECT_EQ(back.point(back.walls[i].v1), s.point(s.walls[i].v1));
    EXPECT_EQ(back.walls[i].front.sector, s.walls[i].front.sector);
    EXPECT_EQ(back.walls[i].back.sector, s.walls[i].back.sector);
    EXPECT_EQ(back.walls[i].front.middle, s.walls[i].front.middle);
  }
  for (size_t i = 0; i < s.sectors.size(); ++i) EXPECT_EQ(back.sectors[i].ceiling, s.sectors[i].ceiling);
  EXPECT_EQ(to_map_text(back, files), to_map_text(s, files));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace p3d::map
