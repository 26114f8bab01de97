// The canvas under Doom's rules (View::doom: WAD levels at a 90-degree view): the
// pixels Chocolate Doom draws, from its own arithmetic (doom_rules.h), each still a
// function of the surface and its place alone, so every renderer draws the same.
//
// - Walls (R_StoreWallRange, R_RenderSegLoop): the column's scale (R_ScaleFromGlobalAngle
//   at Doom's column angle), rows by its 20.12 edges (rows whose top lies within the
//   wall), texel rows by R_DrawColumn's 16.16 stepping from the texture's pegged height
//   (& 127), texel columns by rw_offset - tan * rw_distance (& the texture's width mask),
//   light by scalelight, ceiling and floor rows as Doom marks them.
// - Flats (R_MapPlane, R_DrawSpan): each span steps from its first column in Doom's
//   packed 6.10 position; light by zlight.
// - The sky (R_DrawPlanes): Doom's column angle >> 22, rows by its 16.16 step.
// - Sprites (R_ProjectSprite, R_DrawVisSprite, R_DrawMaskedColumn) and masked middle
//   textures (R_RenderMaskedSegRange), clipped by Doom's drawseg rules (R_DrawSprite):
//   a wall is behind a sprite when its scales are all smaller, or some are and the
//   sprite stands on the wall's near side; silhouettes as Doom keeps them.
#include <algorithm>
#include <bit>
#include <climits>

#include "engine/render/column_major.h"
#include "engine/render/draw.h"
#include "engine/render/texel_loops.h"
#include "engine/render/translation.h"

