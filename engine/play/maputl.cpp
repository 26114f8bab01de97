// The map's geometry as the rules ask it (Doom's p_maputl.c): which side of a line a
// point or box is on, the opening a two-sided line leaves, things linked into their
// sector and blockmap cell, and the traversal of a trace through the blockmap, its
// lines and things visited nearest first. Every test is Doom's own, ties included.
#include <climits>
#include <cstdlib>

#include "engine/play/world.h"

namespace p3d::play {

int World::point_on_line_side(Fixed x, Fixed y, const Line& line) {
  if (!line.dx) return x <= line.v1->x ? line.dy > 0 : line.dy < 0;
  if (!line.dy) return y <= line.v1->y ? line.dx < 0 : line.dx > 0;
  const Fixed dx = wrap_sub(x, line.v1->x), dy = wrap_sub(y, line.v1->y);
  const Fixed left = fixed_mul(line.dy >> kFracBits, dx);
  const Fixed right = fixed_mul(dy, line.dx >> kFracBits);
  return right < left ? 0 : 1;
}

// -1 when the box straddles the line.
int World::box_on_line_side(const Box& box, const Line& ld) {
  int p1 = 0, p2 = 0;
  switch (ld.slope) {
    case Slope::kHorizontal:
      p1 = box[kBoxTop] > ld.v1->y;
      p2 = box[kBoxBottom] > ld.v1->y;
      if (ld.dx < 0) p1 ^= 1, p2 ^= 1;
      break;
    case Slope::kVertical:
      p1 = box[kBoxRight] < ld.v1->x;
      p2 = box[kBoxLeft] < ld.v1->x;
      if (ld.dy < 0) p1 ^= 1, p2 ^= 1;
      break;
    case Slope::kPositive:
      p1 = point_on_line_side(box[kBoxLeft], box[kBoxTop], ld);
      p2 = point_on_line_side(box[kBoxRight], box[kBoxBottom], ld);
      break;
    case Slope::kNegative:
      p1 = point_on_line_side(box[kBoxRight], box[kBoxTop], ld);
      p2 = point_on_line_side(box[kBoxLeft], box[kBoxBottom], ld);
      break;
  }
  return p1 == p2 ? p1 : -1;
}

int World::point_on_divline_side(Fixed x, Fixed y, const DivLine& line) {
  if (!line.dx) return x <= line.x ? line.dy > 0 : line.dy < 0;
  if (!line.dy) return y <= line.y ? line.dx < 0 : line.dx > 0;
  const Fixed dx = wrap_sub(x, line.x), dy = wrap_sub(y, line.y);
  // The sign bits decide most cases without a multiplication.
  if ((line.dy ^ line.dx ^ dx ^ dy) & Fixed(0x80000000)) return (line.dy ^ dx) & Fixed(0x80000000) ? 1 : 0;
  const Fixed left = fixed_mul(line.dy >> 8, dx >> 8);
  const Fixed right = fixed_mul(dy >> 8, line.dx >> 8);
  return right < left ? 0 : 1;
}

World::DivLine World::make_divline(const Line& line) { return {line.v1->x, line.v1->y, line.dx, line.dy}; }

// Where along v2 it meets v1, as a fraction of v2 (16.16); 0 when parallel.
Fixed World::intercept_vector(const DivLine& v2, const DivLine& v1) {
  const Fixed den = wrap_sub(fixed_mul(v1.dy >> 8, v2.dx), fixed_mul(v1.dx >> 8, v2.dy));
  if (den == 0) return 0;
  const Fixed num = wrap_add(fixed_mul(wrap_sub(v1.x, v2.x) >> 8, v1.dy), fixed_mul(wrap_sub(v2.y, v1.y) >> 8, v1.dx));
  return fixed_div(num, den);
}

const World::Opening& World::line_opening(const Line& line) {
  Opening& o = opening_;
  if (line.side[1] == -1) {  // no back side: no opening, the rest as the last line left it
    o.range = 0;
    return o;
  }
  const Sector *front = line.front, *back = line.back;
  o.top = std::min(front->ceiling_height, back->ceiling_height);
  if (front->floor_height > back->floor_height) {
    o.bottom = front->floor_height;
    o.low_floor = back->floor_height;
  } else {
    o.bottom = back->floor_height;
    o.low_floor = front->floor_height;
  }
  o.range = wrap_sub(o.top, o.bottom);
  return o;
}

void World::unset_thing_position(Mobj* thing) {
  if (!(thing->flags & kNosector)) {
    if (thing->snext) thing->snext->sprev = thing->sprev;
    if (thing->sprev)
      thing->sprev->snext = thing->snext;
    else
      thing->subsector->sector->thing_list = thing->snext;
  }
  if (!(thing->flags & kNoblockmap)) {
    if (thing->bnext) thing->bnext->bprev = thing->bprev;
    if (thing->bprev) {
      thing->bprev->bnext = thing->bnext;
    } else {
      if (Mobj** link = block_link(block_x(thing->x), block_y(thing->y))) *link = thing->bnext;
    }
  }
}

void World::set_thing_position(Mobj* thing) {
  Subsector* ss = map_.point_in_subsector(thing->x, thing->y);
  thing->subsector = ss;
  if (!(thing->flags & kNosector)) {  // invisible things stay out of the sector's list
    Sector* sec = ss->sector;
    thing->sprev = nullptr;
    thing->snext = sec->thing_list;
    if (sec->thing_list) sec->thing_list->sprev = thing;
    sec->thing_list = thing;
  }
  if (!(thing->flags & kNoblockmap)) {
    if (Mobj** link = block_link(block_x(thing->x), block_y(thing->y))) {
      thing->bprev = nullptr;
      thing->bnext = *link;
      if (*link) (*link)->bprev = thing;
      *link = thing;
    } else {  // off the map
      thing->bnext = thing->bprev = nullptr;
    }
  }
}

size_t World::block_cell(int bx, int by) const {
  const Blockmap& bm = map_.blockmap;
  if (bx < 0 || by < 0 || bx >= bm.width || by >= bm.height) return kOffTheMap;
  return size_t(by) * size_t(bm.width) + size_t(bx);
}

Mobj** World::block_link(int bx, int by) {
  const size_t cell = block_cell(bx, by);
  if (cell == kOffTheMap) return nullptr;
  if (cell >= block_links_.size()) {  // only once an intercepts overrun changed the blockmap's size
    note_beyond_chocolate("things of blockmap cell " + std::to_string(cell) + ", past the blockmap");
    return nullptr;
  }
  return &block_links_[cell];
}

void World::note_beyond_chocolate(const std::string& what) {
  if (beyond_chocolate_.empty()) beyond_chocolate_ = "tic " + std::to_string(level_time_) + " of the level: " + what;
}

// Vanilla Doom held 128 intercepts, and a trace across more lines and things wrote the
// rest over the globals that followed the array, 12 bytes each (the fraction, whether
// it is a line, the pointer): the line opening, the bullet slope, the player starts, and
// the blockmap's size and origin, for the rest of the level. Chocolate Doom writes the
// fractions and flags where vanilla did, for 61 intercepts more; beyond those it writes
// past its own array.
void World::overrun_intercepts(size_t index) {
  constexpr size_t kVanillaIntercepts = 128, kChocolateIntercepts = kVanillaIntercepts + 61;
  if (index <= kVanillaIntercepts) return;
  if (index >= kChocolateIntercepts) {
    note_beyond_chocolate("a trace met more than " + std::to_string(kChocolateIntercepts) + " lines and things");
    return;
  }
  const Intercept& in = intercepts_[index];
  const int location = int(index - kVanillaIntercepts - 1) * 12;
  overrun_write(location, in.frac);
  overrun_write(location + 4, in.is_line);
  // The pointer (location + 8) was a host address in Chocolate: opentop, swingx and the
  // player starts' coordinates take values no other program can know. Opentop is set
  // again before it is read, and the starts matter only to a netgame's rebirth.
}

// Vanilla's globals after the intercepts array, by byte offset from its end (as
// Chocolate's p_maputl.c lays them out); those it does not emulate are left alone.
void World::overrun_write(int location, int32_t value) {
  auto& bm = map_.blockmap;
  switch (location) {
    case 12: opening_.low_floor = value; return;
    case 16: opening_.bottom = value; return;
    case 24: opening_.range = value; return;
    case 160: bullet_slope_ = value; return;
    case 220: bm.width = value; return;
    case 228: bm.origin_x = value; return;
    case 232: bm.origin_y = value; return;
    case 240: bm.height = value; return;
  }
  constexpr int kStarts = 176, kStartsEnd = kStarts + 4 * 10;  // four mapthing_t of five shorts
  if (location >= kStarts && location < kStartsEnd) {
    const int field = (location - kStarts) / 2;
    auto start_short = [&](int i) -> int16_t& {
      MapThing& t = player_starts_[size_t(i / 5)];
      int16_t* fields[] = {&t.x, &t.y, &t.angle, &t.type, &t.options};
      return *fields[i % 5];
    };
    start_short(field) = int16_t(value & 0xFFFF);
    if (field + 1 < 20) start_short(field + 1) = int16_t((value >> 16) & 0xFFFF);
  }
}

bool World::path_traverse(Fixed x1, Fixed y1, Fixed x2, Fixed y2, int flags,
                          const std::function<bool(Intercept&)>& trav) {
  const bool early_out = flags & kEarlyOut;
  ++valid_count_;
  intercepts_.clear();
  const Fixed org_x = map_.blockmap.origin_x, org_y = map_.blockmap.origin_y;
  if ((wrap_sub(x1, org_x) & (kMapBlockSize - 1)) == 0) x1 = wrap_add(x1, kFracUnit);  // not exactly on a cell's edge
  if ((wrap_sub(y1, org_y) & (kMapBlockSize - 1)) == 0) y1 = wrap_add(y1, kFracUnit);
  trace_ = {x1, y1, wrap_sub(x2, x1), wrap_sub(y2, y1)};

  auto add_line = [&](Line* ld) {
    int s1, s2;
    // Two tests, each precise where the other is not.
    if (trace_.dx > kFracUnit * 16 || trace_.dy > kFracUnit * 16 || trace_.dx < -kFracUnit * 16 ||
        trace_.dy < -kFracUnit * 16) {
      s1 = point_on_divline_side(ld->v1->x, ld->v1->y, trace_);
      s2 = point_on_divline_side(ld->v2->x, ld->v2->y, trace_);
    } else {
      s1 = point_on_line_side(trace_.x, trace_.y, *ld);
      s2 = point_on_line_side(wrap_add(trace_.x, trace_.dx), wrap_add(trace_.y, trace_.dy), *ld);
    }
    if (s1 == s2) return true;  // not crossed
    const Fixed frac = intercept_vector(trace_, make_divline(*ld));
    if (frac < 0) return true;  // behind the source
    if (early_out && frac < kFracUnit && !ld->back) return false;  // a wall in reach ends it
    intercepts_.push_back({frac, true, nullptr, ld});
    overrun_intercepts(intercepts_.size() - 1);
    return true;
  };
  auto add_thing = [&](Mobj* thing) {
    // The thing's diagonal across the trace.
    const bool positive = (trace_.dx ^ trace_.dy) > 0;
    const Fixed xa = wrap_sub(thing->x, thing->radius), xb = wrap_add(thing->x, thing->radius);
    const Fixed ya = positive ? wrap_add(thing->y, thing->radius) : wrap_sub(thing->y, thing->radius);
    const Fixed yb = positive ? wrap_sub(thing->y, thing->radius) : wrap_add(thing->y, thing->radius);
    if (point_on_divline_side(xa, ya, trace_) == point_on_divline_side(xb, yb, trace_)) return true;
    const Fixed frac = intercept_vector(trace_, DivLine{xa, ya, wrap_sub(xb, xa), wrap_sub(yb, ya)});
    if (frac < 0) return true;
    intercepts_.push_back({frac, false, thing, nullptr});
    overrun_intercepts(intercepts_.size() - 1);
    return true;
  };

  // Step through the cells the trace crosses, in order.
  x1 = wrap_sub(x1, org_x);
  y1 = wrap_sub(y1, org_y);
  x2 = wrap_sub(x2, org_x);
  y2 = wrap_sub(y2, org_y);
  const int xt1 = x1 >> kMapBlockShift, yt1 = y1 >> kMapBlockShift;
  const int xt2 = x2 >> kMapBlockShift, yt2 = y2 >> kMapBlockShift;
  constexpr int kBlockToFrac = kMapBlockShift - kFracBits;
  int map_xstep, map_ystep;
  Fixed partial, xstep, ystep;
  if (xt2 > xt1) {
    map_xstep = 1;
    partial = kFracUnit - ((x1 >> kBlockToFrac) & (kFracUnit - 1));
    ystep = fixed_div(wrap_sub(y2, y1), std::abs(wrap_sub(x2, x1)));
  } else if (xt2 < xt1) {
    map_xstep = -1;
    partial = (x1 >> kBlockToFrac) & (kFracUnit - 1);
    ystep = fixed_div(wrap_sub(y2, y1), std::abs(wrap_sub(x2, x1)));
  } else {
    map_xstep = 0;
    partial = kFracUnit;
    ystep = 256 * kFracUnit;
  }
  Fixed y_intercept = wrap_add(y1 >> kBlockToFrac, fixed_mul(partial, ystep));
  if (yt2 > yt1) {
    map_ystep = 1;
    partial = kFracUnit - ((y1 >> kBlockToFrac) & (kFracUnit - 1));
    xstep = fixed_div(wrap_sub(x2, x1), std::abs(wrap_sub(y2, y1)));
  } else if (yt2 < yt1) {
    map_ystep = -1;
    partial = (y1 >> kBlockToFrac) & (kFracUnit - 1);
    xstep = fixed_div(wrap_sub(x2, x1), std::abs(wrap_sub(y2, y1)));
  } else {
    map_ystep = 0;
    partial = kFracUnit;
    xstep = 256 * kFracUnit;
  }
  Fixed x_intercept = wrap_add(x1 >> kBlockToFrac, fixed_mul(partial, xstep));
  int map_x = xt1, map_y = yt1;
  for (int count = 0; count < 64; ++count) {  // the count stops a rounding error from skipping the end
    if ((flags & kAddLines) && !block_lines(map_x, map_y, add_line)) return false;
    if ((flags & kAddThings) && !block_things(map_x, map_y, add_thing)) return false;
    if (map_x == xt2 && map_y == yt2) break;
    if ((y_intercept >> kFracBits) == map_y) {
      y_intercept = wrap_add(y_intercept, ystep);
      map_x += map_xstep;
    } else if ((x_intercept >> kFracBits) == map_x) {
      x_intercept = wrap_add(x_intercept, xstep);
      map_y += map_ystep;
    }
  }

  // Nearest first (Doom's selection: the first of equal fractions), up to the trace's end.
  for (size_t left = intercepts_.size(); left > 0; --left) {
    Fixed dist = INT_MAX;
    Intercept* in = nullptr;
    for (Intercept& scan : intercepts_)
      if (scan.frac < dist) dist = scan.frac, in = &scan;
    if (dist > kFracUnit) return true;
    if (!trav(*in)) return false;
    in->frac = INT_MAX;
  }
  return true;
}

}  // namespace p3d::play
