#include "engine/map/generate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "engine/util/rng.h"

namespace p3d::map {

namespace {

using geom::IPoint;

// Cells in a square spiral around the origin: ring 0, then ring 1, ...
class Spiral {
 public:
  std::pair<int, int> next() {
    if (ring_ == 0) {
      ring_ = 1;
      side_ = step_ = 0;
      return {0, 0};
    }
    const int r = ring_, len = 2 * r;
    std::pair<int, int> c;
    switch (side_) {  // walk the ring counter-clockwise starting at its south-east corner
      case 0: c = {r, -r + step_}; break;
      case 1: c = {r - step_, r}; break;
      case 2: c = {-r, r - step_}; break;
      default: c = {-r + step_, -r}; break;
    }
    if (++step_ == len) {
      step_ = 0;
      if (++side_ == 4) side_ = 0, ++ring_;
    }
    return c;
  }

 private:
  int ring_ = 0, side_ = 0, step_ = 0;
};

struct CellKey {
  int i, j;
  bool operator==(const CellKey&) const = default;
};
struct CellHash {
  size_t operator()(const CellKey& k) const { return std::hash<int64_t>()((int64_t(k.i) << 32) ^ uint32_t(k.j)); }
};

// "r3_-2" style names; snprintf sidesteps a GCC 12 false -Wrestrict on string concatenation.
std::string cell_name(char prefix, int i, int j, int extra = -1) {
  char buf[48];
  if (extra < 0) std::snprintf(buf, sizeof buf, "%c%d_%d", prefix, i, j);
  else std::snprintf(buf, sizeof buf, "%c%d_%d_%d", prefix, i, j, extra);
  return buf;
}

std::string indexed(char prefix, size_t i) {  // "v12"
  char buf[32];
  std::snprintf(buf, sizeof buf, "%c%zu", prefix, i);
  return buf;
}

class SourceBuilder {
 public:
  SourceBuilder(const GenerateOptions& o, const char* title) {
    src_.path = "(generated)";
    src_.title = title;
    src_.textures = o.textures;
    if (src_.textures.size() < 2) throw Error("map generator needs at least two textures");
  }

  int vertex(int64_t x, int64_t y) { return vertex_fixed({x << geom::kFracBits, y << geom::kFracBits}); }  // map units
  int vertex_fixed(IPoint p) {
    auto [it, added] = index_.try_emplace(key(p), static_cast<int>(src_.vertices.size()));
    if (added) src_.vertices.push_back({p});
    return it->second;
  }
  int sector(const std::string& name, double floor, double ceiling, int light, int floor_tex, int ceiling_tex) {
    src_.sectors.push_back({name, floor, ceiling, light, floor_tex, ceiling_tex, {}});
    return static_cast<int>(src_.sectors.size() - 1);
  }
  void solid(int a, int b, int sector, int tex) {
    Wall w;
    w.v1 = a, w.v2 = b;
    w.front.sector = sector;
    w.front.middle = tex;
    src_.walls.push_back(w);
  }
  void portal(int a, int b, int front, int back, int tex) {
    Wall w;
    w.v1 = a, w.v2 = b;
    w.front = {front, tex, kNone, tex, 0, 0};
    w.back = {back, tex, kNone, tex, 0, 0};
    src_.walls.push_back(w);
  }
  void segment(int a, int b, int tex) {
    Wall w;
    w.v1 = a, w.v2 = b;
    w.segment = true;
    w.front.middle = w.back.middle = tex;
    src_.walls.push_back(w);
  }
  size_t wall_count() const { return src_.walls.size(); }
  int textures() const { return static_cast<int>(src_.textures.size()); }
  Source& source() { return src_; }