namespace p3d::render {

using doom::Angle;
using doom::Fixed;
using doom::kFracBits;
using doom::kFracUnit;
using level::kNone;
using level::kSky;
using play::fixed_div;
using play::fixed_mul;
using play::kAngleToFineShift;
using play::kFineAngles;
using play::kFineSine;

namespace {

constexpr int kHeightUnit = 1 << doom::kHeightBits;

Fixed fixed_of(double v) { return doom::to_fixed(v); }
Fixed fixed_of(int64_t fine) { return Fixed(fine * (kFracUnit / 256)); }  // a 1/256-unit coordinate

// Doom's texture width mask: the largest power of two within the width, less one.
int width_mask(int width) { return int(std::bit_floor(unsigned(std::max(width, 1)))) - 1; }

// Doom's texel row within a column of `height` rows: (v >> 16) & 127, and for our
// textures of other heights, that row wrapped to the texture.
inline size_t doom_row(uint32_t v, int height) {
  const uint32_t row = (v >> kFracBits) & 127;
  return row < uint32_t(height) ? row : row % uint32_t(height);
}

}  // namespace

// A side's seg as this frame's view sees it: one of Doom's (Level::doom_segs), or the
// whole side from its start (seg null).
void Canvas::set_up_doom_side(DoomSide& d, uint32_t wall, int side, const level::Level::DoomSeg* seg) {
  const level::Level& l = *level_;
  d.silhouette_ready = d.wall_ready = false;
  const level::Wall& w = l.walls[wall];
  const geom::IPoint p1 = side == 0 ? w.p1 : w.p2, p2 = side == 0 ? w.p2 : w.p1;
  d.v2x = fixed_of(p2.x), d.v2y = fixed_of(p2.y);
  Angle angle;
  Fixed offset = 0, end_x = d.v2x, end_y = d.v2y;  // the seg's own end
  if (seg) {
    d.v1x = seg->v1x, d.v1y = seg->v1y, angle = seg->angle;
    offset = doom_->crispy ? doom::crispy_seg_offset(d.v1x, d.v1y, fixed_of(p1.x), fixed_of(p1.y)) : seg->offset;
    end_x = seg->v2x, end_y = seg->v2y;
  } else {
    d.v1x = fixed_of(p1.x), d.v1y = fixed_of(p1.y);
    angle = doom::seg_angle(double(p2.x - p1.x), double(p2.y - p1.y));
  }
  const doom::Tables& tb = *doom_;
  const int sector = w.sides[side].sector;
  d.precision = sector != kNone ? doom::wall_precision(tb, int64_t(state_->sectors[size_t(sector)].ceiling) -
                                                               int64_t(state_->sectors[size_t(sector)].floor))
                                : doom::WallPrecision{};
  if (tb.crispy) {  // measured from the split points put back onto the wall's line
    const Fixed ax = fixed_of(p1.x), ay = fixed_of(p1.y);
    auto onto_line = [&](Fixed& x, Fixed& y) {
      if ((x != ax || y != ay) && (x != d.v2x || y != d.v2y))
        doom::crispy_onto_line(x, y, ax, ay, play::wrap_sub(d.v2x, ax), play::wrap_sub(d.v2y, ay));
    };
    Fixed sx = d.v1x, sy = d.v1y;
    onto_line(sx, sy);
    onto_line(end_x, end_y);
    d.seg = doom::make_crispy_seg(view_->fx, view_->fy, view_->fangle, sx, sy, end_x, end_y, angle);
  } else {
    d.seg = doom::make_seg(tb, view_->fx, view_->fy, view_->fangle, d.v1x, d.v1y, angle);
  }
  d.seg.offset = play::wrap_add(d.seg.offset, offset);
  // Its drawseg's scales: at the first and last columns Doom gives the whole side.
  int x1, x2;
  doom::seg_columns(tb, view_->fx, view_->fy, view_->fangle, fixed_of(p1.x), fixed_of(p1.y), d.v2x, d.v2y, x1, x2);
  if (x1 < x2) {
    const Fixed max = d.precision.max_scale;
    const Fixed a = doom::scale_at(tb, d.seg, view_->fangle, x1, max), b = doom::scale_at(tb, d.seg, view_->fangle, x2 - 1, max);
    d.low_scale = std::min(a, b), d.high_scale = std::max(a, b);
  } else {
    d.low_scale = d.high_scale = 0;
  }
}

// R_StoreWallRange's set-up of a side's wall for this frame: its heights, which planes
// it marks, its parts' textures, offsets and light, none of which varies by column.
void Canvas::set_up_doom_wall(DoomSide& d, const WallHit& hit, int near) {
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  const level::SectorState& s = state_->sectors[near];
  d.wall_ready = true;
  d.near = near;
  d.far = w.far_sector(hit.side);
  const level::SectorState* b = d.far != kNone ? &state_->sectors[d.far] : nullptr;
  const Fixed viewz = view_->fz;
  const Fixed front_floor = fixed_of(s.floor);
  // Doom's fixed_t heights wrap (a sector at the map's limits, seen from the other one).
  d.worldtop = play::wrap_sub(fixed_of(s.ceiling), viewz);
  d.worldbottom = play::wrap_sub(front_floor, viewz);
  d.worldhigh = d.worldlow = 0;
  d.mark_ceiling = d.mark_floor = true;
  d.top_part = d.bottom_part = false;
  if (b) {
    d.worldhigh = play::wrap_sub(fixed_of(b->ceiling), viewz);
    d.worldlow = play::wrap_sub(fixed_of(b->floor), viewz);
    if (s.ceiling_texture == kSky && b->ceiling_texture == kSky) d.worldtop = d.worldhigh;  // the sky hack
    d.mark_floor = d.worldlow != d.worldbottom || b->floor_texture != s.floor_texture || b->light != s.light;
    d.mark_ceiling = d.worldhigh != d.worldtop || b->ceiling_texture != s.ceiling_texture || b->light != s.light;
    if (b->ceiling <= s.floor || b->floor >= s.ceiling) d.mark_ceiling = d.mark_floor = true;  // a closed door
    d.top_part = d.worldhigh < d.worldtop;
    d.bottom_part = d.worldlow > d.worldbottom;
  }
  d.ceiling_plane = view_->eye < s.ceiling || s.ceiling_texture == kSky;
  d.floor_plane = view_->eye > s.floor;
  d.planes[0] = d.planes[1] = kPlaneNotFound;
  d.x_offset = fixed_of(side.x_offset + state_->scroll(hit.wall, hit.side));
  d.start_map = doom::start_map(side.light != kNone ? side.light : s.light, w.contrast, 0);
  auto height_of = [&](int part) {
    const int texture = state_->texture(hit.wall, hit.side, part);
    return texture >= 0 ? Fixed(level_->textures[size_t(texture)].height) << kFracBits : 0;
  };
  Fixed mid[3];  // each part's texture mid before the side's offsets: Doom's pegging
  mid[level::kMiddlePart] =
      (w.flags & level::kUnpegLower) ? play::wrap_add(d.worldbottom, height_of(level::kMiddlePart)) : d.worldtop;
  mid[level::kUpperPart] = (w.flags & level::kUnpegUpper) || !b
                               ? d.worldtop
                               : play::wrap_add(d.worldhigh, height_of(level::kUpperPart));
  mid[level::kLowerPart] = (w.flags & level::kUnpegLower) ? d.worldtop : d.worldlow;
  const Fixed row_offset = fixed_of(side.y_offset);
  for (int part = 0; part < 3; ++part) {
    d.textures[part] = state_->shown(state_->texture(hit.wall, hit.side, part));
    d.part_x[part] = fixed_of(level_->part_x(side, part));
    d.mid[part] = play::wrap_add(mid[part], play::wrap_add(row_offset, fixed_of(level_->part_y(side, part))));
  }
}

struct Canvas::DoomRun {
  DoomSide* side;
  uint32_t side_index;  // in doom_sides_, for the steps
  doom::Seg seg;
  Fixed max_scale, x_offset;
  int start_map;
  // The wall edges' rows: centery - world * scale in fixed point of `bits` fraction
  // bits (vanilla's 20.12 in 32 bits; Crispy's in 64, fewer bits for taller sectors),
  // the centre and the heights already shifted into it.
  bool crispy;
  int bits;
  int64_t center;
  Fixed top, bottom, high, low;  // worldtop, worldbottom, worldhigh, worldlow
  bool mark_ceiling, mark_floor, ceiling_plane, floor_plane, one_sided;
  bool upper, lower;  // a top or bottom part to draw
  DoomPart parts[3];
};

Canvas::DoomRun Canvas::doom_run(DoomSide& ds, const WallHit& hit, int near) {
  if (!ds.wall_ready || ds.near != near) set_up_doom_wall(ds, hit, near);
  const doom::Tables& t = *doom_;
  const int shift = t.crispy ? kFracBits - ds.precision.height_bits : 4;
  DoomRun r;
  r.side = &ds;
  r.side_index = uint32_t(&ds - doom_sides_.data());
  r.seg = ds.seg;
  r.max_scale = ds.precision.max_scale;
  r.x_offset = ds.x_offset;
  r.start_map = ds.start_map;
  r.crispy = t.crispy;
  r.bits = t.crispy ? ds.precision.height_bits : doom::kHeightBits;
  r.center = t.crispy ? int64_t(t.centeryfrac) >> shift : int64_t(t.centeryfrac >> 4);
  r.top = ds.worldtop >> shift, r.bottom = ds.worldbottom >> shift;
  r.high = ds.worldhigh >> shift, r.low = ds.worldlow >> shift;
  r.mark_ceiling = ds.mark_ceiling, r.mark_floor = ds.mark_floor;
  r.ceiling_plane = ds.ceiling_plane, r.floor_plane = ds.floor_plane;
  r.one_sided = ds.far == kNone;
  r.upper = ds.top_part && ds.textures[level::kUpperPart] != kNone;
  r.lower = ds.bottom_part && ds.textures[level::kLowerPart] != kNone;
  for (int part = 0; part < 3; ++part) {
    DoomPart& p = r.parts[part];
    p.texture = ds.textures[part];
    p.tex = p.texture != kNone ? &level_->textures[size_t(p.texture)] : nullptr;
    p.width_mask = p.tex ? width_mask(p.tex->width) : 0;
    p.mid = ds.mid[part], p.x = ds.part_x[part];
    p.vector = p.tex && t.crispy && indexed_ && columns_pending_ && !painting_planes_ && p.tex->height <= 256 &&
               std::has_single_bit(unsigned(p.tex->height));
    p.rows_log2 = p.tex ? std::countr_zero(unsigned(p.tex->height)) : 0;
  }
  return r;
}

// The edges' rows: centery - world * scale in the run's fixed point (Crispy's in 64
// bits, vanilla's wrapping in 32), rounded up for a top edge (the first row whose top
// lies within the wall) and down for a bottom one.
void Canvas::doom_edge_rows(const DoomRun& r, const Fixed* scales, size_t n, EdgeRows& rows) const {
  const int64_t round_up = (int64_t(1) << r.bits) - 1;
  if (rows.rows.size() < 4 * n) rows.rows.resize(4 * n);  // only grown: a resize up fills
  rows.top = rows.rows.data(), rows.bottom = rows.top + n, rows.high = rows.bottom + n, rows.low = rows.high + n;
  WallEdges edges{r.center, r.bits, r.crispy};
  auto add = [&](int32_t* out, Fixed world, int64_t round) {
    edges.world[edges.count] = world, edges.round[edges.count] = round, edges.rows[edges.count++] = out;
  };
  add(rows.top, r.top, round_up);
  add(rows.bottom, r.bottom, 0);
  if (r.upper) add(rows.high, r.high, 0);
  if (r.lower) add(rows.low, r.low, round_up);
  if (vector_scales_) return doom_edge_rows_avx512(scales, n, edges);
  wall_edge_rows(scales, n, edges);
}

// One column of R_RenderSegLoop. [top, bottom) are the open rows: Doom's ceilingclip + 1
// and floorclip.
[[gnu::always_inline]] inline bool Canvas::doom_column(DoomRun& r, int x, Fixed scale, const EdgeRows& edges, size_t k,
                                                       int& top, int& bottom) {
  const doom::Tables& t = *doom_;
  drawn_doom_side_ = r.side_index;
  // What a drawn part's texels need, worked out for the column's first drawn part: most
  // hits draw none (an opening between sectors), and the step is a division.
  uint32_t iscale = 0;
  int map = 0;
  Fixed column = 0;
  auto draw_part = [&](int y0, int y1, int part) {
    if (y0 >= y1 || dry_) return;
    if (iscale == 0) {
      iscale = 0xFFFFFFFFu / uint32_t(scale);
      map = fixed_or(doom::wall_map(t, r.start_map, scale));
      column = play::wrap_add(doom::texture_column(t, r.seg, x), r.x_offset);
    }
    const DoomPart& p = r.parts[part];
    doom_wall_rows(x, y0, y1, p, int32_t(play::wrap_add(column, p.x) >> kFracBits), iscale, map);
  };
  const int ceiling_clip = top - 1, floor_clip = bottom;
  int yl = edges.top[k];
  if (yl < ceiling_clip + 1) yl = ceiling_clip + 1;
  int ceiling_end = ceiling_clip + 1;  // the rows the ceiling took
  if (r.mark_ceiling) {
    const int y1 = ceiling_end = std::min(yl, floor_clip);
    if (r.ceiling_plane)
      doom_plane_span(*r.side, x, ceiling_clip + 1, y1, true);
    else
      fill_span(x, ceiling_clip + 1, y1, Fill::kVoid);  // Doom marks nothing: we fill it
  }
  int yh = edges.bottom[k];
  if (yh >= floor_clip) yh = floor_clip - 1;
  // Where a wall's edges cross (its top row below its bottom one) both planes claim the
  // rows between: the ceiling keeps them, as Doom draws its ceilings after its floors.
  const int floor_start = r.mark_floor ? std::max(yh + 1, ceiling_end) : floor_clip;
  if (r.mark_floor) {
    if (r.floor_plane)
      doom_plane_span(*r.side, x, floor_start, floor_clip, false);
    else
      fill_span(x, floor_start, floor_clip, Fill::kVoid);
  }

  const bool middle = r.parts[level::kMiddlePart].texture != kNone;
  if (r.one_sided) {
    if (!middle)
      planes_to_horizon(x, yl, yh + 1, r.side->near);
    else
      draw_part(yl, yh + 1, level::kMiddlePart);
    top = bottom;
    return false;
  }
  int new_ceiling = ceiling_clip, new_floor = floor_clip;
  if (r.upper) {
    int mid = edges.high[k];
    if (mid >= floor_clip) mid = floor_clip - 1;
    if (mid >= yl) {
      // An upper part reaching below the floor's first row: Doom draws its planes last.
      draw_part(yl, std::min(mid + 1, floor_start), level::kUpperPart);
      new_ceiling = mid;
    } else {
      new_ceiling = yl - 1;
    }
  } else if (r.mark_ceiling) {
    new_ceiling = yl - 1;
  }
  if (r.lower) {
    int mid = edges.low[k];
    if (mid <= new_ceiling) mid = new_ceiling + 1;
    if (mid <= yh) {
      draw_part(mid, yh + 1, level::kLowerPart);
      new_floor = mid;
    } else {
      new_floor = yh + 1;
    }
  } else if (r.mark_floor) {
    new_floor = yh + 1;
  }
  top = new_ceiling + 1;
  bottom = std::max(new_floor, top);  // crossed: the opening is closed
  return middle && top < bottom;
}

bool Canvas::draw_hit_doom(int x, const WallHit& hit, int near, int& top, int& bottom) {
  DoomRun run = doom_run(doom_side(hit.wall, hit.side, hit.t), hit, near);
  const Fixed scale = doom::scale_at(*doom_, run.seg, view_->fangle, x, run.max_scale);
  doom_edge_rows(run, &scale, 1, run_edges_);
  return doom_column(run, x, scale, run_edges_, 0, top, bottom);
}

// The hits of a seg with a sector in front of it, as runs: the seg looked up once, its
// numbers copied out once, then each column as draw_wall draws it.
void Canvas::draw_doom_walls(const WallHits& hits, std::vector<int>& closed) {
  const int near = level_->walls[hits.wall].sides[hits.side].sector;
  for (size_t i = 0; i < hits.size();) {
    const WallHit first = hits[i];
    if (near == kNone) {  // a segment: its near sector is the column's own
      if (draw_wall(hits.x[i], first)) closed.push_back(hits.x[i]);
      ++i;
      continue;
    }
    double t_low, t_high;
    DoomRun run = doom_run(doom_side(first.wall, first.side, first.t, &t_low, &t_high), first, near);
    size_t end = i + 1;  // the hits in the seg's range of t: all when the side is one seg
    if (t_low == -INFINITY && t_high == INFINITY) end = hits.size();
    while (end < hits.size() && hits.t[end] >= t_low && hits.t[end] < t_high) ++end;
    // The run's scales first: their divisions overlap one another rather than each
    // waiting behind the last column's work.
    run_scales_.resize(end - i);
    if (vector_scales_) {  // eight at a time, their sines gathered
      doom_scales_avx512(hits.x.data() + i, end - i, doom::seg_sines(*doom_, run.seg, view_->fangle), doom_->projection,
                         run.seg.distance, run.max_scale, run_scales_.data());
    } else {
      for (size_t k = i; k < end; ++k)
        run_scales_[k - i] = doom::scale_at(*doom_, run.seg, view_->fangle, hits.x[k], run.max_scale);
    }
    doom_edge_rows(run, run_scales_.data(), end - i, run_edges_);
    const int far = run.side->far;  // the run's: one wall side
    for (size_t k = i; k < end; ++k) {
      const int x = hits.x[k];
      const Fixed scale = run_scales_[k - i];
      if (record_step(x, WallHitRef{hits, k}, near, far,
                      [&](int& top, int& bottom) { return doom_column(run, x, scale, run_edges_, k - i, top, bottom); }))
        closed.push_back(x);
    }
    i = end;
  }
}

// Crispy Doom's R_DrawColumn: texel rows wrap at the texture's own height (its
// tutti-frutti fix), the column as composed.
inline void Canvas::crispy_wall_rows(int x, int y0, int y1, const level::Texture& tex, int u, Fixed v0, uint32_t iscale,
                                     int map) {
  const uint8_t* source = tex.indices.data() + size_t(u) * size_t(tex.height);
  const int64_t period = int64_t(tex.height) << kFracBits;
  // A power of two divides 2^32: the 32-bit v wraps alike. Else v and the step are
  // reduced modulo the height first, so that one subtraction keeps v in range.
  const bool pow2 = (tex.height & (tex.height - 1)) == 0;
  const int64_t v = pow2 ? int64_t(uint32_t(v0)) : level::floor_mod(int64_t(v0), period);
  const int64_t step = pow2 ? int64_t(iscale) : int64_t(iscale) % period;
  const size_t light = size_t(map) * limits::kPaletteSize;
  if (indexed_) return indexed_wall_column(x, y0, y1 - y0, v, step, period, source, level_->light_indices.data() + light);
  wrapped_column(pixel(x, y0), size_t(view_->width), y1 - y0, v, step, period,
                 PalettedColumn{source, level_->light_maps.data() + light});
}

void Canvas::doom_wall_rows(int x, int y0, int y1, const DoomPart& part, int32_t column, uint32_t iscale, int map) {
  if (part.vector && y1 - y0 >= kVectorColumnRows) {  // the commonest case, as crispy_wall_rows draws it
    count(x, y0, y1);
    const uint8_t* source = part.tex->indices.data() + (size_t(column & part.width_mask) << part.rows_log2);
    return wall_column_vbmi(column_pixel(x, y0), y1 - y0, uint32_t(part.mid) + uint32_t(y0 - doom_->centery) * iscale,
                            iscale, part.rows_log2, source,
                            level_->light_indices.data() + size_t(map) * limits::kPaletteSize);
  }
  if (part.texture == kNone) return fill_span(x, y0, y1, Fill::kMissingTexture);
  count(x, y0, y1);
  if (painting_planes_) mark_painted(x, y0, y1, kNoPlane);
  const level::Texture& tex = *part.tex;
  const int texture = part.texture;
  const int u = column & part.width_mask;
  uint32_t v = uint32_t(part.mid) + uint32_t(y0 - doom_->centery) * iscale;
  if (doom_->crispy) return crispy_wall_rows(x, y0, y1, tex, u, Fixed(v), iscale, map);
  // Doom's own 128 rows of the column when the level has them, else the column wrapped.
  const int64_t doom_start = size_t(texture) < level_->doom_column_start.size() ? level_->doom_column_start[size_t(texture)] : kNone;
  const uint8_t* source = doom_start >= 0 ? level_->doom_columns.data() + doom_start + int64_t(u) * 128
                                          : tex.indices.data() + size_t(u) * size_t(tex.height);
  const int h = doom_start >= 0 ? 128 : tex.height;
  const size_t light = size_t(map) * limits::kPaletteSize;
  if ((h & (h - 1)) == 0) {  // rows & (h - 1), as rows & 127 at most: Doom's 16.16 v wraps alike
    const int64_t period = int64_t(std::min(h, 128)) << kFracBits;
    if (indexed_) return indexed_wall_column(x, y0, y1 - y0, v, iscale, period, source, level_->light_indices.data() + light);
    return wrapped_column(pixel(x, y0), size_t(view_->width), y1 - y0, v, iscale, period,
                          PalettedColumn{source, level_->light_maps.data() + light});
  }
  auto draw = [&](auto* out, size_t pitch, const auto* lit) {
    for (int y = y0; y < y1; ++y, out += pitch, v += iscale) *out = lit[source[doom_row(v, h)]];
  };
  if (indexed_) return draw(column_pixel(x, y0), column_pitch_, level_->light_indices.data() + light);
  draw(pixel(x, y0), size_t(view_->width), level_->light_maps.data() + light);
}

// Crispy Doom's R_MapPlane: each pixel's texel from its column's distance from the
// centre column, so that a span's start does not matter. Crispy skips the centre row
// (it draws nothing there): it is drawn as the row below.
Canvas::CrispyRow Canvas::crispy_row(const PlaneKey& key, int y, int xa, int xb) const {
  const doom::Tables& t = *doom_;
  const Fixed height = std::abs(play::wrap_sub(fixed_of(key.height), view_->fz));
  const int dy = std::max(1, std::abs(t.centery - y));
  const Fixed distance = fixed_mul(height, t.yslope[size_t(y)]);
  const Fixed view_cos = play::cosine(view_->fangle), view_sin = play::sine(view_->fangle);
  CrispyRow r{&level_->textures[size_t(key.texture)], y, xa, xb};
  r.xstep = uint32_t(fixed_mul(view_sin, height) / dy), r.ystep = uint32_t(fixed_mul(view_cos, height) / dy);
  const uint32_t dx = uint32_t(xa - t.centerx);
  r.xfrac = uint32_t(view_->fx) + uint32_t(fixed_mul(view_cos, distance)) + dx * r.xstep;
  r.yfrac = 0u - uint32_t(view_->fy) - uint32_t(fixed_mul(view_sin, distance)) + dx * r.ystep;
  r.map = fixed_or(doom::flat_map(t, doom::start_map(key.light, 0, 0), distance));
  return r;
}

void Canvas::draw_crispy_row(const CrispyRow& r) {
  const level::Texture& tex = *r.texture;
  // Doom's flats are 64 x 64, row-major; ours column-major, of any size.
  const bool flat64 = tex.width == 64 && tex.height == 64;
  auto texel = [&](uint32_t fx, uint32_t fy) -> size_t {
    const uint32_t u = (fx >> kFracBits) & 63, v = (fy >> kFracBits) & 63;
    return flat64 ? size_t(u << 6 | v) : size_t(tex.wrap_u(u)) * size_t(tex.height) + size_t(tex.wrap_v(v));
  };
  const uint8_t* indices = tex.indices.data();
  const size_t light = size_t(r.map) * limits::kPaletteSize;
  if (indexed_ && flat64)  // u = (xfrac >> 16) & 63 and v = (yfrac >> 16) & 63 at u * 64 + v
    return indexed_flat_row(index_pixel(r.xa, r.y), r.xb - r.xa, {r.xfrac, r.xstep, kFracBits - 6, 63u << 6},
                            {r.yfrac, r.ystep, kFracBits, 63u}, indices, level_->light_indices.data() + light);
  uint32_t xfrac = r.xfrac, yfrac = r.yfrac;
  auto draw = [&](auto* out, const auto* lit) {
    for (int x = r.xa; x < r.xb; ++x, xfrac += r.xstep, yfrac += r.ystep) *out++ = lit[indices[texel(xfrac, yfrac)]];
  };
  if (indexed_) return draw(index_pixel(r.xa, r.y), level_->light_indices.data() + light);
  draw(pixel(r.xa, r.y), level_->light_maps.data() + light);
}

// The flats' spans under Crispy's rules, a batch of rows set up before any is drawn: the
// set-up's two divisions then overlap from row to row rather than each waiting behind
// the row drawn before.
void Canvas::draw_crispy_flats() {
  constexpr size_t kBatch = 32;
  crispy_rows_.clear();
  auto draw_batch = [&] {
    for (const CrispyRow& r : crispy_rows_) draw_crispy_row(r);
    crispy_rows_.clear();
  };
  planes_.for_each_span([&](const PlaneKey& key, int y, int xa, int xb) {
    crispy_rows_.push_back(crispy_row(key, y, xa, xb));
    if (crispy_rows_.size() == kBatch) draw_batch();
  });
  draw_batch();
}

// R_MapPlane and R_DrawSpan: pixels [xa, xb) of row y of a span from column start.
void Canvas::doom_plane_pixels(const PlaneKey& key, int y, int xa, int xb, int start) {
  const doom::Tables& t = *doom_;
  if (t.crispy) return draw_crispy_row(crispy_row(key, y, xa, xb));
  const level::Texture& tex = level_->textures[size_t(key.texture)];
  const Fixed height = std::abs(play::wrap_sub(fixed_of(key.height), view_->fz));
  const Fixed distance = fixed_mul(height, t.yslope[size_t(y)]);
  const Fixed xstep = fixed_mul(distance, base_x_scale_), ystep = fixed_mul(distance, base_y_scale_);
  const Fixed length = fixed_mul(distance, t.distscale[size_t(start)]);
  const Angle angle = (view_->fangle + t.xtoviewangle[size_t(start)]) >> kAngleToFineShift;
  const Fixed xfrac = play::wrap_add(view_->fx, fixed_mul(kFineSine[angle + kFineAngles / 4], length));
  const Fixed yfrac = play::wrap_sub(play::wrap_sub(0, view_->fy), fixed_mul(kFineSine[angle], length));
  const int map = fixed_or(doom::flat_map(t, doom::start_map(key.light, 0, 0), distance));
  const uint32_t step = ((uint32_t(xstep) << 10) & 0xFFFF0000u) | ((uint32_t(ystep) >> 6) & 0xFFFFu);
  uint32_t position = (((uint32_t(xfrac) << 10) & 0xFFFF0000u) | ((uint32_t(yfrac) >> 6) & 0xFFFFu)) +
                      step * uint32_t(xa - start);
  // Doom's flats are 64 x 64, row-major; ours column-major, of any size.
  const bool flat64 = tex.width == 64 && tex.height == 64;
  auto texel = [&](uint32_t p) -> size_t {
    const uint32_t u = p >> 26, v = (p >> 10) & 63;
    return flat64 ? size_t(u << 6 | v) : size_t(tex.wrap_u(u)) * size_t(tex.height) + size_t(tex.wrap_v(v));
  };
  const uint8_t* indices = tex.indices.data();
  if (indexed_ && flat64)  // Doom's packed position: u its top 6 bits, v bits 10..15, at u * 64 + v
    return indexed_flat_row(index_pixel(xa, y), xb - xa, {position, step, 20, 63u << 6}, {position, step, 10, 63u},
                            indices, level_->light_indices.data() + size_t(map) * limits::kPaletteSize);
  if (indexed_) {
    const uint8_t* lit = level_->light_indices.data() + size_t(map) * limits::kPaletteSize;
    uint8_t* out = index_pixel(xa, y);
    for (int x = xa; x < xb; ++x, position += step) *out++ = lit[indices[texel(position)]];
    return;
  }
  const uint32_t* lit = level_->light_maps.data() + size_t(map) * limits::kPaletteSize;
  uint32_t* out = pixel(xa, y);
  for (int x = xa; x < xb; ++x, position += step) *out++ = lit[indices[texel(position)]];
}

// The planes filed this frame as spans, row by row, each the whole run of one plane
// (equal keys) in its row: PlaneSpans' spans of one key that touch are joined.
void Canvas::doom_gather_spans() {
  const int h = view_->height;
  doom_span_scratch_.clear();
  doom_span_y_.clear();
  planes_.for_each_span([this](const PlaneKey& key, int y, int xa, int xb) {
    doom_span_scratch_.push_back({&key, xa, xb});
    doom_span_y_.push_back(y);
  });
  doom_row_first_.assign(size_t(h) + 1, 0);
  for (int y : doom_span_y_) ++doom_row_first_[size_t(y) + 1];
  for (int y = 0; y < h; ++y) doom_row_first_[size_t(y) + 1] += doom_row_first_[size_t(y)];
  doom_spans_.resize(doom_span_scratch_.size());
  std::vector<uint32_t>& next = doom_span_next_;
  next.assign(doom_row_first_.begin(), doom_row_first_.end());
  for (size_t i = 0; i < doom_span_scratch_.size(); ++i) doom_spans_[next[size_t(doom_span_y_[i])]++] = doom_span_scratch_[i];
  // Each row's spans left to right, touching ones of one key joined.
  size_t out = 0;
  for (int y = 0; y < h; ++y) {
    const auto first = doom_spans_.begin() + std::ptrdiff_t(doom_row_first_[size_t(y)]);
    const auto end = doom_spans_.begin() + std::ptrdiff_t(doom_row_first_[size_t(y) + 1]);
    std::sort(first, end, [](const DoomSpan& a, const DoomSpan& b) { return a.xa < b.xa; });
    doom_row_first_[size_t(y)] = uint32_t(out);
    for (auto it = first; it != end; ++it) {
      if (out > doom_row_first_[size_t(y)] && doom_spans_[out - 1].xb == it->xa && *doom_spans_[out - 1].key == *it->key)
        doom_spans_[out - 1].xb = it->xb;
      else
        doom_spans_[out++] = *it;
    }
  }
  doom_row_first_[size_t(h)] = uint32_t(out);
  doom_spans_.resize(out);
}

// Draws the spans; one that starts at this strip's left edge starts where its run of
// the same plane begins in the strips to the left (their spans are gathered: finish()).
void Canvas::doom_draw_spans() {
  for (int y = 0; y < view_->height; ++y) {
    for (uint32_t i = doom_row_first_[size_t(y)]; i < doom_row_first_[size_t(y) + 1]; ++i) {
      const DoomSpan& s = doom_spans_[i];
      int start = s.xa;
      if (s.xa == x0_) {
        for (const Canvas* c = left_; c; c = c->left_) {
          const uint32_t first = c->doom_row_first_[size_t(y)], end = c->doom_row_first_[size_t(y) + 1];
          if (first == end) break;
          const DoomSpan& last = c->doom_spans_[end - 1];
          if (last.xb != c->x1_ || !(*last.key == *s.key)) break;
          start = last.xa;
          if (last.xa != c->x0_) break;
        }
      }
      doom_plane_pixels(*s.key, y, s.xa, s.xb, start);
    }
  }
}

void Canvas::start_painted_planes() {
  painting_planes_ = true;
  painted_keys_.clear();
  painted_plane_.assign(size_t(view_->width) * size_t(view_->height), kNoPlane);
}

void Canvas::mark_painted(int x, int y0, int y1, uint32_t id) {
  for (int y = y0; y < y1; ++y) painted_plane_[size_t(y) * size_t(view_->width) + size_t(x)] = id;
}

// The painter's flats: the spans of each row are its runs of one plane.
void Canvas::draw_painted_planes() {
  painting_planes_ = false;
  const int w = view_->width;
  for (int y = 0; y < view_->height; ++y) {
    const uint32_t* row = painted_plane_.data() + size_t(y) * size_t(w);
    for (int x = 0; x < w;) {
      int end = x + 1;
      while (end < w && row[end] == row[x]) ++end;
      if (row[x] != kNoPlane) doom_plane_pixels(painted_keys_[row[x]], y, x, end, x);
      x = end;
    }
  }
}

// R_DrawPlanes' sky: texture column (viewangle + xtoviewangle[x]) >> 22, rows from
// Doom's skytexturemid by its step, full bright.
void Canvas::doom_sky_span(int x, int y0, int y1) {
  const level::Texture& tex = level_->textures[size_t(level_->sky_texture)];
  const Angle angle = (view_->fangle + doom_->xtoviewangle[size_t(x)]) >> 22;
  const int u = int(angle) & width_mask(tex.width);
  const int* rows = doom_sky_rows_.data();  // & 127 (Doom's own rows) or wrapped to the texture
  const int64_t doom_start = !doom_->crispy && size_t(level_->sky_texture) < level_->doom_column_start.size()
                                 ? level_->doom_column_start[size_t(level_->sky_texture)]
                                 : kNone;
  const uint8_t* indices = doom_start >= 0 ? level_->doom_columns.data() + doom_start + int64_t(u) * 128
                                           : tex.indices.data() + size_t(u) * size_t(tex.height);
  if (indexed_) {
    const uint8_t* lit = level_->light_indices.data();  // full bright
    const int texels = doom_start >= 0 ? 128 : tex.height;
    if (columns_pending_ && y1 - y0 >= kVectorColumnRows && !doom_sky_row_bytes_.empty())
      return tabled_column_vbmi(column_pixel(x, y0), y1 - y0, doom_sky_row_bytes_.data() + y0, indices, texels, lit);
    uint8_t* out = column_pixel(x, y0);
    for (int y = y0; y < y1; ++y, out += column_pitch_) *out = lit[indices[rows[y]]];
    return;
  }
  const uint32_t* light_map = level_->light_maps.data();
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width) *out = light_map[indices[rows[y]]];
}

