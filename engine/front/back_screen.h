// Doom's smaller views (screen sizes 3 to 9 of its 11): where the view window lies
// (R_ExecuteSetViewSize), and what surrounds it (R_FillBackScreen): the WAD's flat
// tiled over the screen above the status bar, and the bevelled border pictures
// (BRDR_*) around the window.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "engine/image/image.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::front {

struct ViewWindow {
  int x = 0, y = 0, width = 0, height = 0;
  friend bool operator==(const ViewWindow&, const ViewWindow&) = default;
};

// The view's window in a frame whose area above the status bar is width x
// area_height, Doom's screen drawn at `scale`: at 10 blocks and more the whole area,
// below that blocks tenths of it across and down (the height a multiple of 8 of
// Doom's rows), centred.
ViewWindow view_window(int width, int area_height, int screen_blocks, int scale);

class BackScreen {
 public:
  // nullopt when the WADs lack the flat (GRNROCK for Doom II, FLOOR7_2 for Doom).
  static std::optional<BackScreen> load(const wad::Stack& wads, bool commercial);
  // The flat over the frame's first area_height rows, then the border around `view`;
  // Doom's pixels are scale x scale squares.
  void draw(image::Image& frame, int area_height, const ViewWindow& view, int scale,
            const std::vector<uint32_t>& palette) const;

 private:
  std::vector<uint8_t> flat_;  // 64 x 64, row-major
  // Top left, top, top right, left, right, bottom left, bottom, bottom right.
  std::array<std::optional<wad::IndexedImage>, 8> border_;
};

}  // namespace p3d::front
