// Palette indices turned into colours, as Doom's blit turns its 8-bit screen into the
// display's: what a frame kept in indices shows.
#pragma once

#include <cstddef>
#include <cstdint>

namespace p3d::image {

// pixels[x] = palette[indices[x]] for `rows` rows of `width` pixels, the rows
// index_pitch bytes and pixel_pitch pixels apart; palette has 256 colours. 64 pixels at
// a time where the processor has AVX-512 VBMI.
void resolve_palette(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch, int width,
                     int rows, const uint32_t* palette);

// The two ways, for the tests: one pixel at a time, and 64 at a time (only where
// vector_palette() is true).
void resolve_palette_scalar(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch,
                            int width, int rows, const uint32_t* palette);
void resolve_palette_vbmi(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch, int width,
                          int rows, const uint32_t* palette);
bool vector_palette();

}  // namespace p3d::image
