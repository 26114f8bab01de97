// The only writer of pixels. A Canvas holds, per screen column, the rows still
// open (Doom's ceilingclip/floorclip as one [top, bottom) range) and the sector
// the column's ray is travelling through. Renderers hand it wall hits, column by
// column, nearest first; it draws the wall's visible parts, files the floor and
// ceiling in front of it (drawn as rows by finish(), Doom's visplanes), then narrows
// (or closes) the column, and remembers each step (Doom's drawsegs, per column).
// Renderers also hand it the things that may be seen; finish() then draws the
// layers over the solid picture farthest first: the
// masked middle textures of two-sided walls and the sprites, each clipped to the
// rows its column had open at its depth, so what lies behind shows through.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "engine/render/column_major.h"
#include "engine/render/plane_spans.h"
#include "engine/render/texel_loops.h"
#include "engine/render/view.h"

namespace p3d::render {

// One wall seen in one column.
struct WallHit {
  uint32_t wall;
  int side;      // the side facing the camera: 0 front, 1 back
  double depth;  // along the view direction
  double t;      // parameter along the wall, 0 at p1
  int32_t fragment = -1;  // the BSP fragment drawn, when there is one
};

class Canvas {
 public:
  // Resets every column to fully open, in `camera_sector` (may be kNone), for a canvas
  // that owns the whole frame: sizes the frame and the probe first.
  void begin(const level::Level& level, const level::State& state, const View& view, Frame& frame, int camera_sector,
             Probe* probe);
  // The same for a canvas that owns only the columns [x0, x1) of the frame (a strip
  // drawn by its own thread): it draws nothing outside them, and its renderer has sized
  // the frame and the probe's arrays already (prepare_frame, prepare_probe), since other
  // strips fill them at the same time. Under Doom's rules it also names the canvas of
  // the strip to its left (its flats' spans may begin there: see finish_strip).
  void begin_strip(const level::Level& level, const level::State& state, const View& view, Frame& frame,
                   int camera_sector, Probe* probe, int x0, int x1, const Canvas* left);
  static void prepare_probe(const View& view, Probe* probe);
  // Whether the canvas may draw its columns column-major, and its flats, with AVX-512
  // VBMI where the processor has it (column_major.h); the same pixels either way.
  // Before begin().
  void allow_vector_columns(bool allow) { vector_columns_allowed_ = allow; }
  // Sizes the frame's indices when it keeps them and the level is drawn in indices;
  // like prepare_probe, done by begin() for a canvas that owns the whole frame.
  static void prepare_frame(const level::Level& level, Frame& frame);
  // For a renderer that draws over its own pixels (the painter): write the frame's
  // colours at once rather than palette indices resolved at the end (see indexed_).
  void draw_directly() {
    indexed_ = vector_loops_ = columns_pending_ = false;
    frame_->indices.clear();
    if (doom_) start_painted_planes();
  }

  // Front to back: draws what the hit shows in the column's open rows and narrows
  // them. Returns true when this hit closes the column.
  bool draw_wall(int x, const WallHit& hit);
  // One wall side's hits in a fragment's open columns, in column order: their columns,
  // depths and wall parameters side by side, as the walk's projection writes them.
  struct WallHits {
    uint32_t wall;
    int side;
    int32_t fragment;
    std::span<const int32_t> x;
    const double* depth;
    const double* t;
    size_t size() const { return x.size(); }
    WallHit operator[](size_t k) const { return {wall, side, depth[k], t[k], fragment}; }
  };
  // Hit k of hits, made a WallHit only where one is kept (record_step).
  struct WallHitRef {
    const WallHits& hits;
    size_t k;
    operator WallHit() const { return hits[k]; }
  };
  // draw_wall for each of one wall's hits in turn, appending to `closed` each column a
  // hit closes. Under Doom's rules the hits on one of its segs are drawn as a run, the
  // seg looked up and its numbers copied out once (the same pixels as hit by hit).
  void draw_walls(const WallHits& hits, std::vector<int>& closed);

