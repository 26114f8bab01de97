#include "engine/map/name_index.h"

#include <gtest/gtest.h>

#include <string>

namespace p3d::map::detail {
namespace {

// Names that share long prefixes and differ in their last characters, as a
// generated map's do, found again after the table grew many times from empty.
TEST(NameIndex, FindsEveryNameItWasGivenAndNoOther) {
  NameIndex index;
  const int n = 50000;
  for (int i = 0; i < n; ++i) ASSERT_TRUE(index.insert("r" + std::to_string(i) + "_" + std::to_string(i % 7), 3 * i + 1));
  EXPECT_EQ(index.size(), size_t(n));
  for (int i = 0; i < n; ++i) ASSERT_EQ(index.find("r" + std::to_string(i) + "_" + std::to_string(i % 7)), 3 * i + 1) << i;
  for (int i = 0; i < n; i += 97) EXPECT_EQ(index.find("r" + std::to_string(i) + "_" + std::to_string(i % 7 + 7)), NameIndex::kMissing);
  EXPECT_EQ(index.find(""), NameIndex::kMissing);
  EXPECT_EQ(index.find("r1"), NameIndex::kMissing);  // a prefix of a name is not the name
}

TEST(NameIndex, RefusesANameTwiceAndKeepsTheFirstValue) {
  NameIndex index;
  EXPECT_EQ(index.find("a"), NameIndex::kMissing);  // empty, never reserved
  index.reserve(4);
  EXPECT_TRUE(index.insert("a", 7));
  EXPECT_TRUE(index.insert("", 8));  // the empty name is a name like any other
  EXPECT_FALSE(index.insert("a", 9));
  EXPECT_EQ(index.find("a"), 7);
  EXPECT_EQ(index.find(""), 8);
  EXPECT_EQ(index.size(), 2u);
}

}  // namespace
}  // namespace p3d::map::detail
