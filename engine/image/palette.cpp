#include "engine/image/palette.h"

#include "engine/util/cpu.h"

namespace p3d::image {

bool vector_palette() {
#ifdef P3D_VBMI_PALETTE
  return has_avx512_vbmi();
#else
  return false;
#endif
}

void resolve_palette_scalar(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch,
                            int width, int rows, const uint32_t* palette) {
  for (int y = 0; y < rows; ++y, indices += index_pitch, pixels += pixel_pitch)
    for (int x = 0; x < width; ++x) pixels[x] = palette[indices[x]];
}

void resolve_palette(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch, int width,
                     int rows, const uint32_t* palette) {
  if (vector_palette()) return resolve_palette_vbmi(indices, index_pitch, pixels, pixel_pitch, width, rows, palette);
  resolve_palette_scalar(indices, index_pitch, pixels, pixel_pitch, width, rows, palette);
}

#ifndef P3D_VBMI_PALETTE
// Never called: vector_palette() is false.
void resolve_palette_vbmi(const uint8_t*, size_t, uint32_t*, size_t, int, int, const uint32_t*) {}
#endif

}  // namespace p3d::image