 private:
  static uint64_t key(IPoint p) { return uint64_t(uint32_t(p.x)) << 32 | uint32_t(p.y); }  // |x|, |y| < 2^31
  Source src_;
  std::unordered_map<uint64_t, int> index_;
};

// ---- soups -------------------------------------------------------------------

constexpr int kSoupCell = 128, kSoupMargin = 4;

void soup_cell(SourceBuilder& b, uint64_t seed, int ci, int cj, size_t limit) {
  Rng rng(Rng::mix(seed, uint64_t(int64_t(ci)), uint64_t(int64_t(cj))));
  const int64_t x0 = int64_t(ci) * kSoupCell + kSoupMargin, x1 = int64_t(ci + 1) * kSoupCell - kSoupMargin;
  const int64_t y0 = int64_t(cj) * kSoupCell + kSoupMargin, y1 = int64_t(cj + 1) * kSoupCell - kSoupMargin;
  std::vector<std::pair<IPoint, IPoint>> placed;
  for (int n = 0; n < 2 && b.wall_count() < limit; ++n) {
    for (int attempt = 0; attempt < 32; ++attempt) {
      const double angle = rng.uniform(0, 2 * M_PI), length = rng.uniform(24, 100);
      const int64_t ax = x0 + int64_t(rng.below(uint64_t(x1 - x0 + 1)));
      const int64_t ay = y0 + int64_t(rng.below(uint64_t(y1 - y0 + 1)));
      const int64_t bx = ax + std::llround(length * std::cos(angle)), by = ay + std::llround(length * std::sin(angle));
      if (bx < x0 || bx > x1 || by < y0 || by > y1) continue;
      const IPoint a{ax, ay}, c{bx, by};
      bool clear = true;
      for (const auto& [p, q] : placed) clear = clear && geom::segment_contact(a, c, p, q) == geom::SegmentContact::kNone;
      if (!clear) continue;
      placed.push_back({a, c});
      b.segment(b.vertex(ax, ay), b.vertex(bx, by), int(rng.below(uint64_t(b.textures() - 1))));
      break;
    }
  }
}

// ---- rooms -------------------------------------------------------------------

constexpr int kRoomPitch = 256, kRoomGap = 8;  // rooms are 240 wide with 16-unit walls between them

struct Room {
  int sector;
  double floor, ceiling;
  int light, wall_tex;
};

Room room_at(SourceBuilder& b, uint64_t seed, int i, int j) {
  Rng rng(Rng::mix(seed, uint64_t(int64_t(i)), uint64_t(int64_t(j))));
  const int flats = b.textures() - 1;
  Room r;
  r.floor = 8.0 * rng.range(0, 3);
  r.ceiling = r.floor + 96 + 16 * rng.range(0, 6);
  r.light = 96 + 16 * rng.range(0, 8);
  r.wall_tex = int(rng.below(uint64_t(flats)));
  r.sector = b.sector(cell_name('r', i, j), r.floor, r.ceiling, r.light,
                      int(rng.below(uint64_t(flats))), int(rng.below(uint64_t(flats))));
  return r;
}

// A doorway between cell (i, j) and its east (dir 0) or north (dir 1) neighbour, as
// an offset along the shared wall; -1 for none.
int doorway(uint64_t seed, int i, int j, int dir) {
  Rng rng(Rng::mix(seed ^ 0xD00Dull, uint64_t(int64_t(i)) * 2 + dir, uint64_t(int64_t(j))));
  if (rng.below(10) >= 7) return -1;
  return 32 + 16 * rng.range(0, 8);
}

class RoomGrid {
 public:
  RoomGrid(SourceBuilder& b, uint64_t seed, size_t rooms) : b_(b), seed_(seed) {
    Spiral spiral;
    for (size_t n = 0; n < rooms; ++n) order_.push_back(spiral.next());
    for (const auto& [i, j] : order_) rooms_[{i, j}] = room_at(b, seed, i, j);
    for (const auto& [i, j] : order_) build_room(i, j);
    for (const auto& [i, j] : order_) {
      build_door(i, j, 0);
      build_door(i, j, 1);
    }
  }

