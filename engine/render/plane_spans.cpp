#include "engine/render/plane_spans.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace p3d::render {

namespace {

size_t hash_of(const PlaneKey& key) {
  const double height = key.height + 0.0;  // -0 and +0 are one height
  uint64_t bits;
  std::memcpy(&bits, &height, sizeof bits);
  uint64_t h = bits ^ (uint64_t(uint32_t(key.texture)) << 32 | uint32_t(key.light));
  h *= 0x9E3779B97F4A7C15ull;
  return size_t(h ^ (h >> 29));
}

}  // namespace

size_t PlaneKeyHash::operator()(const PlaneKey& key) const { return hash_of(key); }

void PlaneSpans::begin(int x0, int x1, int height) {
  x0_ = x0;
  x1_ = std::max(x0, x1);
  height_ = height;
  planes_.clear();
  runs_.clear();
  table_.assign(std::max<size_t>(table_.size(), 64), -1);
  cached_ = -1;
}

int PlaneSpans::make_plane(const PlaneKey& key, bool is_head) {
  const size_t runs = runs_.size();
  runs_.resize(runs + size_t(x1_ - x0_), Run{0, 0});
  planes_.push_back({key, is_head, -1, x1_, x0_ - 1, runs});
  return int(planes_.size()) - 1;
}

int PlaneSpans::head(const PlaneKey& key) {
  if (cached_ >= 0 && planes_[size_t(cached_)].key == key) return cached_;
  if (planes_.size() * 2 >= table_.size()) {  // keep the table at most half full
    table_.assign(table_.size() * 2, -1);
    for (size_t i = 0; i < planes_.size(); ++i) {
      if (!planes_[i].is_head) continue;
      size_t slot = hash_of(planes_[i].key) & (table_.size() - 1);
      while (table_[slot] >= 0) slot = (slot + 1) & (table_.size() - 1);
      table_[slot] = int(i);
    }
  }
  size_t slot = hash_of(key) & (table_.size() - 1);
  for (; table_[slot] >= 0; slot = (slot + 1) & (table_.size() - 1))
    if (planes_[size_t(table_[slot])].key == key) return cached_ = table_[slot];
  return cached_ = table_[slot] = make_plane(key, true);
}

void PlaneSpans::add(const PlaneKey& key, int x, int y0, int y1) {
  int i = head(key);
  for (;;) {
    Plane& p = planes_[size_t(i)];
    Run& r = run(p, x);
    if (r.top >= r.bottom || r.bottom == y0 || r.top == y1) {
      if (r.top >= r.bottom) r = {y0, y1};
      else r = {std::min(r.top, y0), std::max(r.bottom, y1)};
      p.x_min = std::min(p.x_min, x);
      p.x_max = std::max(p.x_max, x);
      return;
    }
    if (p.next < 0) {
      const int added = make_plane(key, false);  // may move planes_: p is not used after this
      planes_[size_t(i)].next = added;
    }
    i = planes_[size_t(i)].next;
  }
}

}  // namespace p3d::render