// R_ProjectSprite.
bool Canvas::project_doom_sprite(const level::Level& level, const level::State& state, const View& view,
                                 uint32_t thing, Sprite& s) {
  const level::ShownThing& th = state.things[thing];
  if (th.frame == kNone) return false;
  const doom::Tables& t = *view.doom;
  const Fixed gx = fixed_of(th.pos.x), gy = fixed_of(th.pos.y);
  const Fixed tr_x = play::wrap_sub(gx, view.fx), tr_y = play::wrap_sub(gy, view.fy);
  const Fixed view_cos = play::cosine(view.fangle), view_sin = play::sine(view.fangle);
  const Fixed tz = play::wrap_sub(fixed_mul(tr_x, view_cos), -fixed_mul(tr_y, view_sin));
  if (tz < doom::kMinZ) return false;
  const Fixed xscale = fixed_div(t.projection, tz);
  Fixed tx = -play::wrap_add(fixed_mul(tr_y, view_cos), -fixed_mul(tr_x, view_sin));
  if (std::abs(int64_t(tx)) > (int64_t(tz) << 2)) return false;
  const level::SpriteFrame& frame = level.sprite_frames[size_t(th.frame)];
  const Angle seen = doom::point_to_angle(view.fx, view.fy, gx, gy);
  const int rotation = int((seen - doom::to_angle(th.angle) + (play::kAngle45 / 2) * 9) >> 29);
  const level::SpriteImage& image = level.sprite_images[size_t(frame.image[rotation])];
  const int translation = (th.flags & level::kShownTranslation) >> level::kShownTranslationShift;
  const level::Texture& tex = translated_texture(level, size_t(image.texture), translation);
  s.flip = frame.flip[rotation];
  // Crispy measures a mirrored picture's offset from its other edge.
  const int left = t.crispy && s.flip ? tex.width - image.left : image.left;
  tx = play::wrap_sub(tx, Fixed(left) << kFracBits);
  const int x1 = play::wrap_add(t.centerxfrac, fixed_mul(tx, xscale)) >> kFracBits;
  if (x1 > view.width) return false;
  tx = play::wrap_add(tx, Fixed(tex.width) << kFracBits);
  const int x2 = (play::wrap_add(t.centerxfrac, fixed_mul(tx, xscale)) >> kFracBits) - 1;
  if (x2 < 0) return false;
  if (t.crispy && x1 >= x2) return false;  // Crispy drops a sprite one column wide
  s.thing = thing;
  s.depth = double(tz) / kFracUnit;
  s.texture = &tex;
  s.x0 = std::max(x1, 0);
  s.x1 = std::min(x2, view.width - 1);
  if (s.x0 > s.x1) return false;
  s.scale = xscale;
  s.gx = gx, s.gy = gy;
  s.gz = fixed_of(th.z);
  s.gzt = play::wrap_add(s.gz, Fixed(image.top) << kFracBits);
  s.texture_mid = play::wrap_sub(s.gzt, view.fz);
  const Fixed iscale = fixed_div(kFracUnit, xscale);
  s.x_start = x1;
  s.start_frac = s.flip ? (Fixed(tex.width) << kFracBits) - 1 : 0;
  s.x_step = s.flip ? -iscale : iscale;
  const int light = th.sector != kNone ? state.sectors[size_t(th.sector)].light : 255;
  s.light_map = fixed_or(level, state, frame.bright ? 0 : doom::wall_map(t, doom::start_map(light, 0, 0), xscale));
  s.fuzz = (th.flags & level::kShownShadow) != 0;
  return true;
}