 private:
  const Room* room(int i, int j) const {
    auto it = rooms_.find({i, j});
    return it == rooms_.end() ? nullptr : &it->second;
  }
  int door(int i, int j, int dir) const {  // only between two existing rooms
    const bool both = room(i, j) && (dir == 0 ? room(i + 1, j) : room(i, j + 1));
    return both ? doorway(seed_, i, j, dir) : -1;
  }

  // One side of a room from p to q (axis-aligned), with an optional doorway at offset `d`
  // from the side's low end.
  void side(const Room& r, int64_t px, int64_t py, int64_t qx, int64_t qy, int d, int door_sector) {
    if (d < 0) return b_.solid(b_.vertex(px, py), b_.vertex(qx, qy), r.sector, r.wall_tex);
    const int64_t lo = (px == qx ? std::min(py, qy) : std::min(px, qx)) + d, hi = lo + 64;
    const bool vertical = px == qx;
    const bool ascending = vertical ? qy > py : qx > px;
    const int64_t a = ascending ? lo : hi, c = ascending ? hi : lo;
    auto at = [&](int64_t t) { return vertical ? b_.vertex(px, t) : b_.vertex(t, py); };
    b_.solid(b_.vertex(px, py), at(a), r.sector, r.wall_tex);
    b_.portal(at(a), at(c), r.sector, door_sector, r.wall_tex);
    b_.solid(at(c), b_.vertex(qx, qy), r.sector, r.wall_tex);
  }

  void build_room(int i, int j) {
    const Room& r = *room(i, j);
    const int64_t x0 = int64_t(i) * kRoomPitch + kRoomGap, x1 = int64_t(i + 1) * kRoomPitch - kRoomGap;
    const int64_t y0 = int64_t(j) * kRoomPitch + kRoomGap, y1 = int64_t(j + 1) * kRoomPitch - kRoomGap;
    // Clockwise with the room on the right: west (up), north (east), east (down), south (west).
    side(r, x0, y0, x0, y1, door(i - 1, j, 0), door_sector(i - 1, j, 0));
    side(r, x0, y1, x1, y1, door(i, j, 1), door_sector(i, j, 1));
    side(r, x1, y1, x1, y0, door(i, j, 0), door_sector(i, j, 0));
    side(r, x1, y0, x0, y0, door(i, j - 1, 1), door_sector(i, j - 1, 1));
    furnish(r, i, j, x0, y0);
  }

  // Doorway sectors are created on first use, so both rooms find the same one.
  int door_sector(int i, int j, int dir) {
    const int d = door(i, j, dir);
    if (d < 0) return kNone;
    auto [it, added] = doors_.try_emplace({i * 2 + dir, j}, kNone);
    if (added) {
      const Room& a = *room(i, j);
      const Room& c = dir == 0 ? *room(i + 1, j) : *room(i, j + 1);
      const double floor = std::max(a.floor, c.floor);
      const double ceiling = std::max(floor + 64, std::min(a.ceiling, c.ceiling) - 8);
      it->second = b_.sector(cell_name('d', i, j, dir), floor,
                             ceiling, (a.light + c.light) / 2, a.wall_tex, a.wall_tex);
    }
    return it->second;
  }

  // The doorway's two jambs through the wall gap (its room-facing sides are portals).
  void build_door(int i, int j, int dir) {
    const int d = door(i, j, dir);
    if (d < 0) return;
    const int s = door_sector(i, j, dir);
    const int tex = room(i, j)->wall_tex;
    if (dir == 0) {  // east: the gap spans x in [xa, xb]
      const int64_t xa = int64_t(i + 1) * kRoomPitch - kRoomGap, xb = xa + 2 * kRoomGap;
      const int64_t lo = int64_t(j) * kRoomPitch + kRoomGap + d, hi = lo + 64;
      b_.solid(b_.vertex(xa, hi), b_.vertex(xb, hi), s, tex);
      b_.solid(b_.vertex(xb, lo), b_.vertex(xa, lo), s, tex);
    } else {  // north: the gap spans y in [ya, yb]
      const int64_t ya = int64_t(j + 1) * kRoomPitch - kRoomGap, yb = ya + 2 * kRoomGap;
      const int64_t lo = int64_t(i) * kRoomPitch + kRoomGap + d, hi = lo + 64;
      b_.solid(b_.vertex(lo, ya), b_.vertex(lo, yb), s, tex);
      b_.solid(b_.vertex(hi, yb), b_.vertex(hi, ya), s, tex);
    }
  }

