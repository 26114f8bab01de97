// The radix sort by key against std::stable_sort by key: the same order, equal keys in
// the order given, for keys of one to all of their bits, 32 and 64 wide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/util/radix_sort.h"
#include "engine/util/rng.h"

namespace p3d {
namespace {

template <typename Key>
void expect_as_stable_sort(size_t count, int key_bits, uint64_t seed) {
  Rng rng(seed);
  std::vector<std::pair<Key, uint32_t>> pairs(count);
  const uint64_t mask = key_bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << key_bits) - 1;
  for (uint32_t i = 0; i < count; ++i) pairs[i] = {Key(rng.next() & mask), i};
  std::vector<std::pair<Key, uint32_t>> expected = pairs;
  std::stable_sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  radix_sort_by_key(pairs);
  EXPECT_EQ(pairs, expected) << count << " pairs, " << key_bits << "-bit keys";
}

TEST(RadixSort, OrdersAsStableSortByKey) {
  for (const size_t count : {0, 1, 2, 1000, 70000})
    for (const int bits : {1, 3, 12, 13, 24, 32}) {
      expect_as_stable_sort<uint32_t>(count, bits, count * 100 + size_t(bits));
      expect_as_stable_sort<uint64_t>(count, bits, count * 100 + size_t(bits) + 7);
    }
  for (const int bits : {36, 48, 63, 64}) expect_as_stable_sort<uint64_t>(5000, bits, size_t(bits));
}

}  // namespace
}  // namespace p3d
