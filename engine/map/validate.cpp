// Source validation shared by all map formats: every wall has length, no two
// walls cross or overlap, every sector is used and closed, heights and textures
// make sense. Messages point at the line of the offending statement.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <span>
#include <string_view>
#include <unordered_map>

#include "engine/map/source.h"
#include "engine/util/radix_sort.h"

namespace p3d::map {

namespace {

using geom::IPoint;

// The contacts the check refuses: walls that cross, or overlap along a line (meeting at
// an end, or an end on the other's inside, is allowed).
bool refused(geom::SegmentContact kind) {
  return kind == geom::SegmentContact::kCross || kind == geom::SegmentContact::kOverlap;
}

// The max_count contacts with the smallest (later, earlier) walls, kept in a max-heap
// on that key; walls are tested exactly.
class ContactList {
 public:
  ContactList(const Source& src, size_t max_count) : src_(src), max_count_(max_count) {}

  // False when the pair cannot enter the list (a later pair (b', a') >= (b, a) cannot either).
  bool wanted(uint32_t a, uint32_t b) const {
    return best_.size() < max_count_ || later_first({a, b, {}}, best_.front());
  }
  void test(uint32_t a, uint32_t b) {  // a < b
    if (!wanted(a, b)) return;
    const Wall &wa = src_.walls[a], &wb = src_.walls[b];
    const auto kind = geom::segment_contact(src_.point(wa.v1), src_.point(wa.v2), src_.point(wb.v1), src_.point(wb.v2));
    if (refused(kind)) add({a, b, kind});
  }
  void add(const Contact& c) {
    if (std::any_of(best_.begin(), best_.end(), [&](const Contact& o) { return o.a == c.a && o.b == c.b; })) return;
    best_.push_back(c);
    std::push_heap(best_.begin(), best_.end(), later_first);
    if (best_.size() > max_count_) {
      std::pop_heap(best_.begin(), best_.end(), later_first);
      best_.pop_back();
    }
  }
  std::vector<Contact> sorted() && {
    std::sort(best_.begin(), best_.end(), later_first);
    return std::move(best_);
  }