namespace {

// Most of a map's things lie behind the view or far to its sides. R_ProjectSprite's
// two tests done first in doubles, with a margin of a whole unit where the fixed-point
// roundings differ by less than a thousandth, reject those before its fixed-point
// work; a thing 16384 units away or more, where Doom's wrapping arithmetic might
// differ, is left to it.
struct PlainlyUnseen {
  double x, y, cos, sin;
  explicit PlainlyUnseen(const View& view)
      : x(double(view.fx) / kFracUnit),
        y(double(view.fy) / kFracUnit),
        cos(double(play::cosine(view.fangle)) / kFracUnit),
        sin(double(play::sine(view.fangle)) / kFracUnit) {}
  bool operator()(Vec2 p) const {
    const double dx = p.x - x, dy = p.y - y;
    if (std::abs(dx) + std::abs(dy) >= 16384) return false;
    const double tz = dx * cos + dy * sin, tx = dx * sin - dy * cos;
    const double min_z = double(doom::kMinZ) / kFracUnit;
    return tz < min_z - 1 || std::abs(tx) > 4 * tz + 4;
  }
};

}  // namespace

void Canvas::project_doom_sprites(const level::Level& level, const level::State& state, const View& view,
                                  std::vector<Sprite>& out) {
  out.clear();
  const PlainlyUnseen unseen(view);
  Sprite s;
  for (uint32_t i = 0; i < state.things.size(); ++i) {
    const level::ShownThing& th = state.things[i];
    if (th.frame != kNone && !unseen(th.pos) && project_doom_sprite(level, state, view, i, s)) out.push_back(s);
  }
}

