// Drawing: walls (perspective-correct texture columns), floors and ceilings (filed
// per column, drawn as rows: plane_spans.h), sky, masked middle textures, and
// Doom's light (its light levels and distance diminishing, through the level's own
// light maps when its art is paletted). Every pixel is a pure function of (surface,
// x, y), whatever order the renderer visits surfaces in, so all renderers can
// agree to the bit.
//
// Paletted levels are drawn as Doom draws them, in palette indices (through index light
// maps), resolved to colours once per pixel at the end (Canvas::resolve).
//
// Index: lighting, texel sources, Canvas::begin/draw_wall/paint_wall/finish/resolve,
// draw_hit (the rows of one hit), wall_span, draw_masked, sprites (and Doom's fuzz),
// plane_span, sky_span.
#include "engine/render/draw.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "engine/image/palette.h"
#include "engine/render/column_major.h"
#include "engine/render/texel_loops.h"
#include "engine/render/translation.h"

namespace p3d::render {

namespace {

using level::kNone;
using level::kSky;

constexpr double kFix = 65536;  // 16.16 fixed point for texture coordinates

// ---- lighting ------------------------------------------------------------------
// Doom's light: a sector's light picks a starting light map (16 levels, 4 maps
// apart, one level brighter or darker for walls along y or x); nearness brightens
// walls by 1280 / depth maps (at most 23) and flats by 80 / (depth / 16 + 1)
// (Doom's scalelight and zlight tables). 32 maps, 0 the brightest.
constexpr int kLightLevels = 16;
constexpr int kMapsPerLevel = 4;
constexpr int kDarkest = limits::kLightMaps - 1;

int light_start(int light, int contrast) {
  return (kLightLevels - 1 - std::clamp((light >> 4) + contrast, 0, kLightLevels - 1)) * kMapsPerLevel;
}

int wall_light_map(int start, double depth) {
  constexpr double kWallLightK = 1280, kWallLightCap = 23;
  const double gain = std::min(kWallLightCap, kWallLightK / depth);
  return std::clamp(start - static_cast<int>(gain), 0, kDarkest);
}

// Doom's zlight: 128 distance steps of 16 units, brightening by 80 / (step + 1) maps.
constexpr int kZLightSteps = 128;
constexpr auto kZLightGain = [] {
  std::array<int, kZLightSteps> gain{};
  for (int step = 0; step < kZLightSteps; ++step) gain[size_t(step)] = 80 / (step + 1);
  return gain;
}();

int flat_light_map(int start, double depth) {
  const int step = depth >= 16.0 * (kZLightSteps - 1) ? kZLightSteps - 1 : static_cast<int>(depth * (1.0 / 16));
  return std::clamp(start - kZLightGain[size_t(step)], 0, kDarkest);
}

// RGBA art is shaded by multiplying with 256 / 32 per map: 256 is full bright.
uint32_t multiplier(int map) { return static_cast<uint32_t>(limits::kLightMaps - map) * 8; }


// Doubles that become texel coordinates are bounded first (offsets are, by the loaders):
// this keeps the conversion defined whatever the camera.
int64_t to_int(double v) {
  constexpr double kLimit = 0x1p62;
  return !(v > -kLimit) ? int64_t(-kLimit) : v >= kLimit ? int64_t(kLimit) : floor_to_int(v);  // NaN: -kLimit
}

}  // namespace

void Canvas::prepare_probe(const View& view, Probe* probe) {
  if (probe && probe->want_columns) probe->columns.assign(view.width, ColumnHit{});
  if (probe && probe->want_writes) probe->writes.assign(size_t(view.width) * view.height, 0);
}

void Canvas::prepare_frame(const level::Level& level, Frame& frame) {
  if (frame.keep_indices && !level.light_indices.empty()) {
    frame.indices.resize(size_t(frame.width) * size_t(frame.height));
    frame.palette = level.palette;
  } else {
    frame.indices.clear();
    frame.pixels.resize(size_t(frame.width) * size_t(frame.height));  // a frame made without its colours
  }
}

void Canvas::begin(const level::Level& level, const level::State& state, const View& view, Frame& frame,
                   int camera_sector, Probe* probe) {
  prepare_probe(view, probe);
  prepare_frame(level, frame);
  begin_strip(level, state, view, frame, camera_sector, probe, 0, view.width, nullptr);
}

void Canvas::begin_strip(const level::Level& level, const level::State& state, const View& view, Frame& frame,
                         int camera_sector, Probe* probe, int x0, int x1, const Canvas* left) {
  level_ = &level;
  state_ = &state;
  view_ = &view;
  frame_ = &frame;
  hits_ = probe && probe->want_columns ? &probe->columns : nullptr;
  writes_ = probe && probe->want_writes ? &probe->writes : nullptr;
  x0_ = std::max(0, x0);
  x1_ = std::min(view.width, x1);
  columns_.resize(view.width);  // indexed by x; only the owned columns are used
  std::fill(columns_.begin() + x0_, columns_.begin() + x1_, Column{0, view.height, camera_sector});
  if (steps_.size() != size_t(view.width)) steps_.resize(view.width);
  for (int x = x0_; x < x1_; ++x) steps_[x].clear();
  sprites_.clear();
  sprites_known_ = false;
  vector_scales_ = vector_columns_allowed_ && vector_projection();
  things_drawn_.clear();
  fuzz_ready_ = level.generation != 0 && fuzz_index_for_ == level.generation;
  indexed_ = !level.light_indices.empty();
  if (indexed_) {
    if (frame.indexed()) {  // the frame's own rows
      index_pitch_ = size_t(view.width);
      index_base_ = frame.indices.data() + x0_;
    } else {
      index_pitch_ = size_t(std::max(0, x1_ - x0_));
      indices_.resize(index_pitch_ * size_t(view.height));
      index_base_ = indices_.data();
    }
  }
  // Column-major only where the columns are drawn 64 pixels at a time: else turning
  // them into rows costs more than their stores save (4% slower at the five maps' starts).
  vector_loops_ = columns_pending_ = indexed_ && vector_columns_allowed_ && vector_columns();
  if (columns_pending_) {
    column_stride_ = (size_t(view.height) + 63) / 64 * 64;  // each column on its own cache lines
    column_scratch_.resize(column_stride_ * size_t(std::max(0, x1_ - x0_)));
    column_base_ = column_scratch_.data(), column_pitch_ = 1;
  } else {
    column_base_ = index_base_, column_stride_ = 1, column_pitch_ = index_pitch_;
  }
  choose_fill_colors();
  if (row_dy_.size() != size_t(view.height) || (!row_dy_.empty() && row_dy_[0] != 0.5 - view.half_h)) {
    row_dy_.resize(view.height);
    row_inv_.resize(view.height);
    for (int y = 0; y < view.height; ++y) {
      row_dy_[y] = (y + 0.5) - view.half_h;
      row_inv_[y] = row_dy_[y] != 0 ? 1 / row_dy_[y] : 0;
    }
  }
  planes_.begin(x0_, x1_, view.height);
  doom_ = view.doom;
  left_ = left;
  doom_waiting_ = painting_planes_ = false;
  if (doom_) {
    const size_t sides = level.doom_segs.size() + level.walls.size() * 2;
    if (++doom_stamp_ == 0 || doom_side_slots_.size() < sides) doom_side_slots_.assign(sides, 0), doom_stamp_ = 1;
    doom_sides_.clear();
    doom_sides_.reserve(sides);
    const doom::Angle angle = (view.fangle - play::kAngle90) >> play::kAngleToFineShift;
    base_x_scale_ = play::fixed_div(play::kFineSine[angle + play::kFineAngles / 4], doom_->centerxfrac);
    base_y_scale_ = -play::fixed_div(play::kFineSine[angle], doom_->centerxfrac);
  }
  painted_index_.clear();
  painted_count_ = 0;
  tabulate_sky_rows();
  light_sky();
  pixels_ = closed_count_ = masked_pixels_ = sprites_drawn_ = sprite_pixels_ = 0;
}

// The sector whose heights frame the hit: the facing side's; for a plain segment
// the sector it stands in; failing that the column's, then the default.
int Canvas::near_sector(const level::Wall& w, const WallHit& hit, int x) const {
  if (w.sides[hit.side].sector != kNone) return w.sides[hit.side].sector;
  if (w.segment_sector != kNone) return w.segment_sector;
  const int column = x >= 0 ? columns_[x].sector : kNone;
  return column != kNone ? column : level_->default_sector;
}

bool Canvas::draw_wall(int x, const WallHit& hit) {
  const level::Wall& w = level_->walls[hit.wall];
  const int near = near_sector(w, hit, x);
  return record_step(x, hit, near, w.far_sector(hit.side),
                     [&](int& top, int& bottom) { return draw_hit(x, hit, near, top, bottom); });
}

void Canvas::draw_walls(const WallHits& hits, std::vector<int>& closed) {
  if (doom_ && !dry_ && !painting_) return draw_doom_walls(hits, closed);
  for (size_t k = 0; k < hits.size(); ++k)
    if (draw_wall(hits.x[k], hits[k])) closed.push_back(hits.x[k]);
}

bool Canvas::clip_wall(int x, const WallHit& hit) {
  dry_ = true;
  const bool closed = draw_wall(x, hit);
  dry_ = false;
  return closed;
}

void Canvas::paint_wall(int x, const WallHit& hit) {
  int top = 0, bottom = view_->height;
  painting_ = true;
  draw_hit(x, hit, near_sector(level_->walls[hit.wall], hit, -1), top, bottom);
  painting_ = false;
}

void Canvas::paint_background(int x, int sector) {
  painting_ = true;
  planes_to_horizon(x, 0, view_->height, sector);
  painting_ = false;
}

void Canvas::close(int x, const WallHit& hit) {
  columns_[x].top = columns_[x].bottom;
  ++closed_count_;
  if (hits_) (*hits_)[x] = {static_cast<int32_t>(hit.wall), hit.depth, hit.fragment};
}

void Canvas::finish() {
  for (int x = x0_; x < x1_; ++x) {
    Column& c = columns_[x];
    planes_to_horizon(x, c.top, c.bottom, c.sector);
  }
  end_columns();
  if (doom_ && !doom_->crispy) {  // vanilla's spans step from their first column: in a strip, perhaps another strip's
    doom_gather_spans();
    if (x0_ > 0 || x1_ < view_->width) {
      doom_waiting_ = true;
      return;
    }
    doom_draw_spans();
    draw_layers();
    return;
  }
  if (doom_)
    draw_crispy_flats();
  else
    planes_.for_each_span([this](const PlaneKey& key, int y, int xa, int xb) { plane_pixels(key, y, xa, xb); });
  draw_layers();
}

void Canvas::finish_strip() {
  if (!doom_waiting_) return;
  doom_waiting_ = false;
  doom_draw_spans();
  draw_layers();
}

void Canvas::end_columns() {
  if (!columns_pending_) return;
  columns_pending_ = false;
  columns_to_rows(column_scratch_.data(), column_stride_, index_base_, index_pitch_, x1_ - x0_, view_->height);
  column_base_ = index_base_, column_stride_ = 1, column_pitch_ = index_pitch_;
}

void Canvas::resolve(int y0, int y1) {
  if (!indexed_ || frame_->indexed()) return;  // a frame that keeps its indices was drawn in
  image::resolve_palette(index_pixel(x0_, y0), index_pitch_, pixel(x0_, y0), size_t(view_->width), x1_ - x0_, y1 - y0,
                         level_->palette.data());
}

// Draws, within rows [top, bottom), the near sector's ceiling above the wall, its
// floor below, and the wall's middle (one-sided) or upper and lower parts
// (two-sided). On return [top, bottom) is what stays open behind the wall.
//
// The rows stack from the top: near ceiling, upper part, opening, lower part, near
// floor; each begins where the one above ends. So a sector whose ceiling lies below
// its floor shows its ceiling over its floor, and a far one's upper part covers its
// lower part, as Doom draws them, and no pixel is written twice. A part without a
// texture shows the plane that would continue there (the far ceiling or floor, or
// for a one-sided wall its own sector's planes), as Doom ports show a missing texture.
// Returns whether a masked middle texture shows in the opening left.
bool Canvas::draw_hit(int x, const WallHit& hit, int near, int& top, int& bottom) {
  if (doom_ && near != kNone) return draw_hit_doom(x, hit, near, top, bottom);
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  const int upper = state_->shown(state_->texture(hit.wall, hit.side, level::kUpperPart));
  const int middle = state_->shown(state_->texture(hit.wall, hit.side, level::kMiddlePart));
  const int lower = state_->shown(state_->texture(hit.wall, hit.side, level::kLowerPart));
  if (near == kNone) {  // no sector to measure heights from: a wall over every open row
    wall_span(x, top, bottom, {middle, level::kMiddlePart, 0, 255}, hit);
    top = bottom;
    return false;
  }
  const level::SectorState& s = state_->sectors[near];
  const double scale = view_->d / hit.depth;
  auto row = [&](double z) { return view_->row_at(view_->half_h - (z - view_->eye) * scale); };
  const int far = w.far_sector(hit.side);
  const level::SectorState* b = far != kNone ? &state_->sectors[far] : nullptr;
  const bool both_sky = b && s.ceiling_texture == kSky && b->ceiling_texture == kSky;
  const int light = side.light != kNone ? side.light : s.light;
  auto height_of = [&](int texture) { return texture >= 0 ? double(level_->textures[texture].height) : 0.0; };

  int ceiling_row = row(s.ceiling);
  if (both_sky) ceiling_row = std::max(ceiling_row, row(b->ceiling));  // Doom's sky hack: no upper part
  const int wall_top = std::clamp(ceiling_row, top, bottom);
  const int wall_bottom = std::clamp(row(s.floor), wall_top, bottom);
  near_plane(x, top, wall_top, near, true);
  near_plane(x, wall_bottom, bottom, near, false);

  if (!b) {
    if (middle == kNone) {
      planes_to_horizon(x, wall_top, wall_bottom, near);
    } else {
      const double anchor = (w.flags & level::kUnpegLower) ? s.floor + height_of(middle) : s.ceiling;
      wall_span(x, wall_top, wall_bottom, {middle, level::kMiddlePart, anchor, light}, hit);
    }
    top = bottom;
    return false;
  }
  const int upper_end = std::clamp(row(b->ceiling), wall_top, wall_bottom);
  const int lower_start = std::clamp(row(b->floor), upper_end, wall_bottom);
  if (upper == kNone) {
    plane_span(x, wall_top, upper_end, far, true);
  } else {
    const double anchor = (w.flags & level::kUnpegUpper) ? s.ceiling : b->ceiling + height_of(upper);
    wall_span(x, wall_top, upper_end, {upper, level::kUpperPart, anchor, light}, hit);
  }
  if (lower == kNone) {
    plane_span(x, lower_start, wall_bottom, far, false);
  } else {
    const double anchor = (w.flags & level::kUnpegLower) ? s.ceiling : b->floor;  // Doom's rule for unpegged lowers
    wall_span(x, lower_start, wall_bottom, {lower, level::kLowerPart, anchor, light}, hit);
  }
  top = upper_end;
  bottom = lower_start;
  return middle != kNone && upper_end < lower_start;
}

void Canvas::count_writes(int x, int y0, int y1) {
  for (int y = y0; y < y1; ++y) ++(*writes_)[size_t(y) * view_->width + x];
}

void Canvas::choose_fill_colors() {
  const level::Level& l = *level_;
  fill_indices_[size_t(Fill::kVoid)] = l.void_index;
  fill_indices_[size_t(Fill::kMissingTexture)] = l.missing_index;
  const bool paletted = l.palette.size() == limits::kPaletteSize;
  fill_colors_[size_t(Fill::kVoid)] = paletted ? l.palette[l.void_index] : level::kVoidColor;
  fill_colors_[size_t(Fill::kMissingTexture)] = paletted ? l.palette[l.missing_index] : level::kMissingColor;
}

void Canvas::fill_span(int x, int y0, int y1, Fill fill) {
  if (y0 >= y1 || dry_) return;
  count(x, y0, y1);
  if (painting_planes_) mark_painted(x, y0, y1, kNoPlane);
  if (indexed_) {
    uint8_t* out = column_pixel(x, y0);
    for (int y = y0; y < y1; ++y, out += column_pitch_) *out = fill_indices_[size_t(fill)];
    return;
  }
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width) *out = fill_colors_[size_t(fill)];
}