 private:
  static bool later_first(const Contact& x, const Contact& y) { return std::tie(x.b, x.a) < std::tie(y.b, y.a); }
  const Source& src_;
  size_t max_count_;
  std::vector<Contact> best_;
};

struct PointHash {
  size_t operator()(IPoint p) const { return std::hash<int64_t>()(p.x * 0x9E3779B97F4A7C15ll ^ p.y); }
};

// The walls of one grid cell (ascending). All pairs are tested, except among walls
// sharing the cell's busiest endpoint: those meet there, so they can only overlap, and
// overlap exactly when they leave it in the same direction (sorted by direction, not
// paired). This keeps a star or fan of n walls at one point at O(n log n), not n^2.
void test_cell(const Source& src, const std::vector<uint32_t>& cell_walls, ContactList& contacts) {
  constexpr size_t kCrowded = 32;
  std::span<const uint32_t> walls = cell_walls;  // most cells are never copied
  std::vector<uint32_t> rest;                     // what is left once a crowded point's spokes are done
  while (walls.size() > kCrowded) {
    std::unordered_map<IPoint, int, PointHash> uses;
    for (uint32_t w : walls) ++uses[src.point(src.walls[w].v1)], ++uses[src.point(src.walls[w].v2)];
    const auto busiest = std::max_element(uses.begin(), uses.end(), [](const auto& x, const auto& y) {
      return std::tie(x.second, x.first.x, x.first.y) < std::tie(y.second, y.first.x, y.first.y);
    });
    if (busiest->second < int(kCrowded)) break;
    const IPoint hub = busiest->first;
    // (direction away from the hub reduced to lowest terms, wall), and the other walls.
    std::vector<std::pair<std::pair<int64_t, int64_t>, uint32_t>> spokes;
    std::vector<uint32_t> others;
    for (uint32_t w : walls) {
      const IPoint p1 = src.point(src.walls[w].v1), p2 = src.point(src.walls[w].v2);
      if (p1 != hub && p2 != hub) {
        others.push_back(w);
        continue;
      }
      const IPoint d = geom::sub(p1 == hub ? p2 : p1, hub);
      const int64_t g = std::gcd(d.x, d.y);
      if (g == 0) {  // zero length (reported elsewhere)
        others.push_back(w);
        continue;
      }
      spokes.push_back({{d.x / g, d.y / g}, w});
    }
    std::sort(spokes.begin(), spokes.end());
    for (size_t begin = 0; begin < spokes.size();) {
      size_t end = begin;
      while (end < spokes.size() && spokes[end].first == spokes[begin].first) ++end;
      for (size_t q = begin + 1; q < end; ++q)  // pairs in ascending (later, earlier) order
        for (size_t p = begin; p < q && contacts.wanted(spokes[p].second, spokes[q].second); ++p)
          contacts.add({spokes[p].second, spokes[q].second, geom::SegmentContact::kOverlap});
      begin = end;
    }
    for (const auto& spoke : spokes)
      for (uint32_t o : others) contacts.test(std::min(spoke.second, o), std::max(spoke.second, o));
    rest = std::move(others);
    walls = rest;
  }
  for (size_t p = 0; p < walls.size(); ++p)
    for (size_t q = p + 1; q < walls.size(); ++q) contacts.test(walls[p], walls[q]);
}

// Whether any two of the first `count` walls cross or overlap, by a sweep line
// (Shamos and Hoey): O(n log n) whatever the walls' layout. Walls become segments from
// their lesser end to their greater (by x, then y: the sweep line leans by an
// infinitesimal), kept in the order they cross the sweep line. A pair that is ever
// adjacent in that order is tested; the first contact (leftmost point) always has a
// pair adjacent around it before the sweep passes it, and before it every pair that
// shares the line meets at most at an end, so their order is well defined.
class SweepLine {
 public:
  explicit SweepLine(const Source& src) : status_(Below{this}) {
    const size_t n = src.walls.size();
    ends_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
      IPoint a = src.point(src.walls[i].v1), b = src.point(src.walls[i].v2);
      if (less(b, a)) std::swap(a, b);
      ends_[i] = {a, b};
    }
  }

  bool any_contact(size_t count) {
    events_.clear();
    for (uint32_t i = 0; i < count; ++i)
      if (ends_[i][0] != ends_[i][1]) events_.push_back({ends_[i][0], i, true}), events_.push_back({ends_[i][1], i, false});
    // At one point: walls leaving the sweep line first (their neighbours, then tested,
    // must be), then walls joining it.
    std::sort(events_.begin(), events_.end(), [](const Event& x, const Event& y) {
      return less(x.at, y.at) || (x.at == y.at && std::tie(x.start, x.wall) < std::tie(y.start, y.wall));
    });
    status_.clear();
    where_.assign(count, status_.end());
    for (const Event& e : events_) {
      if (e.start) {
        const auto it = status_.insert(e.wall).first;
        where_[e.wall] = it;
        if (it != status_.begin() && bad(*std::prev(it), e.wall)) return true;
        if (std::next(it) != status_.end() && bad(e.wall, *std::next(it))) return true;
      } else {
        const auto it = where_[e.wall];
        const auto after = status_.erase(it);
        if (after != status_.begin() && after != status_.end() && bad(*std::prev(after), *after)) return true;
      }
    }
    return false;
  }

 private:
  struct Event {
    IPoint at;
    uint32_t wall;
    bool start;
  };
  static bool less(IPoint p, IPoint q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); }
  bool bad(uint32_t a, uint32_t b) const {
    return refused(geom::segment_contact(ends_[a][0], ends_[a][1], ends_[b][0], ends_[b][1]));
  }
  // Whether wall s lies below wall t where both cross the sweep line (meeting at most at
  // an end): the later starting end against the other's line, or if it lies on that
  // line, the other end; collinear walls by number.
  struct Below {
    const SweepLine* sweep;
    bool operator()(uint32_t s, uint32_t t) const {
      if (s == t) return false;
      const auto& es = sweep->ends_[s];
      const auto& et = sweep->ends_[t];
      const bool s_later = !less(es[0], et[0]);
      const auto& base = s_later ? et : es;
      const auto& other = s_later ? es : et;
      int o = geom::sign(geom::orient(base[0], base[1], other[0]));
      if (o == 0) o = geom::sign(geom::orient(base[0], base[1], other[1]));
      if (o == 0) return s < t;
      return s_later ? o < 0 : o > 0;
    }
  };

