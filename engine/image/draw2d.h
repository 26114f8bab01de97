// Flat 2D drawing for overlays (HUD, automap, labels): lines, translucent
// rectangles and convex polygons, all clipped to the image.
#pragma once

#include <span>

#include <glm/vec2.hpp>

#include "engine/image/image.h"

namespace p3d::image {

// Mixes `color` over the pixel with opacity alpha in [0, 256].
inline uint32_t blend(uint32_t under, uint32_t color, uint32_t alpha) {
  const uint32_t rb = ((under & 0xFF00FFu) * (256 - alpha) + (color & 0xFF00FFu) * alpha) >> 8 & 0xFF00FFu;
  const uint32_t g = ((under & 0x00FF00u) * (256 - alpha) + (color & 0x00FF00u) * alpha) >> 8 & 0x00FF00u;
  return rb | g | 0xFF000000u;
}

void draw_line(Image& img, glm::dvec2 a, glm::dvec2 b, uint32_t color, uint32_t alpha = 256);
void fill_rect(Image& img, int x, int y, int w, int h, uint32_t color, uint32_t alpha = 256);
void fill_convex(Image& img, std::span<const glm::dvec2> points, uint32_t color, uint32_t alpha = 256);

}  // namespace p3d::image