// The near sector's ceiling (or floor) in front of a wall: seen only from its open
// side. An eye above the ceiling (or below the floor) looks into solid matter: fill it.
void Canvas::near_plane(int x, int y0, int y1, int sector, bool ceiling) {
  const level::SectorState& s = state_->sectors[sector];
  const bool open_side = ceiling ? view_->eye < s.ceiling : view_->eye > s.floor;
  if (open_side)
    plane_span(x, y0, y1, sector, ceiling);
  else
    fill_span(x, y0, y1, Fill::kVoid);
}

// Texture column u of the hit's facing side: the distance from the side's start
// along the wall, plus its offsets.
double Canvas::texture_u(const WallHit& hit, int part) const {
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  return (hit.side == 0 ? hit.t : 1 - hit.t) * w.length + side.x_offset + level_->part_x(side, part) +
         state_->scroll(hit.wall, hit.side);
}

// Texture row v at screen row y is v0 + y * step, v0 = anchor - eye + offsets at row
// 0: computed from row 0 so a pixel does not depend on where its span starts. Both
// are reduced modulo the texture's height in 16.16 (a mask for a power of two).
void Canvas::wall_span(int x, int y0, int y1, const Part& part, const WallHit& hit) {
  if (y0 >= y1 || dry_) return;
  if (part.texture == kNone) return fill_span(x, y0, y1, Fill::kMissingTexture);
  count(x, y0, y1);
  if (painting_planes_) mark_painted(x, y0, y1, kNoPlane);  // a wall with no sector, under Doom's rules
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  const level::Texture& tex = level_->textures[part.texture];
  const int64_t u = to_int(texture_u(hit, part.part));
  const double inv_scale = hit.depth / view_->d;
  const double v0 = part.anchor - view_->eye + side.y_offset + level_->part_y(side, part.part) + (0.5 - view_->half_h) * inv_scale;
  const int64_t period = int64_t(tex.height) << 16;
  auto reduce = [&](int64_t v) { return tex.pow2_height ? v & (period - 1) : level::floor_mod(v, period); };
  const int64_t step = reduce(round_to_int(inv_scale * kFix));
  const int64_t v = reduce(round_to_int(v0 * kFix) + int64_t(y0) * step);
  const int map = fixed_or(wall_light_map(light_start(part.light, w.contrast), hit.depth));
  if (indexed_)
    return indexed_wall_column(x, y0, y1 - y0, v, step, period, tex.index_column(u),
                               level_->light_indices.data() + size_t(map) * limits::kPaletteSize);
  uint32_t* out = pixel(x, y0);
  if (level_->paletted())
    wrapped_column(out, view_->width, y1 - y0, v, step, period,
                   PalettedColumn{tex.index_column(u), level_->light_maps.data() + size_t(map) * limits::kPaletteSize});
  else
    wrapped_column(out, view_->width, y1 - y0, v, step, period, RgbaColumn{tex.column(u), multiplier(map)});
}

