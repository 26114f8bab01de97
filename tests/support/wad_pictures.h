// Checks of Doom's screens drawn from a WAD's pictures (status bar, intermission).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/wad/wad.h"

namespace p3d::test {

// Whether the WAD picture `lump`'s opaque texels show in `frame` (a 320x200 screen) at
// Doom's place (x, y) of it, offsets applied, in the palette's colours.
bool shows_picture(const image::Image& frame, const wad::Stack& wads, const std::vector<uint32_t>& palette,
                   const std::string& lump, int x, int y);

// The picture's width, as Doom centres and right-aligns by it.
int picture_width(const wad::Stack& wads, const std::string& lump);

}  // namespace p3d::test