  std::vector<std::array<IPoint, 2>> ends_;  // per wall: its lesser end, its greater
  std::vector<Event> events_;
  std::set<uint32_t, Below> status_;
  std::vector<std::set<uint32_t, Below>::iterator> where_;
};

}  // namespace

// The least prefix of walls holding a contact (a binary search by sweeps), then the
// earliest wall the last of it meets. O(n log^2 n).
std::optional<Contact> first_contact_by_sweep(const Source& src) {
  SweepLine sweep(src);
  if (!sweep.any_contact(src.walls.size())) return std::nullopt;
  size_t lo = 2, hi = src.walls.size();  // walls [0, hi) hold a contact; [0, lo - 1) do not
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    if (sweep.any_contact(mid)) hi = mid;
    else lo = mid + 1;
  }
  const uint32_t b = uint32_t(hi - 1);
  const Wall& wb = src.walls[b];
  for (uint32_t a = 0; a < b; ++a) {
    const Wall& wa = src.walls[a];
    const auto kind = geom::segment_contact(src.point(wa.v1), src.point(wa.v2), src.point(wb.v1), src.point(wb.v2));
    if (refused(kind)) return Contact{a, b, kind};
  }
  return Contact{0, b, geom::SegmentContact::kCross};  // unreachable: the prefix holds a contact with b
}