// A masked middle texture (Doom's R_RenderMaskedSegRange): hung from the lower of the
// two ceilings, or stood on the higher floor when lower-unpegged; drawn once, not
// tiled; its transparent texels leave what is behind.
void Canvas::draw_masked(int x, const Step& m) {
  const level::Wall& w = level_->walls[m.hit.wall];
  const level::Side& side = w.sides[m.hit.side];
  const level::SectorState& s = state_->sectors[m.near];
  const level::SectorState& b = state_->sectors[m.far];
  const level::Texture& tex = level_->textures[state_->shown(state_->texture(m.hit.wall, m.hit.side, level::kMiddlePart))];
  const double anchor = (w.flags & level::kUnpegLower) ? std::max(s.floor, b.floor) + tex.height
                                                       : std::min(s.ceiling, b.ceiling);
  const int64_t u = to_int(texture_u(m.hit, level::kMiddlePart));
  const double inv_scale = m.hit.depth / view_->d;
  const double v0 = anchor - view_->eye + side.y_offset + level_->part_y(side, level::kMiddlePart) +
                    (0.5 - view_->half_h) * inv_scale;
  const int light = side.light != kNone ? side.light : s.light;
  const int map = fixed_or(wall_light_map(light_start(light, w.contrast), m.hit.depth));
  layer_column(x, m.top, m.bottom, tex, tex.wrap_u(u), round_to_int(v0 * kFix), round_to_int(inv_scale * kFix), map,
               masked_pixels_);
}

