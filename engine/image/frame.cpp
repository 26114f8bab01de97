#include "engine/image/frame.h"

namespace p3d::image {

void Frame::resolve_colours() {
  pixels.resize(indices.size());  // a frame made without_pixels gets them here
  for (size_t i = 0; i < indices.size(); ++i) pixels[i] = palette[indices[i]];
}

std::vector<uint8_t> Frame::png(PngDeflate how) const {
  return indexed() ? encode_png(width, height, indices, palette, how) : encode_png(*this, how);
}

}  // namespace p3d::image
