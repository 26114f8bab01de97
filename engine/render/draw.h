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

#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "engine/render/plane_spans.h"
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
  // Resets every column to fully open, in `camera_sector` (may be kNone). A canvas may
  // own only the columns [x0, x1) of the frame (a strip drawn by its own thread): it then
  // draws nothing outside them, and the probe's arrays must have been sized already
  // (prepare_probe), since other strips fill them at the same time.
  void begin(const level::Level& level, const level::State& state, const View& view, Frame& frame, int camera_sector,
             Probe* probe, int x0 = 0, int x1 = INT32_MAX);
  static void prepare_probe(const View& view, Probe* probe);
  // Sizes the frame's indices when it keeps them and the level is drawn in indices;
  // like prepare_probe, done by begin() for a canvas that owns the whole frame.
  static void prepare_frame(const level::Level& level, Frame& frame);
  // For a renderer that draws over its own pixels (the painter): write the frame's
  // colours at once rather than palette indices resolved at the end (see indexed_).
  void draw_directly() {
    indexed_ = false;
    frame_->indices.clear();
  }

  // Front to back: draws what the hit shows in the column's open rows and narrows
  // them. Returns true when this hit closes the column.
  bool draw_wall(int x, const WallHit& hit);

  // Like draw_wall, but only narrows the column (and records the step): the painter
  // replays its hits front to back with this to learn what each column saw.
  bool clip_wall(int x, const WallHit& hit);

  // Back to front (painter): draws the hit's wall parts and the planes in front of
  // it over the whole column, ignoring and keeping the column's state.
  void paint_wall(int x, const WallHit& hit);
  // Painter's first coat: the sector's planes out to the horizon over the whole column.
  void paint_background(int x, int sector);

  // A thing that may be seen, by its index in state.things (the BSP renderer adds those
  // its walk reaches, the others all of them); things showing no frame are ignored.
  void add_sprite(uint32_t thing);

  // Fills the rows still open in every column with the planes of the column's
  // sector, out to the horizon, draws the floors and ceilings filed so far as rows,
  // then draws the layers (see draw_layers).
  void finish();
  // Writes rows [y0, y1) of the canvas's columns into the frame, after finish(), when
  // it drew palette indices (a no-op otherwise): the indices themselves when the frame
  // keeps them, else their colours. Strips may resolve rows in any order.
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
  };
  // One wall met by one column, front to back: what stays open behind it.
  struct Step {
    WallHit hit;
    int near, far;    // the sectors on the facing and the far side (far: kNone when one-sided)
    int top, bottom;  // rows open behind the wall
    bool masked;      // it shows a masked middle texture in that opening
  };
  // A wall part to draw: texture, which part (for its offsets), where its top texel row lies, light.
  struct Part {
    int texture;
    int part;       // level::Part
    double anchor;  // world height of the texture's row 0 (before the side's y offset)
    int light;      // 0..255
  };
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
  };

  bool draw_hit(int x, const WallHit& hit, int near, int& top, int& bottom);
  void close(int x, const WallHit& hit);
  void near_plane(int x, int y0, int y1, int sector, bool ceiling);
  void plane_span(int x, int y0, int y1, int sector, bool ceiling);
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
  int fixed_or(int map) const;
  uint32_t* pixel(int x, int y) { return frame_->pixels.data() + size_t(y) * view_->width + x; }
  uint8_t* index_pixel(int x, int y) { return indices_.data() + size_t(y) * index_pitch_ + size_t(x - x0_); }
  void count(int x, int y0, int y1);

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
  // Paletted levels draw palette indices (Doom's 8-bit screen) into the canvas's own
  // columns, rows index_pitch_ apart, and resolve() copies them to the frame or looks
  // the palette up once per pixel: a strip of 160 columns of 400 rows is 64 KB, where
  // the 32-bit frame's columns are 2,560 bytes apart. (RGBA levels, and light maps
  // with shades outside the palette, write the frame.)
  bool indexed_ = false;
  std::vector<uint8_t> indices_;
  size_t index_pitch_ = 0;
  // What fills show: on paletted levels the palette's nearest colours, so they have indices.
  uint32_t fill_colors_[2] = {};
  uint8_t fill_indices_[2] = {};
  uint64_t pixels_ = 0, closed_count_ = 0, masked_pixels_ = 0, sprites_drawn_ = 0, sprite_pixels_ = 0;
  bool dry_ = false;       // clip_wall: compute rows, write nothing
  bool painting_ = false;  // paint_wall, paint_background: draw planes at once
};

}  // namespace p3d::render