namespace {

// a / b rounded up (b > 0).
int64_t ceil_div(int64_t a, int64_t b) { return a >= 0 ? (a + b - 1) / b : -((-a) / b); }

}  // namespace

bool Canvas::layer_column(int x, int top, int bottom, const level::Texture& tex, int u, int64_t v0, int64_t step,
                          int light_map, uint64_t& counter, bool fuzz) {
  const size_t column = size_t(u) * size_t(tex.height);
  const size_t map = size_t(light_map) * limits::kPaletteSize;
  bool drew = false;
  auto paint = [&](auto* out, size_t pitch, int y0, int y1, auto colour_of) {
    for (int64_t v = v0 + int64_t(y0) * step; y0 < y1; ++y0, out += pitch, v += step) *out = colour_of(column + size_t(v >> 16));
  };
  auto draw_rows = [&](int y0, int y1) {  // texels all opaque
    if (fuzz) y0 = std::max(y0, 1), y1 = std::min(y1, view_->height - 1);  // as Doom: the rows read stay on screen
    if (y0 >= y1) return;
    drew = true;
    counter += uint64_t(y1 - y0);
    if (writes_)
      for (int y = y0; y < y1; ++y) ++(*writes_)[size_t(y) * view_->width + x];
    if (fuzz) {
      draw_fuzz(x, y0, y1);
    } else if (indexed_) {
      const uint8_t* lit = level_->light_indices.data() + map;
      paint(column_pixel(x, y0), column_pitch_, y0, y1, [&](size_t texel) { return lit[tex.indices[texel]]; });
    } else {
      paint(pixel(x, y0), size_t(view_->width), y0, y1, [&](size_t texel) { return this->lit(tex, texel, light_map); });
    }
  };
  if (step <= 0) {  // so near that one texel row covers every row
    const int64_t row = v0 >> 16;
    if (row >= 0 && row < tex.height && (tex.texels[column + size_t(row)] >> 24)) draw_rows(top, bottom);
    return drew;
  }
  // The screen rows of texel rows [first, end): first << 16 <= v0 + y * step < end << 16, exactly.
  auto first_row = [&](int texel_row) {
    return int(std::clamp<int64_t>(ceil_div((int64_t(texel_row) << 16) - v0, step), top, bottom));
  };
  if (!tex.holes) {
    draw_rows(first_row(0), first_row(tex.height));
    return drew;
  }
  for (uint32_t r = tex.run_start[size_t(u)]; r < tex.run_start[size_t(u) + 1]; ++r) {
    const int y0 = first_row(tex.runs[r].first);
    if (y0 >= bottom) break;
    draw_rows(y0, first_row(tex.runs[r].end));
  }
  return drew;
}

