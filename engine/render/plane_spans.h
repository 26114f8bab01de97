// Floors and ceilings gathered into rows (Doom's visplanes and R_MakeSpans). The
// canvas files each column's run of a plane as the walk meets it; at the end of the
// frame a plane's runs, column by column, become horizontal spans, so a row of a
// plane costs one depth and one light however many pixels it has.
//
// A plane holds at most one run per column. A run touching the one already filed in
// its column joins it (a floor continuing over a two-sided line at the same height);
// any other starts a further plane of the same key. Nothing is ever dropped: the
// planes and their runs grow as needed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace p3d::render {

// What a plane pixel depends on besides (x, y): so runs with equal keys may share spans.
struct PlaneKey {
  double height;
  int texture;
  int light;  // the light map at depth zero (light_start)
  bool operator==(const PlaneKey&) const = default;
};
struct PlaneKeyHash {
  size_t operator()(const PlaneKey& key) const;
};

class PlaneSpans {
 public:
  // Forgets every plane; runs may then be filed in columns [x0, x1) of rows [0, height).
  void begin(int x0, int x1, int height);

  // Files rows [y0, y1) of column x, y0 < y1, as showing `key`.
  void add(const PlaneKey& key, int x, int y0, int y1) { add_to(head(key), x, y0, y1); }
  // The same in two steps, for a caller that files many runs of one key: the key's
  // plane (valid until begin), then runs into it.
  int plane_of(const PlaneKey& key) { return head(key); }
  // Inline where the plane's last run is in the column before, the common case (a wall's
  // columns file their planes left to right).
  void add_to(int plane, int x, int y0, int y1) {
    Plane& p = planes_[size_t(plane)];
    if (x != p.x_max + 1 || x <= p.x_min) return add_to_any_column(plane, x, y0, y1);
    p.x_max = x;
    run(p, x) = {y0, y1};
  }

  // Calls span(key, y, xa, xb) for each maximal run [xa, xb) of row y within one plane:
  // every filed pixel exactly once.
  template <typename SpanFn>
  void for_each_span(SpanFn&& span);

 private:
  struct Run {
    int32_t top, bottom;  // rows [top, bottom); top == bottom: none
  };
  struct Plane {
    PlaneKey key;
    bool is_head;      // the first of its key (the table points at it)
    int next;          // the next plane of the same key, or -1
    int x_min, x_max;  // its runs in columns [x_min, x_max] are set (some empty), the others not
    size_t runs;       // its runs in runs_, one per column of [x0_, x1_)
  };

  int head(const PlaneKey& key);  // the first plane of the key, made when there is none
  void add_to_any_column(int plane, int x, int y0, int y1);  // add_to's every other case
  int make_plane(const PlaneKey& key, bool is_head);
  void cover(Plane& p, int x);  // widens [x_min, x_max] to x, emptying the columns between
  Run& run(const Plane& p, int x) { return runs_[p.runs + size_t(x - x0_)]; }

  int x0_ = 0, x1_ = 0, height_ = 0;
  std::vector<Plane> planes_;
  std::vector<Run> runs_;  // the first runs_used_ belong to this frame's planes
  size_t runs_used_ = 0;
  std::vector<int> table_;  // open addressing: key hash -> first plane, -1 empty
  int cached_ = -1;         // the last head looked up (runs of one wall come in a row)
  std::vector<int> span_start_;  // for_each_span: per row, the column its open span began in
};

template <typename SpanFn>
void PlaneSpans::for_each_span(SpanFn&& span) {
  span_start_.resize(size_t(height_));
  for (const Plane& p : planes_) {
    // Walk the columns left to right: rows in the last run but not this one end their
    // span here; rows in this run but not the last start one.
    Run last{0, 0};
    for (int x = p.x_min; x <= p.x_max + 1; ++x) {
      Run now = x <= p.x_max ? run(p, x) : Run{0, 0};
      if (now.top >= now.bottom) now = {0, 0};
      if (now.top == last.top && now.bottom == last.bottom) continue;  // no span ends or starts
      for (int y = last.top; y < std::min(last.bottom, now.top); ++y) span(p.key, y, span_start_[size_t(y)], x);
      for (int y = std::max(last.top, now.bottom); y < last.bottom; ++y) span(p.key, y, span_start_[size_t(y)], x);
      for (int y = now.top; y < std::min(now.bottom, last.top); ++y) span_start_[size_t(y)] = x;
      for (int y = std::max(now.top, last.bottom); y < now.bottom; ++y) span_start_[size_t(y)] = x;
      last = now;
    }
  }
}

}  // namespace p3d::render
