// Column drawing: walls (perspective-correct texture columns), floors and
// ceilings (exact per-pixel plane intersection), sky, and Doom's light diminishing.
// Every pixel is a pure function of (surface, x, y), whatever order the
// renderer visits surfaces in, so all renderers can agree to the bit.
#include "engine/render/draw.h"

#include <cmath>

namespace p3d::render {

namespace {

using level::kNone;
using level::kSky;

constexpr uint32_t kVoidColor = image::rgba(18, 18, 26);
constexpr uint32_t kMissingTexture = image::rgba(255, 0, 255);

// Doom's light: a sector's light picks a starting colormap (16 levels, 4 maps
// apart); nearness brightens it by 1280 / distance maps, at most 23; 32 maps.
constexpr double kLightK = 1280;
constexpr double kLightCap = 23;

int light_start(int light, int contrast) { return (15 - std::clamp((light >> 4) + contrast, 0, 15)) * 4; }

uint32_t light_multiplier(int start, double gain) {
  const int map = std::clamp(start - static_cast<int>(std::min(kLightCap, gain)), 0, 31);
  return static_cast<uint32_t>(32 - map) * 8;  // 256 = full bright
}

inline uint32_t shade(uint32_t c, uint32_t m) {
  const uint32_t rb = ((c & 0xFF00FFu) * m >> 8) & 0xFF00FFu;
  const uint32_t g = ((c & 0x00FF00u) * m >> 8) & 0x00FF00u;
  return rb | g | 0xFF000000u;
}

constexpr double kFix = 65536;  // 16.16 fixed point for texture coordinates

}  // namespace

void Canvas::begin(const level::Level& level, const View& view, Frame& frame, int camera_sector, Probe* probe) {
  level_ = &level;
  view_ = &view;
  frame_ = &frame;
  hits_ = probe && probe->want_columns ? &probe->columns : nullptr;
  writes_ = probe && probe->want_writes ? &probe->writes : nullptr;
  columns_.assign(view.width, Column{0, view.height, camera_sector});
  if (row_dy_.size() != size_t(view.height) || (!row_dy_.empty() && row_dy_[0] != 0.5 - view.half_h)) {
    row_dy_.resize(view.height);
    row_inv_.resize(view.height);
    for (int y = 0; y < view.height; ++y) {
      row_dy_[y] = (y + 0.5) - view.half_h;
      row_inv_[y] = row_dy_[y] != 0 ? 1 / row_dy_[y] : 0;
    }
  }
  if (hits_) hits_->assign(view.width, ColumnHit{});
  if (writes_) writes_->assign(size_t(view.width) * view.height, 0);
  pixels_ = closed_count_ = 0;
}

// The sector whose heights frame the hit: the facing side's; for a plain segment
// the sector it stands in; failing that the column's, then the default.
int Canvas::near_sector(const level::Wall& w, const WallHit& hit, int x) const {
  if (w.sides[hit.side].sector != kNone) return w.sides[hit.side].sector;
  if (w.segment_sector != kNone) return w.segment_sector;
  const int column = x >= 0 ? columns_[x].sector : kNone;
  return column != kNone ? column : level_->default_sector;
}

// Where a hit's parts fall on screen, in rows; see draw_hit.
struct Canvas::Rows {
  int ceiling, floor;            // the near sector's ceiling and floor lines
  int back_ceiling, back_floor;  // the far sector's, for two-sided walls
};

bool Canvas::draw_wall(int x, const WallHit& hit) {
  Column& c = columns_[x];
  const level::Wall& w = level_->walls[hit.wall];
  const int near = near_sector(w, hit, x);
  int top = c.top, bottom = c.bottom;
  draw_hit(x, hit, near, top, bottom);
  if (w.two_sided()) c.sector = w.sides[1 - hit.side].sector;
  c.top = top;
  c.bottom = bottom;
  if (top < bottom) return false;
  close(x, hit);
  return true;
}

bool Canvas::clip_wall(int x, const WallHit& hit) {
  dry_ = true;
  const uint64_t pixels = pixels_;
  const bool closed = draw_wall(x, hit);
  pixels_ = pixels;
  dry_ = false;
  return closed;
}

void Canvas::paint_wall(int x, const WallHit& hit) {
  int top = 0, bottom = view_->height;
  draw_hit(x, hit, near_sector(level_->walls[hit.wall], hit, -1), top, bottom);
}

void Canvas::paint_background(int x, int sector) { planes_to_horizon(x, 0, view_->height, sector); }

void Canvas::close(int x, const WallHit& hit) {
  columns_[x].top = columns_[x].bottom;
  ++closed_count_;
  if (hits_) (*hits_)[x] = {static_cast<int32_t>(hit.wall), hit.depth, hit.fragment};
}

// Draws, within rows [top, bottom), the near sector's ceiling above the wall, its
// floor below, and the wall's middle (solid) or upper and lower parts (two-sided).
// On return [top, bottom) is what stays open behind the wall (empty when solid).
void Canvas::draw_hit(int x, const WallHit& hit, int near, int& top, int& bottom) {
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  if (near == kNone) {  // no sector to measure heights from: a wall over every open row
    wall_span(x, top, bottom, side.middle, hit, 0, 255);
    top = bottom;
    return;
  }
  const level::Sector& s = level_->sectors[near];
  const double eye = view_->eye, scale = view_->d / hit.depth;
  auto row = [&](double z) { return view_->row_at(view_->half_h - (z - eye) * scale); };
  Rows r{row(s.ceiling), row(s.floor), 0, 0};
  const level::Sector* b = nullptr;
  bool both_sky = false;
  if (w.two_sided()) {
    b = &level_->sectors[w.sides[1 - hit.side].sector];
    r.back_ceiling = row(b->ceiling);
    r.back_floor = row(b->floor);
    both_sky = s.ceiling_texture == kSky && b->ceiling_texture == kSky;
    if (both_sky) r.ceiling = std::max(r.ceiling, r.back_ceiling);  // Doom's sky hack: no upper part
  }

  // A plane is seen only from its open side. An eye below the near floor (or above
  // the near ceiling) looks into solid matter there: fill it, so no row is left
  // unwritten (Doom would leave a hall of mirrors).
  if (eye < s.ceiling)
    plane_span(x, top, std::min(r.ceiling, bottom), near, true);
  else
    fill_span(x, top, std::min(r.ceiling, bottom), kVoidColor);
  if (eye > s.floor)
    plane_span(x, std::max(r.floor, top), bottom, near, false);
  else
    fill_span(x, std::max(r.floor, top), bottom, kVoidColor);
  const int wall_top = std::max(top, r.ceiling), wall_bottom = std::min(bottom, r.floor);

  if (!b) {
    const int tex = side.middle;
    const double h = tex >= 0 ? level_->textures[tex].height : 0;
    wall_span(x, wall_top, wall_bottom, tex, hit, (w.flags & level::kUnpegLower) ? s.floor + h : s.ceiling, s.light);
    top = bottom;
    return;
  }
  if (b->ceiling < s.ceiling && !both_sky) {
    const double h = side.upper >= 0 ? level_->textures[side.upper].height : 0;
    wall_span(x, wall_top, std::min(wall_bottom, r.back_ceiling), side.upper, hit,
              (w.flags & level::kUnpegUpper) ? s.ceiling : b->ceiling + h, s.light);
  }
  if (b->floor > s.floor)
    wall_span(x, std::max(wall_top, r.back_floor), wall_bottom, side.lower, hit,
              (w.flags & level::kUnpegLower) ? s.ceiling : b->floor, s.light);
  top = std::max(wall_top, r.back_ceiling);
  bottom = std::min(wall_bottom, r.back_floor);
}

void Canvas::count(int x, int y0, int y1) {
  if (dry_) return;
  pixels_ += static_cast<uint64_t>(y1 - y0);
  if (writes_)
    for (int y = y0; y < y1; ++y) ++(*writes_)[size_t(y) * view_->width + x];
}

void Canvas::fill_span(int x, int y0, int y1, uint32_t color) {
  if (y0 >= y1 || dry_) return;
  count(x, y0, y1);
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width) *out = color;
}