// The light map a pixel takes: `map`, unless the player's powers fix one for every
// pixel (Doom's fixedcolormap); RGBA art has no invulnerability map and stays bright.
int Canvas::fixed_or(const level::Level& level, const level::State& state, int map) {
  const int fixed = state.fixed_light_map;
  if (fixed < 0) return map;
  return level.paletted() || fixed < limits::kLightMaps ? fixed : 0;
}

// A texel under a light map: looked up in the level's light maps when paletted, else shaded.
uint32_t Canvas::lit(const level::Texture& tex, size_t texel, int light_map) const {
  return level_->paletted() ? level_->light_maps[size_t(light_map) * limits::kPaletteSize + tex.indices[texel]]
                            : shade(tex.texels[texel], multiplier(light_map));
}

// ---- sprites ---------------------------------------------------------------------
// A sprite is a picture facing the viewer at its thing's depth, one texel per map
// unit (Doom's R_ProjectSprite): its rotation chosen by the angle between the
// thing's facing and the view, its origin at the thing's height (ShownThing::z), lit
// by its sector's light and depth like a wall, or full bright; a shadow is fuzz.

constexpr double kSpriteNearDepth = 4;  // Doom's MINZ: nearer things are not drawn

void Canvas::add_sprite(uint32_t thing) {
  if (doom_) {
    Sprite s;
    if (project_doom_sprite(*level_, *state_, *view_, thing, s)) add_projected_sprites({&s, 1});
    return;
  }
  const level::ShownThing& t = state_->things[thing];
  if (t.frame == level::kNone) return;
  const double depth = view_->depth_of(t.pos);
  if (depth < kSpriteNearDepth) return;
  const level::SpriteFrame& frame = level_->sprite_frames[size_t(t.frame)];
  // Outside this canvas's columns whichever picture shows (with columns to spare for
  // rounding): a strip of the screen skips the rotation's arc tangent.
  const double scale = view_->d / depth;
  const double centre = view_->half_w + view_->lateral_of(t.pos) * scale, reach = frame.reach * scale;
  if (centre + reach < x0_ - 2 || centre - reach > x1_ + 1) return;
  // Doom's rotation: the angle from the viewer to the thing, less its facing, in 45-degree steps.
  const geom::Vec2 to_thing = t.pos - view_->pos;
  const double seen_from = std::atan2(to_thing.y, to_thing.x) * (180 / M_PI) - t.angle + 22.5 * 9;
  const int rotation = int(level::floor_mod(to_int(seen_from / 45), level::kRotations));
  const level::SpriteImage& image = level_->sprite_images[size_t(frame.image[rotation])];
  const int translation = (t.flags & level::kShownTranslation) >> level::kShownTranslationShift;
  const level::Texture& tex = translated_texture(*level_, size_t(image.texture), translation);
  Sprite s;
  s.thing = thing;
  s.depth = depth;
  s.texture = &tex;
  s.flip = frame.flip[rotation];
  s.left = view_->lateral_of(t.pos) - image.left;
  s.top = t.z + image.top;
  // Columns whose centre's ray crosses the picture (one more on each side: draw_sprite_column checks).
  s.x0 = std::max(x0_, int(floor_to_int(view_->half_w + s.left * scale)) - 1);
  s.x1 = std::min(x1_ - 1, int(ceil_to_int(view_->half_w + (s.left + tex.width) * scale)) + 1);
  if (s.x0 > s.x1) return;
  const int light = t.sector != kNone ? state_->sectors[size_t(t.sector)].light : 255;
  s.light_map = fixed_or(frame.bright ? 0 : wall_light_map(light_start(light, 0), depth));
  s.fuzz = (t.flags & level::kShownShadow) != 0;
  sprites_.push_back(s);
}

// Column x of a sprite within open rows [top, bottom): its texel column by the ray
// through the column's centre, texel rows as a wall's (16.16, from row 0), not tiled;
// transparent texels skipped.
void Canvas::draw_sprite_column(const Sprite& s, int x, int top, int bottom, bool& drew) {
  const level::Texture& tex = *s.texture;
  const double inv_scale = s.depth / view_->d;
  const int64_t u = to_int((x + 0.5 - view_->half_w) * inv_scale - s.left);
  if (u < 0 || u >= tex.width) return;
  // Texel row at screen row y: (v0 + y * step) >> 16, v0 from top - z at row 0, as walls.
  const int64_t v0 = round_to_int((s.top - view_->eye + (0.5 - view_->half_h) * inv_scale) * kFix);
  const int64_t step = std::max<int64_t>(1, round_to_int(inv_scale * kFix));
  if (layer_column(x, top, bottom, tex, int(s.flip ? tex.width - 1 - u : u), v0, step, s.light_map, sprite_pixels_,
                   s.fuzz))
    drew = true;
}

// Doom's fuzz (R_DrawFuzzColumn): a pixel takes the colour of the pixel one row above
// or below it (Doom's table of 50 offsets), darkened through light map 6. Doom steps
// through the table pixel by pixel in the order it draws; here the step is a function
// of the pixel's place, so renderers and strips agree whatever order they draw in.
// Rows 0 and height - 1 are never fuzzed (layer_column), so the pixel read is on screen.
namespace {
constexpr int kFuzzLightMap = 6;
constexpr int8_t kFuzzOffsets[50] = {  // Doom's fuzzoffset, in rows
    1, -1, 1,  -1, 1,  1,  -1,     //
    1, 1,  -1, 1,  1,  1,  -1,     //
    1, 1,  1,  -1, -1, -1, -1,     //
    1, -1, -1, 1,  1,  1,  1,  -1, //
    1, -1, 1,  1,  -1, -1, 1,      //
    1, -1, -1, -1, -1, 1,  1,      //
    1, 1,  -1, 1,  1,  -1, 1};
int fuzz_offset(int x, int y) { return kFuzzOffsets[size_t(x * 7 + y) % std::size(kFuzzOffsets)]; }
}  // namespace

