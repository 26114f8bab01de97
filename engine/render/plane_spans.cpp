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
  runs_used_ = 0;
  table_.assign(std::max<size_t>(table_.size(), 64), -1);
  cached_ = -1;
}

// A plane's runs are set only as it reaches new columns (cover): most planes cover a
// few columns of a strip, and emptying all of each was a fifth of filing them.
int PlaneSpans::make_plane(const PlaneKey& key, bool is_head) {
  const size_t runs = runs_used_;
  runs_used_ += size_t(x1_ - x0_);
  if (runs_.size() < runs_used_) runs_.resize(std::max(runs_used_, 2 * runs_.size()));  // kept from frame to frame
  planes_.push_back({key, is_head, -1, x1_, x0_ - 1, runs});
  return int(planes_.size()) - 1;
}

void PlaneSpans::cover(Plane& p, int x) {
  if (p.x_min > p.x_max) {
    p.x_min = p.x_max = x;
    return;
  }
  for (int c = p.x_max + 1; c < x; ++c) run(p, c) = {0, 0};
  for (int c = x + 1; c < p.x_min; ++c) run(p, c) = {0, 0};
  p.x_min = std::min(p.x_min, x);
  p.x_max = std::max(p.x_max, x);
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

void PlaneSpans::add_to_any_column(int plane, int x, int y0, int y1) {
  int i = plane;
  for (;;) {
    Plane& p = planes_[size_t(i)];
    if (x < p.x_min || x > p.x_max) {  // a column new to the plane
      cover(p, x);
      run(p, x) = {y0, y1};
      return;
    }
    Run& r = run(p, x);
    if (r.top >= r.bottom || r.bottom == y0 || r.top == y1) {
      r = r.top >= r.bottom ? Run{y0, y1} : Run{std::min(r.top, y0), std::max(r.bottom, y1)};
      return;
    }
    if (p.next < 0) {
      const PlaneKey key = p.key;
      const int added = make_plane(key, false);  // may move planes_: p is not used after this
      planes_[size_t(i)].next = added;
    }
    i = planes_[size_t(i)].next;
  }
}

}  // namespace p3d::render
