// Whether wall pieces bound a convex region, decided exactly: the test that makes a
// BSP cell a leaf (the compiler) and the invariant every leaf keeps (the checker).
//
// Pieces bound a convex region when each lies in the closed half-plane on its inward
// side (the side facing the region) of every other's line. Then a ray meets the
// pieces it sees from their inward side only where it leaves the region, and those
// it sees from behind (two-sided walls, plain segments) only where it enters it:
// at most one of each, the ones from behind first. So a renderer may draw a leaf's
// pieces in one step, those seen from behind before the others.
//
// The test sorts the pieces by the direction of their line turned so that the inward
// side is on the left (exact: directions are integer), and checks each group of one
// direction (they must share one line) against the next group round the circle. That
// is enough: consecutive groups that accept each other meet at points X_i with each
// group's pieces between its two X's, so the X's make a convex polygon (or an open
// convex chain turning by at most half a turn), whose edge lines all support the
// region. O(k log k).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/geom/geom.h"

namespace p3d::bsp {

struct ConvexTest {
  bool convex = false;
  // Not convex: a piece whose line has another piece strictly on its far side (and
  // the region's pieces, or a probe point of them, strictly on its inward side): a
  // splitter that leaves pieces on both sides.
  size_t witness = 0;
};

// Pieces is an accessor with:
//   size_t size() const;
//   const geom::Line& line(size_t i) const;  // the line of piece i's wall (front on its right)
//   int side(size_t i) const;                // the side facing the region: 0 front, 1 back, -1 either
//   int end_side(size_t i, int k, const geom::Line& l) const;  // exact side of end k: +1 left, -1 right, 0 on
// On success `sides` holds every piece's inward side (chosen for those free to face either way).
template <typename Pieces>
ConvexTest convex_region(const Pieces& pieces, std::vector<int8_t>& sides, std::vector<uint32_t>& order) {
  const size_t n = pieces.size();
  sides.assign(n, 0);
  if (n == 0) return {true, 0};
  // Most cells tested are not convex, and show it at once: a piece whose line has
  // pieces strictly on both of its sides, whichever side faces the region. O(k).
  constexpr size_t kQuickLines = 2;
  for (size_t i = 0; i < std::min(n, kQuickLines); ++i) {
    bool left = false, right = false;
    for (size_t j = 0; j < n && !(left && right); ++j)
      for (int k = 0; k < 2; ++k) {
        const int side = pieces.end_side(j, k, pieces.line(i));
        left |= side > 0, right |= side < 0;
      }
    if (left && right) return {false, i};
  }
  // Probe points for the pieces free to face either way: two ends of piece 0 and an end
  // of any piece off its line. Three points not on one line, so every line misses one;
  // a probe off a piece's line is another piece's, and in a convex set it lies on the
  // inward side.
  struct Probe {
    size_t piece;
    int end;
  };
  Probe probes[3] = {{0, 0}, {0, 1}, {0, 0}};
  int probe_count = 2;
  for (size_t i = 1; i < n && probe_count == 2; ++i)
    for (int k = 0; k < 2; ++k)
      if (pieces.end_side(i, k, pieces.line(0)) != 0) {
        probes[probe_count++] = {i, k};
        break;
      }
  if (probe_count == 2) {  // all on one line: each lies on every other's line
    for (size_t i = 0; i < n; ++i) sides[i] = int8_t(std::max(0, pieces.side(i)));
    return {true, 0};
  }
  // Inward direction: the line's direction turned so that the region is on its left.
  auto direction = [&](size_t i) {
    const geom::IPoint d = pieces.line(i).d;
    return sides[i] == 1 ? d : geom::IPoint{-d.x, -d.y};  // the front lies on the right of d
  };
  for (size_t i = 0; i < n; ++i) {
    int side = pieces.side(i);
    for (int p = 0; side < 0 && p < 3; ++p) {
      const int s = pieces.end_side(probes[p].piece, probes[p].end, pieces.line(i));
      if (s != 0) side = s < 0 ? 0 : 1;
    }
    sides[i] = int8_t(side < 0 ? 0 : side);
  }
  auto upper = [](geom::IPoint d) { return d.y > 0 || (d.y == 0 && d.x > 0); };
  auto angle_less = [&](uint32_t a, uint32_t b) {
    const geom::IPoint da = direction(a), db = direction(b);
    const bool ua = upper(da), ub = upper(db);
    if (ua != ub) return ua;
    const int64_t c = geom::cross(da, db);
    return c != 0 ? c > 0 : a < b;
  };
  order.resize(n);
  for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
  std::sort(order.begin(), order.end(), angle_less);
  auto same_direction = [&](uint32_t a, uint32_t b) {
    const geom::IPoint da = direction(a), db = direction(b);
    return upper(da) == upper(db) && geom::cross(da, db) == 0;
  };
  // Piece j against the line of piece i: a violation when an end of j lies strictly
  // on i's far side.
  auto beyond = [&](size_t i, size_t j) {
    const int far = sides[i] == 0 ? 1 : -1;  // the back lies on the left of the line
    return pieces.end_side(j, 0, pieces.line(i)) == far || pieces.end_side(j, 1, pieces.line(i)) == far;
  };
  // Groups of one direction: [begin, end) of order.
  std::vector<std::pair<size_t, size_t>> groups;
  for (size_t b = 0; b < n;) {
    size_t e = b + 1;
    while (e < n && same_direction(order[b], order[e])) ++e;
    groups.push_back({b, e});
    for (size_t k = b + 1; k < e; ++k) {  // parallel and facing alike: one line, or one lies behind the other
      if (beyond(order[b], order[k])) return {false, order[b]};
      if (beyond(order[k], order[b])) return {false, order[k]};
    }
    b = e;
  }
  const size_t g = groups.size();
  for (size_t a = 0; a < g && g > 1; ++a) {
    const size_t b = (a + 1) % g;
    if (g == 2 && a == 1) break;  // two groups: one pair
    const uint32_t la = order[groups[a].first], lb = order[groups[b].first];
    for (size_t k = groups[b].first; k < groups[b].second; ++k)
      if (beyond(la, order[k])) return {false, la};
    for (size_t k = groups[a].first; k < groups[a].second; ++k)
      if (beyond(lb, order[k])) return {false, lb};
  }
  return {true, 0};
}

}  // namespace p3d::bsp