void Canvas::draw_fuzz(int x, int y0, int y1) {
  if (indexed_) {
    const uint8_t* dark = level_->light_indices.data() + size_t(kFuzzLightMap) * limits::kPaletteSize;
    for (int y = y0; y < y1; ++y) *index_pixel(x, y) = dark[*index_pixel(x, y + fuzz_offset(x, y))];
    return;
  }
  for (int y = y0; y < y1; ++y) *pixel(x, y) = fuzz_colour(*pixel(x, y + fuzz_offset(x, y)));
}

// A colour darkened as the fuzz darkens it: on a paletted level through light map 6
// from the colour's first palette index (every pixel drawn in indices is such an index,
// so colours and indices agree), else (a colour no palette index has, RGBA art) by
// light map 6's multiplier.
uint32_t Canvas::fuzz_colour(uint32_t colour) {
  if (level_->palette.size() == limits::kPaletteSize && level_->paletted()) {
    if (!fuzz_ready_) {
      fuzz_index_.clear();
      for (size_t i = 0; i < limits::kPaletteSize; ++i) fuzz_index_.emplace(level_->palette[i], uint8_t(i));
      fuzz_index_for_ = level_->generation;
      fuzz_ready_ = true;
    }
    if (const auto it = fuzz_index_.find(colour); it != fuzz_index_.end())
      return level_->light_maps[size_t(kFuzzLightMap) * limits::kPaletteSize + it->second];
  }
  return shade(colour, multiplier(kFuzzLightMap));
}

void Canvas::draw_layers() {
  end_columns();
  if (painting_planes_) draw_painted_planes();
  if (doom_) return doom_draw_layers();
  // Farthest first; equal depths by thing index, a total order whatever the order things were added in.
  std::sort(sprites_.begin(), sprites_.end(), [](const Sprite& a, const Sprite& b) {
    return a.depth != b.depth ? a.depth > b.depth : a.thing < b.thing;
  });
  std::vector<int>& next_masked = layer_cursor_;  // per column: the farthest step not yet passed
  next_masked.resize(view_->width);
  for (int x = x0_; x < x1_; ++x) next_masked[x] = int(steps_[x].size()) - 1;
  auto masked_down_to = [&](int x, double depth) {  // the masked steps of column x at depth >= `depth`
    const std::vector<Step>& steps = steps_[x];
    for (int& i = next_masked[x]; i >= 0 && steps[size_t(i)].hit.depth >= depth; --i)
      if (steps[size_t(i)].masked) draw_masked(x, steps[size_t(i)]);
  };
  for (const Sprite& s : sprites_) {
    bool drew = false;
    for (int x = s.x0; x <= s.x1; ++x) {
      masked_down_to(x, s.depth);
      // The rows open at the sprite's depth: after the last wall in front of it.
      const std::vector<Step>& steps = steps_[x];
      const auto behind = std::lower_bound(steps.begin(), steps.end(), s.depth,
                                           [](const Step& step, double d) { return step.hit.depth < d; });
      int top = 0, bottom = view_->height;
      if (behind != steps.begin()) top = std::prev(behind)->top, bottom = std::prev(behind)->bottom;
      if (top < bottom) draw_sprite_column(s, x, top, bottom, drew);
    }
    sprites_drawn_ += drew;
    if (drew) things_drawn_.push_back(s.thing);
  }
  for (int x = x0_; x < x1_; ++x) masked_down_to(x, -INFINITY);
}

// Floor or ceiling at height h: row y's ray through column x meets the plane at
// k = (eye - h) / dy ray lengths, i.e. at pos + ray(x) * k, depth k * d. Along a row
// k is constant and ray(x) = ray0 + right * x, so the texture coordinates are linear
// in x: row y's are rounded once to 16.16 (PlaneRow: u0, du, v0, dv) and column x
// samples u0 + x du (mod 2^64), exactly, whether a row span steps along x or the
// painter draws a column. Its light is the row's depth's. (Camera positions, heights
// and the projection are bounded, so the doubles stay far inside 64 bits.)
Canvas::PlaneRow Canvas::plane_row(const PlaneKey& key, int y) const {
  const double h_rel = view_->eye - key.height;
  const double k = h_rel * row_inv_[y];
  const Vec2 p = view_->pos * kFix, r0 = view_->ray0 * kFix, dr = view_->right * kFix;
  const double depth = std::fabs(h_rel) * view_->d * std::fabs(row_inv_[y]);  // |h| d / |dy|
  return {uint64_t(to_int(p.x + r0.x * k)), uint64_t(to_int(dr.x * k)), uint64_t(to_int(-p.y - r0.y * k)),
          uint64_t(to_int(-dr.y * k)), fixed_or(flat_light_map(key.light, depth))};
}

// A floor or ceiling seen in rows [y0, y1) of column x: filed as a plane run, drawn by
// rows in finish(); the painter, which draws over itself, draws it at once.
void Canvas::plane_span(int x, int y0, int y1, int sector, bool ceiling) {
  if (y0 >= y1 || dry_) return;
  const level::SectorState& s = state_->sectors[sector];
  const int texture = state_->shown(ceiling ? s.ceiling_texture : s.floor_texture);
  if (texture == kSky) return sky_span(x, y0, y1);
  count(x, y0, y1);
  // Doom's visplanes are of one light level (0..255); ours of one light map.
  const PlaneKey key{ceiling ? s.ceiling : s.floor, texture, doom_ ? s.light : light_start(s.light, 0)};
  if (painting_)
    plane_column(key, x, y0, y1);
  else
    planes_.add(key, x, y0, y1);
}