void Canvas::add_projected_sprites(std::span<const Sprite> sprites, bool all) {
  for (Sprite s : sprites) {
    s.x0 = std::max(s.x0, x0_), s.x1 = std::min(s.x1, x1_ - 1);
    if (s.x0 > s.x1) continue;
    sprites_.push_back(s);
    for (int x = s.x0; x <= s.x1; ++x) columns_[x].sprite = true;
  }
  sprites_known_ = all;
}


// R_DrawMaskedColumn over the opaque runs of texture column u.
bool Canvas::doom_masked_column(int x, int top, int bottom, const level::Texture& tex, int u, Fixed top_screen,
                                Fixed scale, uint32_t iscale, Fixed mid, int light_map, uint64_t& counter, bool fuzz) {
  // A wall's clip rows may lie off the screen (Doom's clip arrays do too): the screen's own bound.
  top = std::max(top, 0), bottom = std::min(bottom, view_->height);
  bool drew = false;
  const size_t column = size_t(u) * size_t(tex.height);
  const size_t map = size_t(light_map) * limits::kPaletteSize;
  auto post = [&](int first, int end) {
    const Fixed top_y = play::wrap_add(top_screen, Fixed(uint32_t(scale) * uint32_t(first)));
    const Fixed bottom_y = play::wrap_add(top_y, Fixed(uint32_t(scale) * uint32_t(end - first)));
    int y0 = (top_y + kFracUnit - 1) >> kFracBits, y1 = ((bottom_y - 1) >> kFracBits) + 1;
    y0 = std::max(y0, top), y1 = std::min(y1, bottom);
    if (fuzz) y0 = std::max(y0, 1), y1 = std::min(y1, view_->height - 1);  // as Doom: the rows read stay on screen
    if (y0 >= y1) return;
    drew = true;
    counter += uint64_t(y1 - y0);
    if (writes_)
      for (int y = y0; y < y1; ++y) ++(*writes_)[size_t(y) * size_t(view_->width) + size_t(x)];
    if (fuzz) return draw_fuzz(x, y0, y1);
    uint32_t v = uint32_t(play::wrap_sub(mid, Fixed(first) << kFracBits)) + uint32_t(y0 - doom_->centery) * iscale;
    const int length = end - first;
    // Most posts' rows stay within the post: no row to clamp, the plain column loop.
    const uint64_t last = uint64_t(v & ((128u << kFracBits) - 1)) + uint64_t(iscale) * uint64_t(y1 - 1 - y0);
    if (indexed_ && (last >> kFracBits) < uint64_t(length))
      return wrapped_column(column_pixel(x, y0), column_pitch_, y1 - y0, int64_t(v), int64_t(iscale),
                            int64_t(128) << kFracBits,
                            IndexedColumn{tex.indices.data() + column + size_t(first), level_->light_indices.data() + map});
    auto row = [&](uint32_t vv) {  // within the post; past its end, its last row (Doom reads the pad byte)
      const int r = int((vv >> kFracBits) & 127);
      return column + size_t(first + std::min(r, length - 1));
    };
    if (indexed_) {
      const uint8_t* lit = level_->light_indices.data() + map;
      uint8_t* out = column_pixel(x, y0);
      for (int y = y0; y < y1; ++y, out += column_pitch_, v += iscale) *out = lit[tex.indices[row(v)]];
    } else {
      uint32_t* out = pixel(x, y0);
      for (int y = y0; y < y1; ++y, out += view_->width, v += iscale) *out = lit(tex, row(v), light_map);
    }
  };
  if (!tex.holes) {
    post(0, tex.height);
    return drew;
  }
  for (uint32_t r = tex.run_start[size_t(u)]; r < tex.run_start[size_t(u) + 1]; ++r) post(tex.runs[r].first, tex.runs[r].end);
  return drew;
}

