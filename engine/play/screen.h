// Doom's 320x200 screen within a frame: a whole scale and an offset, and its
// pictures drawn there (patches with their offsets, transparent texels skipped), for
// the status bar, the message line and the intermission.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/image/image.h"
#include "engine/wad/picture.h"

namespace p3d::play {

constexpr int kScreenWidth = 320, kScreenHeight = 200;

struct ScreenPlace {
  int scale = 1;
  int left = 0, top = 0;  // where the screen's (0, 0) lies in the frame

  // The largest whole scale at which the screen fits (at least 1).
  static int scale_for(int width, int height) {
    return std::max(1, std::min(width / kScreenWidth, height / kScreenHeight));
  }
  // The screen at that scale, centred across; `rows` of the screen end at the frame's
  // bottom (the status bar's 32), or all 200 centred when rows is 0.
  static ScreenPlace in(const image::Image& frame, int rows = 0) {
    ScreenPlace p;
    p.scale = scale_for(frame.width, frame.height);
    p.left = (frame.width - kScreenWidth * p.scale) / 2;
    p.top = rows ? frame.height - rows * p.scale - (kScreenHeight - rows) * p.scale
                 : (frame.height - kScreenHeight * p.scale) / 2;
    return p;
  }
};

// The picture at the screen's (x, y), its offsets applied, each texel a scale x scale
// square; clipped to the frame.
inline void draw_picture(image::Image& frame, const wad::IndexedImage& pic, int x, int y, const ScreenPlace& at,
                         const std::vector<uint32_t>& palette) {
  const int s = at.scale, x0 = at.left + (x - pic.left_offset) * s, y0 = at.top + (y - pic.top_offset) * s;
  for (int c = 0; c < pic.width; ++c)
    for (int r = 0; r < pic.height; ++r) {
      if (!pic.opaque[pic.at(c, r)]) continue;
      const uint32_t colour = palette[pic.indices[pic.at(c, r)]];
      for (int dy = 0; dy < s; ++dy)
        for (int dx = 0; dx < s; ++dx) {
          const int px = x0 + c * s + dx, py = y0 + r * s + dy;
          if (px >= 0 && py >= 0 && px < frame.width && py < frame.height) frame.at(px, py) = colour;
        }
    }
}

}  // namespace p3d::play