void Canvas::doom_plane_span_otherwise(DoomSide& ds, int x, int y0, int y1, bool ceiling) {
  if (painting_) return plane_span(x, y0, y1, ds.near, ceiling);
  int& plane = ds.planes[ceiling];
  if (plane == kPlaneNotFound) {
    const level::SectorState& s = state_->sectors[ds.near];
    const int texture = state_->shown(ceiling ? s.ceiling_texture : s.floor_texture);
    plane = texture == kSky ? kSkyPlane : planes_.plane_of({ceiling ? s.ceiling : s.floor, texture, s.light});
  }
  if (plane == kSkyPlane) return sky_span(x, y0, y1);
  count(x, y0, y1);
  planes_.add_to(plane, x, y0, y1);
}

namespace {

// Calls draw(texel_of): texel_of(u, v) is the texel index at 16.16 coordinates (u, v),
// wrapped by mask for power-of-two sizes (the low 32 bits then suffice: a texture is
// at most 4096 wide), else by modulo.
template <typename Draw>
void with_texel_index(const level::Texture& tex, Draw&& draw) {
  if (tex.pow2_width && tex.pow2_height) {
    const uint32_t shift = uint32_t(std::countr_zero(unsigned(tex.height)));
    const uint32_t umask = uint32_t(tex.width - 1) << shift, vmask = uint32_t(tex.height - 1);
    draw([=](uint64_t u, uint64_t v) {
      return size_t(((uint32_t(u) >> (16 - shift)) & umask) | ((uint32_t(v) >> 16) & vmask));
    });
  } else {
    draw([&](uint64_t u, uint64_t v) {
      return size_t(tex.wrap_u(int64_t(u) >> 16)) * tex.height + tex.wrap_v(int64_t(v) >> 16);
    });
  }
}

}  // namespace

// Pixels [xa, xb) of row y of a plane: one light map for the row.
void Canvas::plane_pixels(const PlaneKey& key, int y, int xa, int xb) {
  if (doom_) return doom_plane_pixels(key, y, xa, xb, xa);
  const level::Texture& tex = level_->textures[key.texture];
  const PlaneRow row = plane_row(key, y);
  if (indexed_ && tex.pow2_width && tex.pow2_height) {  // with_texel_index's arithmetic, modulo 2^32
    const uint32_t shift = uint32_t(std::countr_zero(unsigned(tex.height)));
    return indexed_flat_row(index_pixel(xa, y), xb - xa,
                            {uint32_t(row.u0 + uint64_t(xa) * row.du), uint32_t(row.du), 16 - shift,
                             uint32_t(tex.width - 1) << shift},
                            {uint32_t(row.v0 + uint64_t(xa) * row.dv), uint32_t(row.dv), 16, uint32_t(tex.height - 1)},
                            tex.indices.data(), level_->light_indices.data() + size_t(row.light_map) * limits::kPaletteSize);
  }
  auto draw = [&](auto colour_of_texel, auto texel_of, auto* out) {
    uint64_t u = row.u0 + uint64_t(xa) * row.du, v = row.v0 + uint64_t(xa) * row.dv;
    for (int x = xa; x < xb; ++x, u += row.du, v += row.dv) *out++ = colour_of_texel(texel_of(u, v));
  };
  const size_t light_map = size_t(row.light_map) * limits::kPaletteSize;
  with_texel_index(tex, [&](auto texel_of) {
    if (indexed_) {
      const uint8_t* map = level_->light_indices.data() + light_map;
      const uint8_t* indices = tex.indices.data();
      draw([=](size_t texel) { return map[indices[texel]]; }, texel_of, index_pixel(xa, y));
    } else if (level_->paletted()) {
      const uint32_t* map = level_->light_maps.data() + light_map;
      const uint8_t* indices = tex.indices.data();
      draw([=](size_t texel) { return map[indices[texel]]; }, texel_of, pixel(xa, y));
    } else {
      const uint32_t* texels = tex.texels.data();
      const uint32_t m = multiplier(row.light_map);
      draw([=](size_t texel) { return shade(texels[texel], m); }, texel_of, pixel(xa, y));
    }
  });
}

// The painter's column of a plane: the same pixels as plane_pixels gives by rows, from
// the plane's rows, each computed once a frame (painted_rows).
void Canvas::plane_column(const PlaneKey& key, int x, int y0, int y1) {
  if (painting_planes_) {  // Doom's rules: drawn as spans at the end (draw_painted_planes)
    auto [it, added] = painted_index_.try_emplace(key, painted_keys_.size());
    if (added) painted_keys_.push_back(key);
    return mark_painted(x, y0, y1, uint32_t(it->second));
  }
  const level::Texture& tex = level_->textures[key.texture];
  const PlaneRow* rows = painted_rows(key, y0, y1);
  uint32_t* out = pixel(x, y0);
  with_texel_index(tex, [&](auto texel_of) {
    for (int y = y0; y < y1; ++y, out += view_->width) {
      const PlaneRow& r = rows[y];
      *out = lit(tex, texel_of(r.u0 + uint64_t(x) * r.du, r.v0 + uint64_t(x) * r.dv), r.light_map);
    }
  });
}

const Canvas::PlaneRow* Canvas::painted_rows(const PlaneKey& key, int y0, int y1) {
  auto [it, added] = painted_index_.try_emplace(key, painted_count_);
  if (added && painted_.size() <= painted_count_++) painted_.emplace_back();
  PaintedPlane& p = painted_[it->second];
  if (added) p.ready.assign(size_t(view_->height), 0), p.rows.resize(size_t(view_->height));
  for (int y = y0; y < y1; ++y)
    if (!p.ready[size_t(y)]) p.rows[size_t(y)] = plane_row(key, y), p.ready[size_t(y)] = 1;
  return p.rows.data();
}