  // Like draw_wall, but only narrows the column (and records the step): the painter
  // replays its hits front to back with this to learn what each column saw.
  bool clip_wall(int x, const WallHit& hit);

  // Back to front (painter): draws the hit's wall parts and the planes in front of
  // it over the whole column, ignoring and keeping the column's state.
  void paint_wall(int x, const WallHit& hit);
  // Painter's first coat: the sector's planes out to the horizon over the whole column.
  void paint_background(int x, int sector);

  // A thing's sprite as this view sees it.
  struct Sprite {
    uint32_t thing;               // index in state.things
    double depth;                 // of the thing's position along the view direction
    int x0, x1;                   // columns it may cover
    const level::Texture* texture;
    bool flip;
    double left;                  // lateral position (right of the view axis) of the picture's left edge
    double top;                   // world height of the picture's top row
    int light_map;                // 0 (full bright) .. 31
    bool fuzz;                    // Doom's shadow (MF_SHADOW)
    // Doom's rules (R_ProjectSprite): its scale, texel column at unclipped column x_start
    // and step per column, and the height of its top above the eye.
    doom::Fixed scale = 0, start_frac = 0, x_step = 0, texture_mid = 0, gz = 0, gzt = 0;
    int x_start = 0;
    doom::Fixed gx = 0, gy = 0;
  };
  // Doom's rules: every thing's sprite as the view projects it (R_ProjectSprite),
  // clipped to the screen, once a frame for all the strips rather than by each.
  static void project_doom_sprites(const level::Level& level, const level::State& state, const View& view,
                                   std::vector<Sprite>& out);
  // R_ProjectSprite of one thing over the whole screen; false when it shows nothing there.
  static bool project_doom_sprite(const level::Level& level, const level::State& state, const View& view,
                                  uint32_t thing, Sprite& s);
  // Those of a frame's projected sprites that cross this canvas's columns. With
  // `all`, they are every sprite the canvas will draw, added before any wall: a
  // column's steps are then kept only where a sprite or a masked middle needs them.
  void add_projected_sprites(std::span<const Sprite> sprites, bool all = false);

  // A thing that may be seen, by its index in state.things (the BSP renderer adds those
  // its walk reaches, the others all of them); things showing no frame are ignored.
  void add_sprite(uint32_t thing);

  // Fills the rows still open in every column with the planes of the column's
  // sector, out to the horizon, draws the floors and ceilings filed so far as rows,
  // then draws the layers (see draw_layers).
  void finish();
  // For a strip (a canvas of some columns): after every strip of the frame has finished,
  // what finish() left for later under Doom's rules, where a flat's span steps from its
  // first column, which may lie in a strip to the left: the flats and the layers. A
  // no-op under our rules, and for a canvas of the whole frame.
  void finish_strip();
  bool waiting() const { return doom_waiting_; }  // finish() left work to finish_strip()
  // Writes the colours of rows [y0, y1) of the canvas's columns into the frame, after
  // finish(), when it drew palette indices into its own columns (a no-op otherwise: a
  // frame that keeps its indices was drawn in). Strips may resolve rows in any order.
  void resolve(int y0, int y1);
  bool drew_indices() const { return indexed_; }
  // Masked middle textures and sprites, farthest first in every column, each clipped
  // to the rows its column had open at its depth. Equal depths: the masked wall
  // first, then sprites by thing index. Shadows (kShownShadow) darken what lies
  // around them (draw_fuzz).
  void draw_layers();

  // The things whose sprite wrote a pixel (strips merge them: a sprite across two
  // strips is one sprite drawn).
  const std::vector<uint32_t>& things_drawn() const { return things_drawn_; }

  // Copies the canvas's counts into the frame's statistics.
  void count_into(RenderStats& stats) const {
    stats.columns_closed = closed_count_;
    stats.pixels_written = pixels_;
    stats.masked_pixels = masked_pixels_;
    stats.sprites_drawn = sprites_drawn_;
    stats.sprite_pixels = sprite_pixels_;
  }

