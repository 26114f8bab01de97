// A 5x7 bitmap font (our own design) for labels and the HUD: printable ASCII,
// drawn into an Image in 6x8 cells at any integer scale.
#pragma once

#include <string_view>

#include "engine/image/image.h"

namespace p3d::image {

constexpr int kGlyphWidth = 6, kGlyphHeight = 8;  // cell size, including one pixel of spacing

// Draws text with its top-left corner at (x, y); '\n' starts a new line. Characters
// outside printable ASCII draw as '?'. Clipped to the image.
void draw_text(Image& img, int x, int y, std::string_view text, uint32_t color, int scale = 1);

// Width in pixels of the widest line of text drawn at `scale`.
int text_width(std::string_view text, int scale = 1);

}  // namespace p3d::image