// Texture row v at screen row y is v0 + y * step (anchor - height + y offset):
// computed from row 0 so a pixel does not depend on where its span starts.
void Canvas::wall_span(int x, int y0, int y1, int texture, const WallHit& hit, double anchor, int light) {
  if (y0 >= y1 || dry_) return;
  if (texture == kNone) return fill_span(x, y0, y1, kMissingTexture);
  count(x, y0, y1);
  const level::Wall& w = level_->walls[hit.wall];
  const level::Side& side = w.sides[hit.side];
  const level::Texture& tex = level_->textures[texture];
  const double u = (hit.side == 0 ? hit.t : 1 - hit.t) * w.length + side.x_offset;
  const uint32_t* column = tex.column(static_cast<int>(static_cast<int64_t>(std::floor(u)) & tex.width_mask));
  const double inv_scale = hit.depth / view_->d;
  const double v0 = anchor - view_->eye + side.y_offset + (0.5 - view_->half_h) * inv_scale;
  const int64_t step = std::llround(inv_scale * kFix);
  int64_t v = std::llround(v0 * kFix) + y0 * step;
  const uint32_t mult = light_multiplier(light_start(light, w.contrast), kLightK / hit.depth);
  const uint32_t mask = tex.height_mask;
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width, v += step) *out = shade(column[(v >> 16) & mask], mult);
}