 private:
  struct Column {
    int top, bottom;  // open rows [top, bottom)
    int sector;
    uint32_t nearest_masked = UINT32_MAX;  // its first step with a masked middle texture (none: UINT32_MAX)
    bool sprite = false;                   // a sprite crosses it (add_projected_sprites)
  };
  // One wall met by one column, front to back: what stays open behind it.
  static constexpr uint32_t kNoDoomSide = UINT32_MAX;
  struct Step {
    WallHit hit;
    int near, far;    // the sectors on the facing and the far side (far: kNone when one-sided)
    int top, bottom;  // rows open behind the wall
    bool masked;      // it shows a masked middle texture in that opening
    uint32_t doom_side = kNoDoomSide;  // its DoomSide's index, as draw_hit_doom found it
    bool masked_drawn = false;         // doom_draw_layers drew its masked texture
  };
  // A wall part to draw: texture, which part (for its offsets), where its top texel row lies, light.
  struct Part {
    int texture;
    int part;       // level::Part
    double anchor;  // world height of the texture's row 0 (before the side's y offset)
    int light;      // 0..255
  };
  // Doom's rules: one side of a wall as this frame's view sets it up (R_StoreWallRange),
  // made on first use in a frame (doom_side).
  struct DoomSide {
    doom::Seg seg;
    doom::Fixed v1x = 0, v1y = 0, v2x = 0, v2y = 0;  // the seg's first vertex, the side's end (R_PointOnSegSide)
    doom::Fixed low_scale = 0, high_scale = 0;       // its scales at the ends of its columns (drawsegs)
    doom::WallPrecision precision;                   // its largest scale and edge bits (Crispy's wiggle fix)
    // Its silhouettes as R_DrawSprite reads them, worked out once a frame, on a
    // sprite's first look (doom_silhouette): a sprite whose foot lies below
    // bottom_height meets its bottom clip, one whose top lies above top_height its top
    // clip (INT64_MIN and INT64_MAX: none); closed, that clip shuts the whole column.
    bool silhouette_ready = false;
    bool bottom_closed = false, top_closed = false;
    int64_t bottom_height = 0, top_height = 0;
    // Its wall as R_StoreWallRange sets it up, worked out on the first column a frame
    // draws it (set_up_doom_wall), so the column loop keeps only R_RenderSegLoop's steps.
    // Kept for the near sector it was made for: a segment's may vary by column.
    bool wall_ready = false;
    int near = 0, far = 0;  // far: kNone when one-sided
    doom::Fixed worldtop = 0, worldbottom = 0, worldhigh = 0, worldlow = 0;
    bool mark_ceiling = true, mark_floor = true, top_part = false, bottom_part = false;
    bool ceiling_plane = false, floor_plane = false;  // a plane to draw, else the void
    // Its near sector's floor and ceiling (by bool ceiling) as filed: a plane of planes_,
    // kSkyPlane, or kPlaneNotFound before the first run (doom_plane_span).
    int planes[2] = {kPlaneNotFound, kPlaneNotFound};
    doom::Fixed x_offset = 0;                          // the side's, scrolled
    int start_map = 0;                                 // its light before distance
    int textures[3] = {};                              // per level::Part, as shown
    doom::Fixed part_x[3] = {}, mid[3] = {};           // per part: column offset, texture mid
  };

