#include "engine/map/name_index.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

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

// Numbered names share cache lines of slots by stem and number: names that only a
// stem, a leading zero, a long number or the digits alone tell apart stay apart.
TEST(NameIndex, NumberedNamesWithTheSameNumbersStayApart) {
  NameIndex index;
  std::vector<std::string> names;
  for (int i = 0; i < 3000; ++i)
    for (const char* stem : {"v", "w", "v_", "", "sector"}) names.push_back(std::string(stem) + std::to_string(i));
  for (const char* name : {"v01", "v001", "v0001", "12345678901234567890", "22345678901234567890", "x-1", "x-01"})
    names.push_back(name);
  for (size_t i = 0; i < names.size(); ++i) ASSERT_TRUE(index.insert(names[i], int(i))) << names[i];
  for (size_t i = 0; i < names.size(); ++i) ASSERT_EQ(index.find(names[i]), int(i)) << names[i];
  EXPECT_EQ(index.find("v3000"), NameIndex::kMissing);
  EXPECT_EQ(index.find("v00001"), NameIndex::kMissing);
  EXPECT_EQ(index.find("32345678901234567890"), NameIndex::kMissing);
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
