// Names to indices for the .map parser: vertices, sectors and textures, each looked up
// once or twice per wall. An open-addressed table of (hash tag, index) pairs, eight
// bytes a slot, whose names sit in one array: a lookup is one probe run and one string
// compare, where std::unordered_map chased a node per name (a tenth of compiling a
// million-wall map).
//
// Names mostly end in a number (v0, v1, ...; r3_17), and walls name the vertices of
// their neighbours. Names that differ only in their number's last three bits share a
// cache line of slots, at their number's place in it, so a run of walls finds its
// vertices with one cache miss in eight; the lines themselves are spread by the hash.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "engine/util/rng.h"

namespace p3d::map::detail {

// Whether two words are the same: a memcmp (inlined against a literal), where
// string_view's == called compare() out of line, a tenth of parsing a big map.
inline bool same_word(std::string_view a, std::string_view b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size()) == 0);
}

class NameIndex {
 public:
  static constexpr int kMissing = -1;

  void reserve(size_t names) {
    chars_.reserve(names * 8);  // names mostly short (v123456): not copied as they come
    ends_.reserve(names);
    values_.reserve(names);
    if (names * 2 > slots_.size()) rehash(names * 2);
  }
  // The index given to `name`, or kMissing.
  int find(std::string_view name) const { return slots_.empty() ? kMissing : find(name, hash(name)); }
  // False (and nothing changed) when `name` is there already.
  bool insert(std::string_view name, int value) {
    const uint64_t h = hash(name);
    if (!slots_.empty() && find(name, h) != kMissing) return false;
    if ((size() + 1) * 2 > slots_.size()) rehash(std::max<size_t>(16, slots_.size() * 2));
    chars_.append(name);
    ends_.push_back(chars_.size());
    values_.push_back(value);
    place(h, int32_t(size() - 1));
    return true;
  }
  size_t size() const { return values_.size(); }

 private:
  int find(std::string_view name, uint64_t h) const {
    for (size_t i = h & mask();; i = (i + 1) & mask()) {
      const Slot& s = slots_[i];
      if (s.name == kEmpty) return kMissing;
      if (s.tag == tag(h) && same_word(name_at(size_t(s.name)), name)) return values_[size_t(s.name)];
    }
  }

  static constexpr int32_t kEmpty = -1;
  static constexpr size_t kMaxDigits = 9;  // a number's digits read (more belong to the stem)
  struct Slot {
    uint32_t tag = 0;        // high bits of the name's hash: most mismatches end here
    int32_t name = kEmpty;   // into names_ and values_, or kEmpty: a free slot
  };

  // Low 32 bits: the first slot to probe; high 32: the tag. A name ending in digits
  // hashes its stem, its digit count and its number without the last three bits, and
  // puts those bits in the slot's place within its cache line (8 slots).
  static uint64_t hash(std::string_view name) {
    size_t stem = name.size();
    while (stem > 0 && name.size() - stem < kMaxDigits && name[stem - 1] >= '0' && name[stem - 1] <= '9') --stem;
    uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : name.substr(0, stem)) h = (h ^ uint8_t(c)) * 0x100000001b3ull;
    const size_t digits = name.size() - stem;
    if (digits == 0) return mix64(h);
    uint64_t number = 0;
    for (const char c : name.substr(stem)) number = number * 10 + uint64_t(c - '0');
    const uint64_t line = mix64(h ^ (digits << 56) ^ (number >> 3));
    const uint64_t place = number & 7;
    return ((line >> 32) ^ (place * 0x9e3779b9u)) << 32 | ((line & 0xfffffff8u) | place);
  }
  static uint32_t tag(uint64_t h) { return uint32_t(h >> 32); }
  size_t mask() const { return slots_.size() - 1; }

  void place(uint64_t h, int32_t name) {
    size_t i = h & mask();
    while (slots_[i].name != kEmpty) i = (i + 1) & mask();
    slots_[i] = {tag(h), name};
  }
  void rehash(size_t at_least) {
    size_t capacity = 16;
    while (capacity < at_least) capacity *= 2;
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    for (const Slot& s : old)
      if (s.name != kEmpty) place(hash(name_at(size_t(s.name))), s.name);
  }

  std::string_view name_at(size_t i) const {
    const size_t start = i == 0 ? 0 : ends_[i - 1];
    return std::string_view(chars_).substr(start, ends_[i] - start);
  }

  // The names one after another, each ending where ends_ says: a million vertices' names
  // in 15 MB, where as strings they took 32.
  std::string chars_;
  std::vector<uint32_t> ends_;  // the names come from one file, under limits::kMaxFileBytes (2 GiB)
  std::vector<int> values_;
  std::vector<Slot> slots_;  // a power of two, at most half full
};

}  // namespace p3d::map::detail