  bool draw_hit(int x, const WallHit& hit, int near, int& top, int& bottom);
  // draw_wall's bookkeeping around draw(top, bottom), which draws the hit into the
  // column's open rows [top, bottom), narrows them and returns whether it shows a
  // masked middle texture: the column's new rows and sector (far, the sector behind the
  // wall, when it has one), its step; true when closed.
  template <typename Hit, typename Draw>  // Hit: a WallHit or a WallHitRef
  bool record_step(int x, const Hit& hit, int near, int far, Draw&& draw);
  // Doom's rules (draw_doom.cpp): R_StoreWallRange and R_RenderSegLoop for one column.
  bool draw_hit_doom(int x, const WallHit& hit, int near, int& top, int& bottom);
  // What R_RenderSegLoop's columns of one side share, copied out of its DoomSide (set
  // up first if need be) for a run of columns: the loop then keeps them in registers
  // rather than reading them again behind every pixel store (bytes may alias anything).
  struct DoomRun;
  DoomRun doom_run(DoomSide& ds, const WallHit& hit, int near);
  // A column's wall edges as screen rows before any clip: R_RenderSegLoop's yl and yh
  // (top, bottom) and its upper and lower parts' mid rows (high, low; set only where
  // the run has those parts).
  struct EdgeRows {
    std::vector<int32_t> rows;  // the four, n columns each
    int32_t *top, *bottom, *high, *low;
  };
  // The edges of n columns of a run from their scales, worked out together before any
  // column is drawn (eight at a time where vector_scales_).
  void doom_edge_rows(const DoomRun& run, const doom::Fixed* scales, size_t n, EdgeRows& rows) const;
  // One column of R_RenderSegLoop from its side's run; k its place in the run's rows.
  bool doom_column(DoomRun& run, int x, doom::Fixed scale, const EdgeRows& edges, size_t k, int& top, int& bottom);
  void draw_doom_walls(const WallHits& hits, std::vector<int>& closed);
  // A step's DoomSide: the one its column drew, so the sprites' scan of every
  // column's walls skips the search for the seg.
  DoomSide& doom_side(const Step& step) {
    if (step.doom_side != kNoDoomSide) return doom_sides_[step.doom_side];
    return doom_side(step.hit.wall, step.hit.side, step.hit.t);
  }
  // The side's seg at the wall's parameter t, set up on first use in a frame: the lookup
  // inline (a column asks for it at every wall, and a sprite's column again), the set-up not.
  // [*t_low, *t_high), when asked for: the wall parameters whose hits find the same seg.
  DoomSide& doom_side(uint32_t wall, int side, double t, double* t_low = nullptr, double* t_high = nullptr) {
    const level::Level& l = *level_;
    const size_t side_index = size_t(wall) * 2 + size_t(side);
    size_t index = l.doom_segs.size() + side_index;  // the side as one seg
    double low = -INFINITY, high = INFINITY;
    if (side_index + 1 < l.doom_seg_start.size()) {
      const uint32_t first = l.doom_seg_start[side_index], end = l.doom_seg_start[side_index + 1];
      if (first < end) {  // the last seg starting at or before t (the first when none does)
        uint32_t i = first;
        while (i + 1 < end && l.doom_segs[i + 1].t0 <= t) ++i;
        index = i;
        if (i > first) low = l.doom_segs[i].t0;
        if (i + 1 < end) high = l.doom_segs[i + 1].t0;
      }
    }
    if (t_low) *t_low = low, *t_high = high;
    uint64_t& slot = doom_side_slots_[index];
    if (slot >> 32 == doom_stamp_) return doom_sides_[uint32_t(slot)];
    slot = uint64_t(doom_stamp_) << 32 | doom_sides_.size();
    DoomSide& d = doom_sides_.emplace_back();  // reserved: no reference to another moves
    set_up_doom_side(d, wall, side, index < l.doom_segs.size() ? &l.doom_segs[index] : nullptr);
    return d;
  }
  void set_up_doom_side(DoomSide& d, uint32_t wall, int side, const level::Level::DoomSeg* seg);
  void set_up_doom_wall(DoomSide& d, const WallHit& hit, int near);
  // A wall part's texture as a run's columns draw it, looked up once a run.
  struct DoomPart {
    int texture;                // kNone: none
    const level::Texture* tex;  // null with none
    int width_mask;             // Doom's: the largest power of two within the width, less one
    doom::Fixed mid, x;         // the texture's mid (pegged, offset) and its column offset
    // Crispy's rules, indices, the vector loops on and 2^rows_log2 rows (at most 256):
    // a column of 16 rows or more goes straight to wall_column_vbmi.
    bool vector = false;
    int rows_log2 = 0;
  };
  // Rows [y0, y1) of a wall column as R_DrawColumn draws them: texel row
  // ((mid + (y - centery) * iscale) >> 16) & 127, column `column` & the part's width mask.
  void doom_wall_rows(int x, int y0, int y1, const DoomPart& part, int32_t column, uint32_t iscale, int map);
  void crispy_wall_rows(int x, int y0, int y1, const level::Texture& tex, int u, doom::Fixed v0, uint32_t iscale, int map);
  // Pixels [xa, xb) of row y of a flat, its span stepping from column `start` <= xa.
  void doom_plane_pixels(const PlaneKey& key, int y, int xa, int xb, int start);
  // Crispy's rules: a flat's row [xa, xb) of row y set up (R_MapPlane), then drawn.
  struct CrispyRow {
    const level::Texture* texture;
    int y, xa, xb;
    uint32_t xfrac = 0, yfrac = 0, xstep = 0, ystep = 0;  // column xa's texel position and the steps
    int map = 0;
  };
  CrispyRow crispy_row(const PlaneKey& key, int y, int xa, int xb) const;
  // n pixels of a flat's row in palette indices (texel_loops.h's indexed_row), by the
  // vector loop where the canvas may use it.
  void indexed_flat_row(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                        const uint8_t* light_map) const;
  void draw_crispy_row(const CrispyRow& row);
  void draw_crispy_flats();
  // The flats as spans: gathered from the planes filed (doom_gather_spans), each span
  // merged with its neighbours of the same plane, then drawn (doom_draw_spans), a span
  // at the strip's left edge from where it begins in the strips to the left.
  void doom_gather_spans();
  void doom_draw_spans();
  // The painter's flats: the plane each pixel shows last (painted_plane_), drawn at the
  // end as spans of equal planes.
  void start_painted_planes();
  void mark_painted(int x, int y0, int y1, uint32_t id);
  void draw_painted_planes();
  void doom_sky_span(int x, int y0, int y1);
  void doom_draw_layers();
  const DoomSide& doom_silhouette(const Step& step);
  void doom_draw_masked(int x, const Step& step);
  // R_DrawMaskedColumn: rows of texture column u from its opaque runs, the picture's
  // top at screen position top_screen (16.16), clipped to [top, bottom).
  bool doom_masked_column(int x, int top, int bottom, const level::Texture& tex, int u, doom::Fixed top_screen,
                          doom::Fixed scale, uint32_t iscale, doom::Fixed mid, int light_map, uint64_t& counter,
                          bool fuzz);
  void close(int x, const WallHit& hit);
  void near_plane(int x, int y0, int y1, int sector, bool ceiling);
  void plane_span(int x, int y0, int y1, int sector, bool ceiling);
  // plane_span for a Doom side's near sector: its plane found once a frame, not per column.
  // Inline for a plane already found (two calls a wall column); the plane's first run,
  // the sky and the painter go out of line.
  static constexpr int kPlaneNotFound = -1, kSkyPlane = -2;
  void doom_plane_span(DoomSide& ds, int x, int y0, int y1, bool ceiling);
  void doom_plane_span_otherwise(DoomSide& ds, int x, int y0, int y1, bool ceiling);
  // Row y of a plane: texture coordinates 16.16 at column 0 and per column, light map.
  struct PlaneRow {
    uint64_t u0, du, v0, dv;  // texture v runs south: north is up
    int light_map;
  };
  PlaneRow plane_row(const PlaneKey& key, int y) const;
  void plane_pixels(const PlaneKey& key, int y, int xa, int xb);
  void plane_column(const PlaneKey& key, int x, int y0, int y1);
  const PlaneRow* painted_rows(const PlaneKey& key, int y0, int y1);
  void sky_span(int x, int y0, int y1);
  void tabulate_sky_rows();
  void light_sky();
  void wall_span(int x, int y0, int y1, const Part& part, const WallHit& hit);
  void draw_masked(int x, const Step& step);
  void draw_sprite_column(const Sprite& s, int x, int top, int bottom, bool& drew);
  // Rows [top, bottom) of column x of a layer (a masked middle texture, a sprite):
  // texture column u, texel row (v0 + y * step) >> 16, drawn where the texture is
  // opaque, by its runs of opaque texels (no test per pixel) and never tiled; as
  // Doom's fuzz (draw_fuzz) when `fuzz`. Counts the pixels into counter; returns
  // whether it drew one.
  bool layer_column(int x, int top, int bottom, const level::Texture& tex, int u, int64_t v0, int64_t step, int light_map,
                    uint64_t& counter, bool fuzz = false);
  // Doom's fuzz over rows [y0, y1) of column x: each pixel takes the colour of the one
  // a row above or below it, darkened.
  void draw_fuzz(int x, int y0, int y1);
  uint32_t fuzz_colour(uint32_t colour);
  enum class Fill { kVoid, kMissingTexture };
  void fill_span(int x, int y0, int y1, Fill fill);
  void choose_fill_colors();
  void planes_to_horizon(int x, int y0, int y1, int sector);
  int near_sector(const level::Wall& w, const WallHit& hit, int x) const;
  double texture_u(const WallHit& hit, int part) const;
  uint32_t lit(const level::Texture& tex, size_t texel, int light_map) const;
  int fixed_or(int map) const { return state_->fixed_light_map < 0 ? map : fixed_or(*level_, *state_, map); }
  static int fixed_or(const level::Level& level, const level::State& state, int map);
  uint32_t* pixel(int x, int y) { return frame_->pixels.data() + size_t(y) * view_->width + x; }
  uint8_t* index_pixel(int x, int y) { return index_base_ + size_t(y) * index_pitch_ + size_t(x - x0_); }
  // A pixel of a column (a wall, the sky, a fill, a layer), rows column_pitch_ apart: in
  // column_scratch_ until end_columns(), then the one index_pixel gives.
  uint8_t* column_pixel(int x, int y) {
    return column_base_ + size_t(x - x0_) * column_stride_ + size_t(y) * column_pitch_;
  }
  // Turns the columns drawn so far into the rows of the indices, before the first row is
  // drawn (finish); a no-op once done, and on canvases that draw no indices.
  void end_columns();
  // count rows of a wall column in palette indices from row y0: texel row (v >> 16) mod
  // period of the column `source` (period >> 16 rows, v and step reduced) under `light`.
  // Inline: its callers' periods are a texture's height, so most of its tests fold away.
  [[gnu::always_inline]] void indexed_wall_column(int x, int y0, int count, int64_t v, int64_t step, int64_t period,
                                                  const uint8_t* source, const uint8_t* light) {
    const int64_t rows = period >> 16;
    if (columns_pending_ && count >= kVectorColumnRows && (period & 0xFFFF) == 0 && rows > 0 && rows <= 256) {
      if ((rows & (rows - 1)) == 0)
        return wall_column_vbmi(column_pixel(x, y0), count, uint32_t(v), uint32_t(step),
                                std::countr_zero(uint64_t(rows)), source, light);
      return wrapped_column_vbmi(column_pixel(x, y0), count, uint32_t(v), uint32_t(step), int(rows), source, light);
    }
    wrapped_column(column_pixel(x, y0), column_pitch_, count, v, step, period, IndexedColumn{source, light});
  }
  void count(int x, int y0, int y1) {
    pixels_ += static_cast<uint64_t>(y1 - y0);
    if (writes_) count_writes(x, y0, y1);
  }
  void count_writes(int x, int y0, int y1);

