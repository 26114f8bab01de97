// Camera, per-frame statistics and per-column hit records: the plain data that
// flows into and out of every renderer.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/geom/geom.h"
#include "engine/image/frame.h"
#include "engine/level/level.h"

namespace p3d::render {

using geom::Vec2;
// The frame every renderer draws into (image/frame.h).
using image::Frame;

constexpr double kEyeHeight = 41;  // Doom's view height above the floor
// Cameras must stay within this many map units of the origin (4x the map range), and
// so must eye heights: the texture arithmetic is sized for it. Tools check it.
constexpr double kMaxCameraCoord = 4 * geom::kMaxCoord;

struct Camera {
  Vec2 pos{0, 0};
  double z = kEyeHeight;  // absolute eye height
  double angle = 0;       // degrees, counter-clockwise from east (+x)
  double fov = 90;        // horizontal field of view, degrees
};

// A camera standing at pos with its eye `eye_height` above the floor found there.
Camera camera_at(const level::Level& level, Vec2 pos, double angle, double eye_height = kEyeHeight, double fov = 90);

struct RenderStats {
  uint64_t nodes_visited = 0;    // BSP nodes whose splitter was tested
  uint64_t subtrees_culled = 0;  // subtrees of those not entered: their box projects onto closed (or no) columns
  uint64_t fragments_drawn = 0;  // fragments that drew at least one column
  uint64_t columns_closed = 0;
  uint64_t pixels_written = 0;   // by walls, floors, ceilings and sky: each pixel once, front to back
  uint64_t masked_pixels = 0;    // by masked middle textures, over what is behind them
  uint64_t sprites_drawn = 0;    // things whose sprite wrote at least one pixel
  uint64_t sprite_pixels = 0;
  bool early_exit = false;       // every column was closed: the traversal stopped there
  // Ray-based renderers:
  uint64_t rays = 0;
  uint64_t steps = 0;            // cells (DDA) or marching steps (sphere) over all rays
  uint64_t max_steps = 0;        // most steps of one ray

  void add_ray(uint64_t ray_steps) {
    ++rays;
    steps += ray_steps;
    max_steps = std::max(max_steps, ray_steps);
  }
};

// Per screen column: the wall that closes it (its index in the level; the wall's
// `source` is the number users know), its perpendicular distance, and the BSP
// fragment it was drawn from (-1 for non-BSP renderers).
struct ColumnHit {
  int32_t wall = -1;
  double dist = 0;
  int32_t fragment = -1;
};
using ColumnHits = std::vector<ColumnHit>;

// Optional per-frame outputs, filled only when asked for: the closing hit of every
// column (capture --columns, the tests), the order in which fragments were drawn
// (BSP renderers; pictures), and how often each pixel was written (overdraw).
struct Probe {
  bool want_columns = false, want_order = false, want_writes = false;
  ColumnHits columns;
  std::vector<uint32_t> order;   // fragment indices, in the order they first drew a column
  std::vector<uint16_t> writes;  // per pixel, row-major
};

}  // namespace p3d::render