// R_RenderMaskedSegRange, one column.
void Canvas::doom_draw_masked(int x, const Step& m) {
  const level::Wall& w = level_->walls[m.hit.wall];
  const level::Side& side = w.sides[m.hit.side];
  const level::SectorState& s = state_->sectors[m.near];
  const level::SectorState& b = state_->sectors[m.far];
  const int texture = state_->shown(state_->texture(m.hit.wall, m.hit.side, level::kMiddlePart));
  const level::Texture& tex = level_->textures[size_t(texture)];
  const doom::Tables& t = *doom_;
  const DoomSide& ds = doom_side(m);
  const Fixed scale = doom::scale_at(t, ds.seg, view_->fangle, x, ds.precision.max_scale);
  // Heights at the map's limits less the eye wrap, as Doom's fixed_t did.
  Fixed mid = (w.flags & level::kUnpegLower)
                  ? play::wrap_sub(play::wrap_add(fixed_of(std::max(s.floor, b.floor)), Fixed(tex.height) << kFracBits), view_->fz)
                  : play::wrap_sub(fixed_of(std::min(s.ceiling, b.ceiling)), view_->fz);
  mid = play::wrap_add(mid, fixed_of(side.y_offset + level_->part_y(side, level::kMiddlePart)));
  const Fixed column = play::wrap_add(doom::texture_column(t, ds.seg, x),
                                      fixed_of(side.x_offset + level_->part_x(side, level::kMiddlePart) +
                                               state_->scroll(m.hit.wall, m.hit.side)));
  const int u = int(column >> kFracBits) & width_mask(tex.width);
  const int light = side.light != kNone ? side.light : s.light;
  const int map = fixed_or(doom::wall_map(t, doom::start_map(light, w.contrast, 0), scale));
  const Fixed top_screen = play::wrap_sub(t.centeryfrac, fixed_mul(mid, scale));
  doom_masked_column(x, m.top, m.bottom, tex, std::min(u, tex.width - 1), top_screen, scale,
                     0xFFFFFFFFu / uint32_t(scale), mid, map, masked_pixels_, false);
}

