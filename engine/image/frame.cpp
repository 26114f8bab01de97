#include "engine/image/frame.h"

#include <algorithm>
#include <array>

#include "engine/image/palette.h"

namespace p3d::image {

void Frame::resolve_colours() {
  pixels.resize(indices.size());  // a frame made without_pixels gets them here
  if (indices.empty()) return;
  std::array<uint32_t, 256> colours{};  // a shorter palette's missing colours black
  std::copy_n(palette.begin(), std::min<size_t>(palette.size(), colours.size()), colours.begin());
  resolve_palette(indices.data(), 0, pixels.data(), 0, int(indices.size()), 1, colours.data());  // rows end to end
}

std::vector<uint8_t> Frame::png(int level) const {
  return indexed() ? encode_png(width, height, indices, palette, level) : encode_png(*this, level);
}

}  // namespace p3d::image
