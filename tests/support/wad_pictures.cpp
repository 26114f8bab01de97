#include "tests/support/wad_pictures.h"

#include "engine/wad/picture.h"

namespace p3d::test {

bool shows_picture(const image::Image& frame, const wad::Stack& wads, const std::vector<uint32_t>& palette,
                   const std::string& lump, int x, int y) {
  const wad::IndexedImage pic = wad::decode_picture(wads.find(lump)->bytes, lump);
  for (int c = 0; c < pic.width; ++c)
    for (int r = 0; r < pic.height; ++r)
      if (pic.opaque[pic.at(c, r)] &&
          frame.at(x - pic.left_offset + c, y - pic.top_offset + r) != palette[pic.indices[pic.at(c, r)]])
        return false;
  return true;
}

int picture_width(const wad::Stack& wads, const std::string& lump) {
  return wad::decode_picture(wads.find(lump)->bytes, lump).width;
}

}  // namespace p3d::test
