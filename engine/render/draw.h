// The only writer of pixels. A Canvas holds, per screen column, the rows still
// open (Doom's ceilingclip/floorclip as one [top, bottom) range) and the sector
// the column's ray is travelling through. Renderers hand it wall hits, column by
// column, nearest first; it draws the wall's visible parts and the floor and
// ceiling in front of it, then narrows (or closes) the column. Masked middle
// textures of two-sided walls are recorded with the rows open through them (Doom's
// drawsegs) and drawn last, farthest first, so what lies behind shows through.
#pragma once

#include <span>
#include <vector>

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
  // Resets every column to fully open, in `camera_sector` (may be kNone).
  void begin(const level::Level& level, const View& view, Frame& frame, int camera_sector, Probe* probe);

  // Front to back: draws what the hit shows in the column's open rows and narrows
  // them. Returns true when this hit closes the column.
  bool draw_wall(int x, const WallHit& hit);

  // Like draw_wall, but only narrows the column (and records the closing hit): the
  // painter replays its hits front to back with this to learn which wall closed a column.
  bool clip_wall(int x, const WallHit& hit);

  // Back to front (painter): draws the hit's wall parts, its masked texture and the
  // planes in front of it over the whole column, ignoring and keeping the column's state.
  void paint_wall(int x, const WallHit& hit);
  // Painter's first coat: the sector's planes out to the horizon over the whole column.
  void paint_background(int x, int sector);

  // Fills the rows still open in every column with the planes of the column's sector,
  // out to the horizon, then draws the recorded masked textures farthest first.
  void finish();

  // Copies the canvas's counts (columns closed, pixels written) into the frame's statistics.
  void count_into(RenderStats& stats) const {
    stats.columns_closed = closed_count_;
    stats.pixels_written = pixels_;
    stats.masked_pixels = masked_pixels_;
  }

 private:
  struct Column {
    int top, bottom;  // open rows [top, bottom)
    int sector;
  };
  // A masked middle texture seen in one column, with the rows open through its wall.
  struct Masked {
    int x;
    WallHit hit;
    int near, far;    // the sectors on the facing and the far side
    int top, bottom;  // rows it may cover
  };
  // A wall part to draw: texture, which part (for its offsets), where its top texel row lies, light.
  struct Part {
    int texture;
    int part;       // level::Part
    double anchor;  // world height of the texture's row 0 (before the side's y offset)
    int light;      // 0..255
  };

  void draw_hit(int x, const WallHit& hit, int near, int& top, int& bottom);
  void close(int x, const WallHit& hit);
  void near_plane(int x, int y0, int y1, int sector, bool ceiling);
  void plane_span(int x, int y0, int y1, int sector, bool ceiling);
  void sky_span(int x, int y0, int y1);
  void wall_span(int x, int y0, int y1, const Part& part, const WallHit& hit);
  void draw_masked(const Masked& m);
  void fill_span(int x, int y0, int y1, uint32_t color);
  void planes_to_horizon(int x, int y0, int y1, int sector);
  int near_sector(const level::Wall& w, const WallHit& hit, int x) const;
  double texture_u(const WallHit& hit, int part) const;
  uint32_t* pixel(int x, int y) { return frame_->pixels.data() + size_t(y) * view_->width + x; }
  void count(int x, int y0, int y1);
  void count_one(int x, int y);

  const level::Level* level_ = nullptr;
  const View* view_ = nullptr;
  Frame* frame_ = nullptr;
  ColumnHits* hits_ = nullptr;         // from the probe, when asked for
  std::vector<uint16_t>* writes_ = nullptr;
  std::vector<Column> columns_;
  std::vector<Masked> masked_;   // in the order met: per column, nearest first
  std::vector<double> row_dy_;   // (y + 0.5) - H/2 per row
  std::vector<double> row_inv_;  // 1 / row_dy_
  uint64_t pixels_ = 0, closed_count_ = 0, masked_pixels_ = 0;
  bool dry_ = false;  // clip_wall: compute rows, write and record nothing
};

}  // namespace p3d::render