// The step's side with its silhouettes (R_StoreWallRange's silhouette, bsilheight
// and tsilheight), worked out on first use in a frame.
const Canvas::DoomSide& Canvas::doom_silhouette(const Step& step) {
  DoomSide& d = doom_side(step);
  if (d.silhouette_ready) return d;
  d.silhouette_ready = true;
  d.bottom_closed = d.top_closed = false;
  d.bottom_height = INT64_MAX, d.top_height = INT64_MIN;  // one-sided: both bind every sprite
  if (step.far == kNone) return d;
  const level::SectorState& f = state_->sectors[size_t(step.near)];
  const level::SectorState& k = state_->sectors[size_t(step.far)];
  const Fixed ff = fixed_of(f.floor), fc = fixed_of(f.ceiling), kf = fixed_of(k.floor), kc = fixed_of(k.ceiling);
  d.bottom_height = ff > kf ? int64_t(ff) : kf > view_->fz ? INT64_MAX : INT64_MIN;
  d.top_height = fc < kc ? int64_t(fc) : kc < view_->fz ? INT64_MIN : INT64_MAX;
  if (kc <= ff) d.bottom_closed = true, d.bottom_height = INT64_MAX;  // a closed door
  if (kf >= fc) d.top_closed = true, d.top_height = INT64_MIN;
  return d;
}