namespace {

// The grid's entries (cell id, wall), made in the order of the walls: a cell id is
// under 2^25 (at most 4,097 cells a side).
using CellEntries = std::vector<std::pair<uint32_t, uint32_t>>;

// Whether the grid's cells (entries sorted by cell) hold so many pairs that testing
// them would cost more than a sweep line.
bool crowded(const CellEntries& entries, size_t walls) {
  constexpr double kPairsPerWall = 64;
  double pairs = 0;
  for (size_t begin = 0; begin < entries.size();) {
    size_t end = begin;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    pairs += double(end - begin) * double(end - begin - 1) / 2;
    begin = end;
  }
  return pairs > kPairsPerWall * double(walls);
}

// Candidate pairs come from a uniform grid: each wall is entered in the cells its
// segment passes through, and walls sharing a cell are tested (test_cell). A grid
// whose cells hold many pairs (long parallel walls side by side) would be quadratic:
// then a sweep line tells whether any contact exists (the valid level's answer), and
// where the first is.
std::vector<Contact> find_contacts_impl(const Source& src, size_t max_count) {
  const auto& walls = src.walls;
  const size_t n = walls.size();
  if (n < 2 || max_count == 0) return {};

  int64_t min_x = INT64_MAX, min_y = INT64_MAX, max_x = INT64_MIN, max_y = INT64_MIN;
  double total_length = 0;
  for (const Wall& w : walls) {
    for (IPoint p : {src.point(w.v1), src.point(w.v2)}) {
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
    const IPoint d = geom::sub(src.point(w.v2), src.point(w.v1));
    total_length += std::sqrt(double(d.x) * double(d.x) + double(d.y) * double(d.y));
  }
  const double extent = double(std::max(max_x - min_x, max_y - min_y)) + 1;
  const double cell = std::max({total_length / n, extent / 4096.0, 1.0});
  const int64_t cells_x = static_cast<int64_t>((max_x - min_x) / cell) + 1;

  CellEntries entries;  // (cell id, wall)
  entries.reserve(n * 3);
  for (uint32_t i = 0; i < n; ++i) {
    IPoint a = src.point(walls[i].v1), b = src.point(walls[i].v2);
    if (b.x < a.x) std::swap(a, b);
    const double ax = (a.x - min_x) / cell, ay = (a.y - min_y) / cell;
    const double bx = (b.x - min_x) / cell, by = (b.y - min_y) / cell;
    const int64_t c0 = static_cast<int64_t>(ax), c1 = static_cast<int64_t>(bx);
    for (int64_t cx = c0; cx <= c1; ++cx) {
      // y-range of the segment inside this column of cells, widened to be conservative.
      auto y_at = [&](double x) { return bx == ax ? ay : ay + (by - ay) * (std::clamp(x, ax, bx) - ax) / (bx - ax); };
      double y0 = y_at(double(cx)), y1 = y_at(double(cx + 1));
      if (y0 > y1) std::swap(y0, y1);
      if (cx == c0) y0 = std::min(y0, ay), y1 = std::max(y1, ay);
      if (cx == c1) y0 = std::min(y0, by), y1 = std::max(y1, by);
      const int64_t r0 = std::max<int64_t>(0, static_cast<int64_t>(y0 - 1e-6));
      const int64_t r1 = static_cast<int64_t>(y1 + 1e-6);
      for (int64_t cy = r0; cy <= r1; ++cy) entries.push_back({uint32_t(cy * cells_x + cx), i});
    }
  }
  radix_sort_by_key(entries);  // by cell, each cell's walls in order
  if (crowded(entries, n)) {
    if (max_count == 1) {
      const std::optional<Contact> first = first_contact_by_sweep(src);
      return first ? std::vector<Contact>{*first} : std::vector<Contact>{};
    }
    if (!SweepLine(src).any_contact(n)) return {};
  }

  ContactList contacts(src, max_count);
  std::vector<uint32_t> cell_walls;
  for (size_t begin = 0; begin < entries.size();) {
    size_t end = begin;
    cell_walls.clear();
    for (; end < entries.size() && entries[end].first == entries[begin].first; ++end) cell_walls.push_back(entries[end].second);
    test_cell(src, cell_walls, contacts);
    begin = end;
  }
  return std::move(contacts).sorted();
}

void check_crossings(const Source& src) {
  const std::vector<Contact> contacts = find_contacts_impl(src, 1);
  if (contacts.empty()) return;
  const Contact& c = contacts.front();
  const Wall& later = src.walls[c.b];
  const std::string other = src.walls[c.a].loc.str();
  if (c.kind == geom::SegmentContact::kCross) throw Error(later.loc, "wall crosses the wall at " + other);
  throw Error(later.loc, "wall overlaps the collinear wall at " + other);
}

// Walking a sector's boundary with the sector on the right, every point is
// entered as often as it is left; otherwise the sector leaks.
std::vector<OpenSector> find_open_sectors_impl(const Source& src) {
  // Each sector's visits (vertex, +1 leaving / -1 entering) gathered by a counting sort
  // on the sector, then sorted by point within the sector: a few each, where one sort
  // of every visit by (sector, point) was a twentieth of compiling a million walls.
  struct Visit {
    uint32_t vertex;
    int32_t delta;
  };
  std::vector<uint32_t> first(src.sectors.size() + 1, 0);
  auto each_visit = [&](auto&& visit) {
    auto side = [&](int sector, int from, int to) {
      if (sector < 0 || size_t(sector) >= src.sectors.size()) return;  // no sector: reported elsewhere
      visit(size_t(sector), Visit{uint32_t(from), +1});
      visit(size_t(sector), Visit{uint32_t(to), -1});
    };
    for (const Wall& w : src.walls) {
      if (w.segment) continue;
      side(w.front.sector, w.v1, w.v2);
      if (w.two_sided()) side(w.back.sector, w.v2, w.v1);
    }
  };
  each_visit([&](size_t sector, Visit) { ++first[sector + 1]; });
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Visit> visits(first.back());
  std::vector<uint32_t> next(first.begin(), first.end() - 1);
  each_visit([&](size_t sector, Visit v) { visits[next[sector]++] = v; });

  auto point_less = [&](const Visit& a, const Visit& b) {
    const IPoint p = src.point(int(a.vertex)), q = src.point(int(b.vertex));
    return std::tie(p.x, p.y) < std::tie(q.x, q.y);
  };
  // Per sector, its open point at the smallest coordinates: the first unbalanced one.
  std::vector<OpenSector> out;
  for (size_t sector = 0; sector + 1 < first.size(); ++sector) {
    const auto begin = visits.begin() + first[sector], end = visits.begin() + first[sector + 1];
    std::sort(begin, end, point_less);
    for (auto run = begin; run != end;) {
      const IPoint p = src.point(int(run->vertex));
      int balance = 0;
      for (; run != end && src.point(int(run->vertex)) == p; ++run) balance += run->delta;
      if (balance != 0) {
        out.push_back({int(sector), p});
        break;
      }
    }
  }
  return out;
}

// A wall written the wrong way round leaves two walls of its sector leaving one of
// its ends and two entering the other: name it, as that is the usual mistake.
std::string reversed_wall_hint(const Source& src, int sector) {
  std::map<std::pair<int64_t, int64_t>, int> balance;
  auto key = [&](int v) { return std::pair{src.point(v).x, src.point(v).y}; };
  for (const Wall& w : src.walls) {
    if (w.segment) continue;
    if (w.front.sector == sector) ++balance[key(w.v1)], --balance[key(w.v2)];
    if (w.two_sided() && w.back.sector == sector) ++balance[key(w.v2)], --balance[key(w.v1)];
  }
  for (const Wall& w : src.walls)
    if (!w.segment && w.front.sector == sector && balance[key(w.v1)] == 2 && balance[key(w.v2)] == -2)
      return "; the wall at " + w.loc.str() +
             " may run the wrong way round (a sector lies on the right of its walls, from the first vertex to the second)";
  return "";
}

void check_sector_closure(const Source& src) {
  for (int s : unused_sectors(src))
    throw Error(src.sectors[s].loc, "sector '" + src.sectors[s].name + "' is not bounded by any wall");
  const std::vector<OpenSector> open = find_open_sectors_impl(src);
  if (open.empty()) return;
  const geom::Vec2 p = geom::to_world(open.front().at);
  const int sector = open.front().sector;
  const Sector& s = src.sectors[size_t(sector)];
  throw Error(s.loc, "sector '" + s.name + "' is not closed: its boundary has an open end at (" + std::to_string(p.x) +
                         ", " + std::to_string(p.y) + ")" + reversed_wall_hint(src, sector));
}

// A two-sided wall shows an upper part where the far ceiling is lower than the
// near one, and a lower part where the far floor is higher; those need textures.
void check_wall_textures(const Source& src) {
  for (const Wall& w : src.walls) {
    if (!w.two_sided()) continue;
    const Sector& f = src.sectors[w.front.sector];
    const Sector& b = src.sectors[w.back.sector];
    const bool both_sky = f.ceiling_texture == kSkyTexture && b.ceiling_texture == kSkyTexture;
    auto need = [&](const Side& side, const Sector& near, const Sector& far, const char* which) {
      if (far.ceiling < near.ceiling && !both_sky && side.upper == kNone)
        throw Error(w.loc, std::string("wall needs an upper texture on its ") + which + " side (sector '" + far.name +
                               "' has a lower ceiling than '" + near.name + "')");
      if (far.floor > near.floor && side.lower == kNone)
        throw Error(w.loc, std::string("wall needs a lower texture on its ") + which + " side (sector '" + far.name +
                               "' has a higher floor than '" + near.name + "')");
    };
    need(w.front, f, b, "front");
    need(w.back, b, f, "back");
  }
}

}  // namespace

std::vector<Contact> find_contacts(const Source& source, size_t max_count) {
  return find_contacts_impl(source, max_count);
}

std::vector<OpenSector> find_open_sectors(const Source& source) { return find_open_sectors_impl(source); }

std::vector<int> unused_sectors(const Source& src) {
  std::vector<bool> used(src.sectors.size(), false);
  for (const Wall& w : src.walls) {
    if (w.segment) continue;
    used[w.front.sector] = true;
    if (w.two_sided()) used[w.back.sector] = true;
  }
  std::vector<int> out;
  for (size_t s = 0; s < src.sectors.size(); ++s)
    if (!used[s] && int(s) != src.default_sector) out.push_back(int(s));
  return out;
}

void check_limits(const Source& src) {
  const FileLoc file{src.path.string(), 0};
  auto fail = [](const FileLoc& loc, std::string_view what) {
    throw Error(loc, std::string(what) + " is beyond the limits a compiled level holds (engine/util/limits.h)");
  };
  // Checked a few times per wall: no message is made unless it fails.
  auto fail_if = [&](bool bad, const FileLoc& loc, std::string_view what) {
    if (bad) fail(loc, what);
  };
  auto name = [&](const std::string& n, const FileLoc& loc, const char* what) {
    if (n.size() > limits::kMaxNameLength)
      fail(loc, std::string(what) + " name of " + std::to_string(n.size()) + " bytes");
  };
  auto coordinate = [&](double v, const FileLoc& loc, const char* what) {
    fail_if(!(std::fabs(v) <= geom::kMaxCoord), loc, what);  // NaN fails too
  };
  if (src.walls.size() > limits::kMaxWalls) throw Error(file, limits::too_many_walls());
  if (src.title.size() > limits::kMaxTitleLength)
    fail(file, "a title of " + std::to_string(src.title.size()) + " bytes");
  coordinate(src.player.pos.x, src.player.loc, "the player start");
  coordinate(src.player.pos.y, src.player.loc, "the player start");
  fail_if(!std::isfinite(src.player.angle), src.player.loc, "the player's angle");
  for (const Texture& t : src.textures) {
    name(t.name, t.loc, "a texture");
    fail_if(t.image.width > kMaxTextureSize || t.image.height > kMaxTextureSize, t.loc, "a texture's size");
  }
  for (const Sector& s : src.sectors) {
    name(s.name, s.loc, "a sector");
    coordinate(s.floor, s.loc, "a floor height");
    coordinate(s.ceiling, s.loc, "a ceiling height");
    fail_if(s.light < 0 || s.light > 255, s.loc, "a light level");
  }
  for (const Wall& w : src.walls)
    for (const Side& side : {w.front, w.back}) {
      bool offsets_fit = std::fabs(side.x_offset) <= limits::kMaxOffset && std::fabs(side.y_offset) <= limits::kMaxOffset;
      const PartOffsets parts = src.parts(side);
      for (int k = 0; k < 3; ++k)
        offsets_fit = offsets_fit && std::fabs(parts.x[k]) <= limits::kMaxOffset && std::fabs(parts.y[k]) <= limits::kMaxOffset;
      fail_if(!offsets_fit, w.loc, "a texture offset");
      fail_if(side.light != kNone && (side.light < 0 || side.light > 255), w.loc, "a wall's light level");
    }
  for (const SpriteImage& i : src.sprite_images) {
    name(i.name, file, "a sprite image");
    if (i.image.width > kMaxTextureSize || i.image.height > kMaxTextureSize || std::abs(i.left) > kMaxTextureSize ||
        std::abs(i.top) > kMaxTextureSize)
      fail(file, "sprite image " + i.name);
  }
  for (const SpriteFrame& f : src.sprites) {
    name(f.name, file, "a sprite frame");
    coordinate(f.drop, file, "a sprite's drop");
  }
  for (const Thing& t : src.things) {
    coordinate(t.pos.x, file, "a thing's position");
    coordinate(t.pos.y, file, "a thing's position");
    fail_if(!std::isfinite(t.angle), file, "a thing's angle");
  }
}

void validate(const Source& src) {
  check_limits(src);
  if (src.walls.empty()) throw Error(FileLoc{src.path.string(), 0}, "the map has no walls");
  for (const Wall& w : src.walls) {
    if (src.point(w.v1) == src.point(w.v2)) throw Error(w.loc, "zero-length wall: both ends are at the same point");
    if (!w.segment && w.front.sector == kNone) throw Error(w.loc, "wall has no front sector");
  }
  check_crossings(src);
  check_sector_closure(src);
  check_wall_textures(src);
}

}  // namespace p3d::map