  const level::Level* level_ = nullptr;
  const level::State* state_ = nullptr;
  const View* view_ = nullptr;
  Frame* frame_ = nullptr;
  ColumnHits* hits_ = nullptr;         // from the probe, when asked for
  std::vector<uint16_t>* writes_ = nullptr;
  std::vector<Column> columns_;
  std::vector<std::vector<Step>> steps_;  // per column, nearest first
  PlaneSpans planes_;  // floors and ceilings waiting for finish()
  // The painter's planes: rows computed once a frame, on first use.
  struct PaintedPlane {
    std::vector<PlaneRow> rows;
    std::vector<uint8_t> ready;
  };
  std::unordered_map<PlaneKey, size_t, PlaneKeyHash> painted_index_;
  std::vector<PaintedPlane> painted_;
  size_t painted_count_ = 0;
  std::vector<Sprite> sprites_;
  bool sprites_known_ = false;  // sprites_ holds every sprite of the strip (add_projected_sprites)
  std::vector<uint32_t> things_drawn_;
  int x0_ = 0, x1_ = 0;  // the columns this canvas owns
  std::vector<int> layer_cursor_;  // draw_layers: per column, the farthest step not yet passed
  std::vector<double> row_dy_;   // (y + 0.5) - H/2 per row
  std::vector<double> row_inv_;  // 1 / row_dy_
  std::vector<int> sky_rows_;       // the sky's texture row at each screen row
  std::vector<double> sky_angles_;  // each column's angle left of the view direction, radians
  struct SkyKey {
    int texture_height = 0;
    double d = 0, half_h = 0;
    int height = 0;
    double half_w = 0;
    int width = 0;
    bool operator==(const SkyKey&) const = default;
  };
  SkyKey sky_key_;  // what sky_rows_ and sky_angles_ were tabulated for
  std::vector<uint8_t> lit_sky_;  // paletted levels: the sky's indices, full bright
  std::pair<uint64_t, int> lit_sky_for_{0, -1};  // the level generation and sky texture lit_sky_ is of
  // Paletted levels drawn in colours: each palette colour's first index, for the fuzz
  // (found on first use in a frame; fuzz_index_for_ is the level generation it is of).
  std::unordered_map<uint32_t, uint8_t> fuzz_index_;
  uint64_t fuzz_index_for_ = 0;
  bool fuzz_ready_ = false;
  // Paletted levels draw palette indices (Doom's 8-bit screen), rows index_pitch_
  // apart: into the frame's own when it keeps them (strips share a row's cache line at
  // their edges only: two strips on two threads drew 2-5% faster so than into their
  // own columns copied at the end); else into the canvas's own columns, whose colours
  // resolve() looks up once per pixel: a strip of 320 columns of 400 rows is 128 KB,
  // where the 32-bit frame's columns are 2,560 bytes apart. (RGBA levels, and light
  // maps with shades outside the palette, write the frame.)
  bool indexed_ = false;
  std::vector<uint8_t> indices_;
  uint8_t* index_base_ = nullptr;  // at column x0_ of row 0: in the frame, or indices_
  size_t index_pitch_ = 0;
  // Where the processor has the vector column loops (vector_columns()), the walk draws
  // its columns (walls, skies, fills) column-major, a column's rows adjacent bytes, 64
  // of which the loops draw at once, and end_columns() turns them into the rows
  // (column_major.h); elsewhere column_pixel is index_pixel from the start.
  std::vector<uint8_t> column_scratch_;
  uint8_t* column_base_ = nullptr;           // column x0_'s row 0
  size_t column_stride_ = 0, column_pitch_ = 0;  // from one column to the next, one row to the next
  bool vector_loops_ = false;     // this frame: indices drawn, the vector loops allowed and on this processor
  bool columns_pending_ = false;  // columns in column_scratch_ (only with the vector loops), not yet in the rows
  bool vector_columns_allowed_ = true;
  // What fills show: on paletted levels the palette's nearest colours, so they have indices.
  uint32_t fill_colors_[2] = {};
  uint8_t fill_indices_[2] = {};
  uint64_t pixels_ = 0, closed_count_ = 0, masked_pixels_ = 0, sprites_drawn_ = 0, sprite_pixels_ = 0;
  // Doom's rules (View::doom), when the view follows them: the tables, the flats'
  // stepping across the screen (basexscale, baseyscale), each wall side's seg.
  const doom::Tables* doom_ = nullptr;
  doom::Fixed base_x_scale_ = 0, base_y_scale_ = 0;
  uint32_t doom_stamp_ = 0;
  std::vector<doom::Fixed> run_scales_;  // draw_doom_walls' scratch: a run's columns' scales
  EdgeRows run_edges_;                    // and their edges' rows
  bool vector_scales_ = false;           // this frame: the scales eight at a time (vector_projection())
  uint32_t drawn_doom_side_ = kNoDoomSide;  // the DoomSide draw_hit_doom last drew, for its Step
  // This frame's sides in the order first met, packed: a strip touches a few hundred of
  // a level's thousands, and one slot per seg (this frame's stamp above its place in
  // doom_sides_) finds them. Reserved for every seg, so that none ever moves.
  std::vector<DoomSide> doom_sides_;
  std::vector<uint64_t> doom_side_slots_;
  struct DoomSkyKey {  // what doom_sky_rows_ were tabulated for
    const doom::Tables* tables = nullptr;
    uint64_t generation = 0;
    int texture = -1;
    bool operator==(const DoomSkyKey&) const = default;
  };
  DoomSkyKey doom_sky_key_;
  std::vector<int> doom_sky_rows_;
  std::vector<uint8_t> doom_sky_row_bytes_;  // the same, when the sky is at most 256 texels tall (else empty)
  static constexpr uint32_t kNoPlane = UINT32_MAX;
  struct DoomSpan {
    const PlaneKey* key;
    int xa, xb;
  };
  std::vector<CrispyRow> crispy_rows_;       // draw_crispy_flats' batch
  std::vector<DoomSpan> doom_spans_;         // this frame's flat spans, row by row
  std::vector<uint32_t> doom_row_first_;     // per row, and one more: its first span in doom_spans_
  std::vector<int> doom_span_y_;             // doom_gather_spans' scratch: each span's row
  std::vector<DoomSpan> doom_span_scratch_;
  std::vector<uint32_t> doom_span_next_;     // doom_gather_spans' scratch: where each row's next span goes
  const Canvas* left_ = nullptr;             // the strip to the left (begin)
  bool doom_waiting_ = false;                // finish() left the flats and layers to finish_strip()
  std::vector<uint32_t> painted_plane_;      // the painter's: per pixel, its plane in painted_keys_, or kNoPlane
  std::vector<PlaneKey> painted_keys_;
  bool painting_planes_ = false;
  bool dry_ = false;       // clip_wall: compute rows, write nothing
  bool painting_ = false;  // paint_wall, paint_background: draw planes at once
};

inline void Canvas::doom_plane_span(DoomSide& ds, int x, int y0, int y1, bool ceiling) {
  if (y0 >= y1 || dry_) return;
  const int plane = ds.planes[ceiling];
  if (plane < 0 || painting_) return doom_plane_span_otherwise(ds, x, y0, y1, ceiling);
  count(x, y0, y1);
  planes_.add_to(plane, x, y0, y1);
}

template <typename Hit, typename Draw>
bool Canvas::record_step(int x, const Hit& hit, int near, int far, Draw&& draw) {
  Column& c = columns_[x];
  int top = c.top, bottom = c.bottom;
  drawn_doom_side_ = kNoDoomSide;
  const bool masked = draw(top, bottom);
  if (far != level::kNone) c.sector = far;
  c.top = top;
  c.bottom = bottom;
  if (masked && c.nearest_masked == UINT32_MAX) c.nearest_masked = uint32_t(steps_[x].size());
  if (masked || c.sprite || !sprites_known_) steps_[x].push_back({hit, near, far, top, bottom, masked, drawn_doom_side_});
  if (top < bottom) return false;
  close(x, hit);
  return true;
}

inline void Canvas::indexed_flat_row(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                                     const uint8_t* light_map) const {
  // A short row keeps the scalar loop, as short wall columns do (8 and 32 pixels as the
  // threshold took the same time as 16).
  if (vector_loops_ && n >= 16) return flat_row_vbmi(out, n, u, v, indices, light_map);
  indexed_row(out, n, u, v, indices, light_map);
}

}  // namespace p3d::render