// Floor or ceiling at height h: row y's ray meets the plane at k = (eye - h) / dy
// ray lengths, i.e. at pos + ray(x) * k, depth k * d. Exact per pixel.
void Canvas::plane_span(int x, int y0, int y1, int sector, bool ceiling) {
  if (y0 >= y1 || dry_) return;
  const level::Sector& s = level_->sectors[sector];
  const int texture = ceiling ? s.ceiling_texture : s.floor_texture;
  if (texture == kSky) return sky_span(x, y0, y1);
  count(x, y0, y1);
  const level::Texture& tex = level_->textures[texture];
  const double h_rel = view_->eye - (ceiling ? s.ceiling : s.floor);
  const Vec2 ray = view_->ray(x);
  const double px = view_->pos.x * kFix, py = -view_->pos.y * kFix;  // texture v runs south: north is up
  const double rx = ray.x * kFix, ry = -ray.y * kFix;
  const int start = light_start(s.light, 0);
  const double gain_per_dy = kLightK / (std::fabs(h_rel) * view_->d);  // 1280 / depth = 1280 |dy| / (|h| d)
  const uint32_t wmask = tex.width_mask, hmask = tex.height_mask;
  const int shift = tex.height_shift;
  const uint32_t* texels = tex.texels.data();
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width) {
    const double k = h_rel * row_inv_[y];
    const int64_t u = static_cast<int64_t>(px + rx * k) >> 16;
    const int64_t v = static_cast<int64_t>(py + ry * k) >> 16;
    const uint32_t texel = texels[((u & wmask) << shift) | (v & hmask)];
    *out = shade(texel, light_multiplier(start, gain_per_dy * std::fabs(row_dy_[y])));
  }
}

// The sky wraps four times around the horizon and hangs from the top of the screen.
void Canvas::sky_span(int x, int y0, int y1) {
  if (dry_) return;
  if (level_->sky_texture == kNone) return fill_span(x, y0, y1, kVoidColor);
  count(x, y0, y1);
  const level::Texture& tex = level_->textures[level_->sky_texture];
  const double angle = view_->angle + std::atan2(view_->half_w - (x + 0.5), view_->d);
  const int64_t u = static_cast<int64_t>(std::floor(-angle / (2 * M_PI) * 4 * tex.width));
  const uint32_t* column = tex.column(static_cast<int>(u & tex.width_mask));
  const double rows_per_texel = 0.6 * view_->height / tex.height;
  uint32_t* out = pixel(x, y0);
  for (int y = y0; y < y1; ++y, out += view_->width)
    *out = column[std::min<int>(tex.height - 1, static_cast<int>((y + 0.5) / rows_per_texel))];
}

// What a column shows past its last wall: its sector's planes out to the horizon.
void Canvas::planes_to_horizon(int x, int y0, int y1, int sector) {
  if (y0 >= y1) return;
  if (sector == kNone) return fill_span(x, y0, y1, kVoidColor);
  const level::Sector& s = level_->sectors[sector];
  const int horizon = view_->row_at(view_->half_h);  // first row whose centre is not above the horizon
  const int below = horizon < view_->height && row_dy_[horizon] == 0 ? horizon + 1 : horizon;
  const int ceiling_end = std::min(y1, horizon), floor_start = std::max(y0, below);
  if (view_->eye < s.ceiling)
    plane_span(x, y0, ceiling_end, sector, true);
  else
    fill_span(x, y0, ceiling_end, kVoidColor);
  fill_span(x, std::max(y0, horizon), std::min(y1, below), kVoidColor);
  if (view_->eye > s.floor)
    plane_span(x, floor_start, y1, sector, false);
  else
    fill_span(x, floor_start, y1, kVoidColor);
}

void Canvas::finish() {
  for (int x = 0; x < view_->width; ++x) {
    Column& c = columns_[x];
    planes_to_horizon(x, c.top, c.bottom, c.sector);
  }
}

}  // namespace p3d::render