// R_DrawMasked: sprites farthest first (by scale), each after the masked walls behind
// it in its columns, clipped by the walls in front of it (R_DrawSprite); then the
// masked walls left, farthest first.
void Canvas::doom_draw_layers() {
  std::sort(sprites_.begin(), sprites_.end(), [](const Sprite& a, const Sprite& b) {
    return a.scale != b.scale ? a.scale < b.scale : a.thing < b.thing;
  });
  const doom::Tables& t = *doom_;
  for (const Sprite& s : sprites_) {
    bool drew = false;
    for (int x = s.x0; x <= s.x1; ++x) {
      std::vector<Step>& steps = steps_[x];
      int clip_top = -2, clip_bottom = -2;  // Doom's cliptop and clipbot, -2 unset
      const size_t nearest_masked = std::min<size_t>(columns_[x].nearest_masked, steps.size());
      for (size_t i = steps.size(); i-- > 0;) {  // farthest first, as Doom scans its drawsegs
        // The farthest wall in front that binds decides each clip: once both are set,
        // only masked walls nearer still may draw (those Doom counts behind the sprite).
        if (clip_top != -2 && clip_bottom != -2 && i < nearest_masked) break;
        Step& step = steps[i];
        const DoomSide& ds = doom_silhouette(step);
        const bool behind = ds.high_scale < s.scale ||
                            (ds.low_scale < s.scale &&
                             !doom::point_on_seg_side(s.gx, s.gy, ds.v1x, ds.v1y, ds.v2x, ds.v2y));
        if (behind) {
          if (step.masked && !step.masked_drawn) doom_draw_masked(x, step), step.masked_drawn = true;
          continue;
        }
        // A masked wall's drawseg keeps both silhouettes (R_StoreWallRange).
        int64_t bottom_height = ds.bottom_height, top_height = ds.top_height;
        if (step.masked) {
          if (top_height == INT64_MAX) top_height = INT64_MIN;
          if (bottom_height == INT64_MIN) bottom_height = INT64_MAX;
        }
        const bool sil_bottom = s.gz < bottom_height, sil_top = s.gzt > top_height;
        const int bottom_clip = ds.bottom_closed ? -1 : step.bottom;
        const int top_clip = ds.top_closed ? view_->height : step.top - 1;
        if (sil_bottom && clip_bottom == -2) clip_bottom = bottom_clip;
        if (sil_top && clip_top == -2) clip_top = top_clip;
      }
      if (clip_bottom == -2) clip_bottom = view_->height;
      if (clip_top == -2) clip_top = -1;
      const int top = clip_top + 1, bottom = clip_bottom;
      if (top >= bottom) continue;
      const level::Texture& tex = *s.texture;
      const Fixed frac = play::wrap_add(s.start_frac, Fixed(uint32_t(s.x_step) * uint32_t(x - s.x_start)));
      const int u = frac >> kFracBits;
      if (u < 0 || u >= tex.width) continue;
      const Fixed top_screen = play::wrap_sub(t.centeryfrac, fixed_mul(s.texture_mid, s.scale));
      if (doom_masked_column(x, top, bottom, tex, u, top_screen, s.scale, uint32_t(std::abs(s.x_step)), s.texture_mid,
                             s.light_map, sprite_pixels_, s.fuzz))
        drew = true;
    }
    sprites_drawn_ += drew;
    if (drew) things_drawn_.push_back(s.thing);
  }
  for (int x = x0_; x < x1_; ++x) {
    const std::vector<Step>& steps = steps_[x];
    const size_t nearest_masked = columns_[x].nearest_masked;
    for (size_t i = steps.size(); i-- > 0 && i >= nearest_masked;)
      if (steps[i].masked && !steps[i].masked_drawn) doom_draw_masked(x, steps[i]);
  }
}

}  // namespace p3d::render