// Doom's sky: 1024 texture columns around the horizon (a 256-wide sky repeats four
// times), the column at the ray's angle; texture row 100 at the horizon and one row
// per pixel at Doom's projection (d = 160), so the sky keeps its angular size at any
// resolution. Full bright. A screen row's texture row is the same in every column,
// and a column's angle from the view direction the same in every frame of a size:
// begin() tabulates both.
constexpr double kSkyColumns = 1024, kSkyMidRow = 100, kDoomProjection = 160;

void Canvas::tabulate_sky_rows() {
  if (level_->sky_texture == kNone) return sky_rows_.clear();
  const level::Texture& tex = level_->textures[level_->sky_texture];
  if (view_->doom) {  // Doom's: texel row (skytexturemid + (y - centery) * iscale) >> 16, & 127
    const doom::Tables& t = *view_->doom;
    const DoomSkyKey key{&t, level_->generation, level_->sky_texture};
    if (key.generation != 0 && key == doom_sky_key_) return;  // generation 0: a level never finalized
    doom_sky_key_ = key;
    doom_sky_rows_.resize(size_t(view_->height));
    for (int y = 0; y < view_->height; ++y) {
      const uint32_t v = uint32_t(kSkyMidRow * doom::kFracUnit) + uint32_t(y - t.centery) * uint32_t(t.sky_iscale);
      if (t.crispy) {  // Crispy's: wrapped at the texture's height
        doom_sky_rows_[size_t(y)] = int(level::floor_mod(int64_t(int32_t(v)), int64_t(tex.height) << doom::kFracBits) >> doom::kFracBits);
        continue;
      }
      const int row = int((v >> doom::kFracBits) & 127);
      const bool doom_rows = size_t(level_->sky_texture) < level_->doom_column_start.size() &&
                             level_->doom_column_start[size_t(level_->sky_texture)] >= 0;
      doom_sky_rows_[size_t(y)] = doom_rows || row < tex.height ? row : row % tex.height;
    }
    doom_sky_row_bytes_.assign(doom_sky_rows_.begin(), doom_sky_rows_.end());  // for tabled_column_vbmi
    if (tex.height > 256) doom_sky_row_bytes_.clear();
    return;
  }
  // The rows depend only on these: a game's or a benchmark's frames reuse them.
  const SkyKey key{tex.height, view_->d, view_->half_h, view_->height, view_->half_w, view_->width};
  if (key == sky_key_ && sky_rows_.size() == size_t(view_->height)) return;
  sky_key_ = key;
  const double rows_per_pixel = kDoomProjection / view_->d;
  sky_rows_.resize(size_t(view_->height));
  for (int y = 0; y < view_->height; ++y) sky_rows_[size_t(y)] = tex.wrap_v(to_int(kSkyMidRow + row_dy_[y] * rows_per_pixel));
  sky_angles_.resize(size_t(view_->width));
  for (int x = 0; x < view_->width; ++x) sky_angles_[size_t(x)] = std::atan2(view_->half_w - (x + 0.5), view_->d);
}

// The sky's palette indices under its light map (full bright), once per level: a sky
// pixel is then one lookup, not two.
void Canvas::light_sky() {
  if (!indexed_ || level_->sky_texture == kNone) return;
  const std::pair key{level_->generation, level_->sky_texture};
  if (key.first != 0 && lit_sky_for_ == key) return;  // generation 0: a level never finalized
  const level::Texture& tex = level_->textures[level_->sky_texture];
  lit_sky_.resize(tex.indices.size());
  for (size_t i = 0; i < tex.indices.size(); ++i) lit_sky_[i] = level_->light_indices[tex.indices[i]];
  lit_sky_for_ = key;
}

void Canvas::sky_span(int x, int y0, int y1) {
  if (dry_) return;
  if (level_->sky_texture == kNone) return fill_span(x, y0, y1, Fill::kVoid);
  count(x, y0, y1);
  if (painting_planes_) mark_painted(x, y0, y1, kNoPlane);
  if (doom_) return doom_sky_span(x, y0, y1);
  const level::Texture& tex = level_->textures[level_->sky_texture];
  const double angle = view_->angle + sky_angles_[size_t(x)];
  const int64_t u = to_int(angle / (2 * M_PI) * kSkyColumns);
  const int* rows = sky_rows_.data();
  if (indexed_) {
    const uint8_t* lit = lit_sky_.data() + size_t(tex.wrap_u(u)) * size_t(tex.height);
    uint8_t* out = column_pixel(x, y0);
    for (int y = y0; y < y1; ++y, out += column_pitch_) *out = lit[rows[y]];
    return;
  }
  uint32_t* out = pixel(x, y0);
  if (level_->paletted()) {
    const uint8_t* indices = tex.index_column(u);
    const uint32_t* light_map = level_->light_maps.data();
    for (int y = y0; y < y1; ++y, out += view_->width) *out = light_map[indices[rows[y]]];
  } else {
    const uint32_t* texels = tex.column(u);
    for (int y = y0; y < y1; ++y, out += view_->width) *out = texels[rows[y]] | 0xFF000000u;
  }
}

// What a column shows past its last wall: its sector's planes out to the horizon.
void Canvas::planes_to_horizon(int x, int y0, int y1, int sector) {
  if (y0 >= y1) return;
  if (sector == kNone) return fill_span(x, y0, y1, Fill::kVoid);
  const int horizon = view_->row_at(view_->half_h);  // first row whose centre is not above the horizon
  const int below = horizon < view_->height && row_dy_[horizon] == 0 ? horizon + 1 : horizon;
  const int ceiling_end = std::min(y1, horizon), floor_start = std::max(y0, below);
  near_plane(x, y0, ceiling_end, sector, true);
  fill_span(x, std::max(y0, horizon), std::min(y1, below), Fill::kVoid);
  near_plane(x, floor_start, y1, sector, false);
}

}  // namespace p3d::render
