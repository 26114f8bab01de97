// PNG's row filters for the encoder (png_encode.cpp): each row filtered by whichever of
// the five leaves the smallest sum of absolute differences (libpng's heuristic), costed
// over a sample of a long row's bytes; or by Paeth alone. The loops run as wide as the
// processor allows (SSE2, or AVX2 where it has it) and write the same bytes at every
// width.
#pragma once

#include <cstddef>
#include <cstdint>

namespace p3d::image {

// PNG's filters, numbered as in the file: 0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth.
constexpr int kPaethFilter = 4;

// How many bytes the filters' loops take at a time: one (rows too short for more),
// sixteen (SSE2, part of x86-64) or thirty-two (AVX2).
enum class FilterLanes { kOne, kSixteen, kThirtyTwo };

// The widest this processor runs (kOne off x86-64).
FilterLanes widest_filter_lanes();

// One row of `stride` bytes (`channels` a pixel) filtered into out[0] (the filter type)
// and out[1..stride]; `up` is the row above (zeros for the first). At most `lanes` wide:
// tests compare the widths.
void filter_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* out,
                FilterLanes lanes = widest_filter_lanes());

// The same row filtered by Paeth, uncosted: a palette image's filter at PNG level 1.
// Its bytes are indices, names rather than magnitudes, so the sum of differences weighs
// nothing real; on Doom frames Paeth alone writes PNGs 0.7% smaller (geomean of 12
// maps, 2 sizes) in 0.92-0.94 of the capture's time (docs/benchmarks.md, "Threads and
// captures").
void paeth_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* out,
               FilterLanes lanes = widest_filter_lanes());

}  // namespace p3d::image