  // Half the rooms get a square pillar, a quarter a raised platform, always in one
  // quadrant: the room's centre (where cameras and players start) stays clear.
  void furnish(const Room& r, int i, int j, int64_t x0, int64_t y0) {
    Rng rng(Rng::mix(seed_ ^ 0xF00Dull, uint64_t(int64_t(i)), uint64_t(int64_t(j))));
    const int kind = int(rng.below(4));
    if (kind >= 2) return;
    const int64_t size = 32 + 16 * rng.range(0, 2);
    const int quadrant = int(rng.below(4));
    const int slack = int((80 - size) / 8);  // quadrant span 80 = 120 minus 24 to the wall and 16 to the centre
    const int64_t px = x0 + (quadrant & 1 ? 136 : 24) + 8 * rng.range(0, slack);
    const int64_t py = y0 + (quadrant & 2 ? 136 : 24) + 8 * rng.range(0, slack);
    const int a = b_.vertex(px, py), c = b_.vertex(px + size, py), e = b_.vertex(px + size, py + size),
              f = b_.vertex(px, py + size);
    if (kind == 0) {  // pillar: counter-clockwise around it keeps the room on the right
      for (auto [p, q] : {std::pair{a, c}, {c, e}, {e, f}, {f, a}}) b_.solid(p, q, r.sector, r.wall_tex);
      return;
    }
    const double floor = r.floor + 8 * rng.range(1, 3);  // a platform one step up
    const int platform = b_.sector(cell_name('p', i, j), floor,
                                   std::max(r.ceiling, floor + 64), r.light, r.wall_tex, r.wall_tex);
    for (auto [p, q] : {std::pair{a, c}, {c, e}, {e, f}, {f, a}}) b_.portal(p, q, r.sector, platform, r.wall_tex);
  }

