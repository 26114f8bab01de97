// The frame a renderer draws into, and on which the game composes what else the
// player sees (the weapon, the status bar): plain data, below both.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/image/image.h"

namespace p3d::image {

// A rendered frame: its colours (the image's pixels), or Doom's 8-bit screen. A
// caller that sets keep_indices lets a level drawn in palette indices stay that way:
// the renderer then leaves `indices` (row-major) and `palette` and does not touch the
// pixels, as Doom leaves its screen to the blit (a paletted PNG needs no colours, and
// a frame's time is then comparable with a Doom port's render-only time).
struct Frame : Image {
  using Image::Image;
  // A frame whose pixels are made by the first render that writes colours: one kept in
  // palette indices never needs them (at 3840x2160, 33 MB not to fill).
  static Frame without_pixels(int width, int height) {
    Frame f;
    f.width = width, f.height = height;
    return f;
  }
  bool keep_indices = false;
  // The width of Doom's screen this frame is a view window of (320: a smaller view of
  // Doom's 320x200 screen, drawn by vanilla's rules at its own width); 0: itself.
  int doom_screen_width = 0;
  std::vector<uint8_t> indices;  // empty unless the last render kept them
  std::vector<uint32_t> palette;
  bool indexed() const { return !indices.empty(); }
  // Writes the pixels from the indices (nothing when not indexed).
  void resolve_colours();
  // The frame as a PNG: a paletted one when it kept its indices (a quarter of the bytes
  // to filter), else its colours.
  std::vector<uint8_t> png(int level = kPngDefaultLevel) const;
};

}  // namespace p3d::image