  SourceBuilder& b_;
  uint64_t seed_;
  std::vector<std::pair<int, int>> order_;
  std::unordered_map<CellKey, Room, CellHash> rooms_;
  std::unordered_map<CellKey, int, CellHash> doors_;
};

// ---- shapes ------------------------------------------------------------------

// A point in map units rounded to the fixed grid.
IPoint grid_point(double x, double y) { return {std::llround(x * geom::kFixedOne), std::llround(y * geom::kFixedOne)}; }

// Vertices of `points` (clockwise, consecutive repeats dropped) as one closed loop of
// walls with `inside` on their right; `outside` behind (kNone: one-sided).
void closed_loop(SourceBuilder& b, std::vector<IPoint> points, int inside, int outside, int tex) {
  points.erase(std::unique(points.begin(), points.end()), points.end());
  while (points.size() > 1 && points.front() == points.back()) points.pop_back();
  std::vector<int> v;
  v.reserve(points.size());
  for (const IPoint& p : points) v.push_back(b.vertex_fixed(p));
  for (size_t i = 0; i < v.size(); ++i) {
    const int a = v[i], c = v[(i + 1) % v.size()];
    if (outside == kNone) b.solid(a, c, inside, tex);
    else b.portal(a, c, inside, outside, tex);
  }
}

// Points on an ellipse, clockwise from (rx, 0).
std::vector<IPoint> ellipse_points(size_t n, double rx, double ry) {
  std::vector<IPoint> points;
  points.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    const double a = -2 * M_PI * double(i) / double(n);
    points.push_back(grid_point(rx * std::cos(a), ry * std::sin(a)));
  }
  return points;
}

// The radius at which n walls round onto the grid as the circle does: 1,000,000
// at 100,000 walls (each vertex bulges out by an eighth of a grid step), scaled as n^2.
double near_convex_radius(size_t n) { return std::clamp(1e6 * std::pow(double(n) / 1e5, 2), 64.0, 1.5e6); }

std::string fixed_text(int64_t fixed) {  // exact: fixed / 256 has at most 8 decimals
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.8f", fixed / geom::kFixedOne);
  std::string s = buf;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string number_text(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool plain_name(const std::string& s) {
  return !s.empty() && s.find_first_of(" \t#=") == std::string::npos && s != "sky" && s != "-";
}

}  // namespace

Source generate_soup(const GenerateOptions& o) {
  SourceBuilder b(o, "Random segment soup");
  Spiral spiral;
  while (b.wall_count() < o.walls) {
    const auto [i, j] = spiral.next();
    soup_cell(b, o.seed, i, j, o.walls);
  }
  Source& s = b.source();
  const int flat = b.textures() - 1;
  s.sectors.push_back({"(default)", 0, 128, 192, flat, flat, {}});
  s.default_sector = 0;
  s.player = {{0, 0}, 45, {}};
  return std::move(s);
}

Source generate_rooms(const GenerateOptions& o) {
  size_t rooms = o.walls / 15 + 1;  // about 14 walls per room: start low, grow until enough
  for (;;) {
    SourceBuilder b(o, "Random rooms");
    RoomGrid grid(b, o.seed, rooms);
    if (b.wall_count() >= o.walls) {
      Source& s = b.source();
      s.player = {{kRoomPitch / 2.0, kRoomPitch / 2.0}, 0, {}};
      return std::move(s);
    }
    rooms += (o.walls - b.wall_count()) / 15 + 1;
  }
}

const std::vector<std::string>& shape_kinds() {
  static const std::vector<std::string> kinds = {"circle", "ellipse", "jitter", "star", "fan", "spiral", "comb", "rings"};
  return kinds;
}

Source generate_shape(const std::string& kind, const GenerateOptions& o) {
  if (std::find(shape_kinds().begin(), shape_kinds().end(), kind) == shape_kinds().end())
    throw Error("unknown shape " + kind);
  SourceBuilder b(o, kind.c_str());
  Rng rng(o.seed);
  const size_t n = std::max<size_t>(o.walls, 8);
  const int flat = b.textures() - 1;
  auto room = [&](const std::string& name) { return b.sector(name, 0, 128, 160, flat, flat); };
  Source& s = b.source();
  s.player = {{0, 0}, 0, {}};
  const double r = near_convex_radius(n);
  if (kind == "circle" || kind == "ellipse") {
    closed_loop(b, ellipse_points(n, r, kind == "circle" ? r : r / 2.5), room("room"), kNone, 0);
  } else if (kind == "jitter") {
    const double jitter = 2 * M_PI * r / double(n) / 16;
    std::vector<IPoint> points;
    for (size_t i = 0; i < n; ++i) {
      const double a = -2 * M_PI * double(i) / double(n), radius = r + rng.uniform(-jitter, jitter);
      points.push_back(grid_point(radius * std::cos(a), radius * std::sin(a)));
    }
    closed_loop(b, points, room("room"), kNone, 0);
  } else if (kind == "star") {
    std::vector<IPoint> points;
    for (size_t i = 0; i < n; ++i) {
      const double a = -2 * M_PI * double(i) / double(n), radius = i % 2 ? r / 2 : r;
      points.push_back(grid_point(radius * std::cos(a), radius * std::sin(a)));
    }
    closed_loop(b, points, room("room"), kNone, 0);
  } else if (kind == "fan") {
    const int centre = b.vertex(0, 0);
    for (const IPoint& p : ellipse_points(n, r, r)) b.segment(centre, b.vertex_fixed(p), 0);
    s.sectors.push_back({"(default)", 0, 128, 192, flat, flat, {}});
    s.default_sector = 0;
    s.player = {{r / 3, 7}, 0, {}};
  } else if (kind == "spiral") {
    // A corridor 2,000 wide between two spirals, 4,000 apart from turn to turn.
    const double turns = std::max(2.0, std::round(std::sqrt(double(n)) / 16)), width = 2000, pitch = 2 * width, r0 = 2 * width;
    const size_t side = n / 2;
    std::vector<IPoint> inner, outer;
    for (size_t i = 0; i < side; ++i) {
      const double t = 2 * M_PI * turns * double(i) / double(side - 1), radius = r0 + pitch * t / (2 * M_PI);
      inner.push_back(grid_point(radius * std::cos(t), radius * std::sin(t)));
      outer.push_back(grid_point((radius + width) * std::cos(t), (radius + width) * std::sin(t)));
    }
    inner.insert(inner.end(), outer.rbegin(), outer.rend());  // out along the inner spiral, back along the outer
    closed_loop(b, inner, room("corridor"), kNone, 0);
    s.player = {{-(r0 + pitch / 2 + width / 2), 0}, 90, {}};
  } else if (kind == "comb") {
    // Teeth 8 wide and 1,000 long, 8 apart, on a back 1,000 deep.
    const int64_t teeth = int64_t(std::max<size_t>(n / 4, 2)), depth = 1000, length = 1000, x_end = 16 * teeth - 8;
    std::vector<IPoint> points;
    for (int64_t i = 0; i < teeth; ++i)
      for (const auto& [x, y] : {std::pair{16 * i, int64_t{0}}, {16 * i, length}, {16 * i + 8, length}, {16 * i + 8, int64_t{0}}})
        points.push_back(grid_point(double(x), double(y)));
    points.front() = grid_point(0, double(-depth));
    points.back() = grid_point(double(x_end), double(-depth));
    closed_loop(b, points, room("comb"), kNone, 0);
    s.player = {{double(x_end) / 2, -double(depth) / 2}, 90, {}};
  } else {  // rings
    const size_t rings = std::max<size_t>(2, size_t(std::lround(std::sqrt(double(n)) / 32)));
    std::vector<int> sectors;
    for (size_t i = 0; i < rings; ++i) sectors.push_back(b.sector("ring" + std::to_string(i), 8.0 * double(i), 256, 160, flat, flat));
    for (size_t i = 0; i < rings; ++i) {
      const double radius = r * double(i + 1) / double(rings);
      closed_loop(b, ellipse_points(n / rings, radius, radius), sectors[i], i + 1 < rings ? sectors[i + 1] : kNone, int(i % 2));
    }
  }
  return std::move(s);
}

std::string generate_grid_text(const GridOptions& o) {
  if (o.cols < 8 || o.rows < 8) throw Error("grid maps are at least 8x8");
  if (o.texture_files.size() != 7) throw Error("grid maps need 7 texture files");
  Rng rng(o.seed);
  const int cols = o.cols, rows = o.rows;
  std::vector<char> tiles(size_t(cols) * rows, 'A');  // text order: row 0 is the north
  auto at = [&](int c, int r) -> char& { return tiles[size_t(r) * cols + c]; };
  const char walls[] = {'A', 'B', 'C', 'D', 'E'};
  if (o.kind == "caves" || o.kind == "arena") {
    const uint64_t per_thousand = o.kind == "caves" ? 300 : 10;
    for (int r = 1; r < rows - 1; ++r)
      for (int c = 1; c < cols - 1; ++c) at(c, r) = rng.below(1000) < per_thousand ? walls[rng.below(5)] : '.';
  } else {
    // Recursive backtracker on odd cells, then rooms and loops.
    std::vector<std::pair<int, int>> stack{{1, 1}};
    at(1, 1) = '.';
    while (!stack.empty()) {
      const auto [c, r] = stack.back();
      std::pair<int, int> options[4];
      int n = 0;
      for (auto [dc, dr] : {std::pair{2, 0}, {-2, 0}, {0, 2}, {0, -2}}) {
        const int nc = c + dc, nr = r + dr;
        if (nc > 0 && nr > 0 && nc < cols - 1 && nr < rows - 1 && at(nc, nr) != '.') options[n++] = {nc, nr};
      }
      if (n == 0) {
        stack.pop_back();
        continue;
      }
      const auto [nc, nr] = options[rng.below(uint64_t(n))];
      at((c + nc) / 2, (r + nr) / 2) = '.';
      at(nc, nr) = '.';
      stack.push_back({nc, nr});
    }
    for (int k = 0; k < cols * rows / 400; ++k) {  // rooms
      const int w = rng.range(3, 9), h = rng.range(3, 9);
      const int c0 = rng.range(1, std::max(1, cols - w - 2)), r0 = rng.range(1, std::max(1, rows - h - 2));
      for (int r = r0; r < std::min(rows - 1, r0 + h); ++r)
        for (int c = c0; c < std::min(cols - 1, c0 + w); ++c) at(c, r) = '.';
    }
    for (int k = 0; k < cols * rows / 50; ++k) at(rng.range(1, cols - 2), rng.range(1, rows - 2)) = '.';  // loops
    for (char& t : tiles)  // wall textures in patches
      if (t != '.') t = 'A';
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
        if (at(c, r) != '.') at(c, r) = walls[Rng::mix(o.seed, uint64_t(c / 8), uint64_t(r / 8)) % 5];
  }
  // The player faces east from an empty cell near the middle.
  for (int d = 0; d < cols + rows; ++d) {
    bool placed = false;
    for (int r = rows / 2 - d; r <= rows / 2 + d && !placed; ++r)
      for (int c = cols / 2 - d; c <= cols / 2 + d && !placed; ++c)
        if (c > 0 && r > 0 && c < cols - 1 && r < rows - 1 && at(c, r) == '.') at(c, r) = '>', placed = true;
    if (placed) break;
  }
  std::string out = "# Generated by mapgen. See maps/FORMAT.md.\n";
  const char* title = o.kind == "caves" ? "Caves" : o.kind == "arena" ? "Arena" : "Labyrinth";
  out += std::string("title ") + title + "\ncell " + std::to_string(o.cell) + "\n";
  const char* names[] = {"wall0", "wall1", "wall2", "wall3", "wall4", "floor", "ceiling"};
  for (int i = 0; i < 7; ++i) out += std::string("texture ") + names[i] + " " + o.texture_files[i] + "\n";
  out += "floor 0 floor\nceiling " + std::to_string(o.cell * 3 / 2) + " ceiling\nlight 192\n";
  for (int i = 0; i < 5; ++i) out += std::string("tile ") + walls[i] + " " + names[i] + "\n";
  out += "map\n";
  for (int r = 0; r < rows; ++r) {
    out.append(&tiles[size_t(r) * cols], size_t(cols));
    out += '\n';
  }
  return out + "end\n";
}

std::vector<Texture> builtin_textures() {
  const std::pair<const char*, uint32_t> colours[] = {
      {"red", image::rgba(170, 70, 50)},   {"green", image::rgba(70, 150, 80)}, {"blue", image::rgba(70, 90, 170)},
      {"sand", image::rgba(190, 170, 120)}, {"grey", image::rgba(120, 120, 120)}};
  std::vector<Texture> textures;
  for (const auto& [name, base] : colours) {
    Texture t{name, image::Image(16, 16), {}};
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const bool line = x == 0 || y == 0 || (x == 8 && y < 8) || (y == 8);
        t.image.at(x, y) = line ? image::rgba(30, 30, 30) : base ^ uint32_t((x * 7 + y * 13) & 15);
      }
    textures.push_back(std::move(t));
  }
  return textures;
}

std::string to_map_text(const Source& s, const std::vector<std::string>& texture_files) {
  std::string out;
  auto line = [&](const std::string& text) { out += text + '\n'; };
  line("# Generated by mapgen. See maps/FORMAT.md.");
  if (!s.title.empty()) line("title " + s.title);
  std::vector<std::string> tex_names(s.textures.size()), sector_names(s.sectors.size());
  for (size_t i = 0; i < s.textures.size(); ++i) {
    tex_names[i] = plain_name(s.textures[i].name) ? s.textures[i].name : indexed('t', i);
    line("texture " + tex_names[i] + " " + texture_files.at(i));
  }
  if (s.sky_texture != kNone) line("sky " + tex_names[s.sky_texture]);
  auto sector_fields = [&](const Sector& sec) {
    return "floor=" + number_text(sec.floor) + " ceiling=" + number_text(sec.ceiling) +
           " light=" + std::to_string(sec.light) + " floor_tex=" + tex_names[sec.floor_texture] + " ceiling_tex=" +
           (sec.ceiling_texture == kSkyTexture ? std::string("sky") : tex_names[sec.ceiling_texture]);
  };
  for (size_t i = 0; i < s.sectors.size(); ++i) {
    if (int(i) == s.default_sector) {
      line("default " + sector_fields(s.sectors[i]));
      continue;
    }
    sector_names[i] = plain_name(s.sectors[i].name) ? s.sectors[i].name : indexed('s', i);
    line("sector " + sector_names[i] + " " + sector_fields(s.sectors[i]));
  }
  for (size_t i = 0; i < s.vertices.size(); ++i)
    line("vertex v" + std::to_string(i) + " " + fixed_text(s.vertices[i].pos.x) + " " + fixed_text(s.vertices[i].pos.y));
  auto side_fields = [&](const Side& sd, const std::string& prefix) {
    std::string f;
    if (sd.upper != kNone) f += " " + prefix + "upper=" + tex_names[sd.upper];
    if (sd.middle != kNone) f += " " + prefix + "middle=" + tex_names[sd.middle];
    if (sd.lower != kNone) f += " " + prefix + "lower=" + tex_names[sd.lower];
    if (sd.x_offset != 0) f += " " + prefix + "xoff=" + number_text(sd.x_offset);
    if (sd.y_offset != 0) f += " " + prefix + "yoff=" + number_text(sd.y_offset);
    return f;
  };
  for (const Wall& w : s.walls) {
    const std::string ends = indexed('v', size_t(w.v1)) + " " + indexed('v', size_t(w.v2));
    if (w.segment) {
      std::string f = " texture=" + tex_names[w.front.middle];
      if (w.front.x_offset != 0) f += " xoff=" + number_text(w.front.x_offset);
      if (w.front.y_offset != 0) f += " yoff=" + number_text(w.front.y_offset);
      line("segment " + ends + f);
      continue;
    }
    std::string f = " front=" + sector_names[w.front.sector] + side_fields(w.front, "");
    if (w.two_sided()) {
      f += " back=" + sector_names[w.back.sector];
      Side back = w.back;  // the parser defaults back upper/lower to the front's: write only differences
      if (back.upper == w.front.upper) back.upper = kNone;
      if (back.lower == w.front.lower) back.lower = kNone;
      f += side_fields(back, "back_");
    }
    if (w.flags == (kUnpegUpper | kUnpegLower)) f += " unpeg=both";
    else if (w.flags & kUnpegUpper) f += " unpeg=upper";
    else if (w.flags & kUnpegLower) f += " unpeg=lower";
    line("wall " + ends + f);
  }
  line("player " + number_text(s.player.pos.x) + " " + number_text(s.player.pos.y) + " " + number_text(s.player.angle));
  for (const Thing& t : s.things)
    line("thing " + std::to_string(t.type) + " " + number_text(t.pos.x) + " " + number_text(t.pos.y) + " " +
         number_text(t.angle));
  return out;
}

}  // namespace p3d::map
