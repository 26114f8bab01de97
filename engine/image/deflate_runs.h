// A zlib stream (RFC 1950/1951) made of runs and literals only: each byte repeating
// the one before it sixteen times or more becomes a match at distance 1 (as zlib's Z_RLE
// strategy, with longer runs), everything else a literal, a block of Huffman codes
// for each 64 KB.
// A filtered PNG row of a rendered frame is mostly runs (the Up and Sub filters turn a
// magnified texel into zeros), so this keeps nearly all of a general deflater's
// compression at a fraction of its work: no hash table and no search.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace p3d::image {

// Appends the zlib stream of `in` to out; the same bytes give the same stream.
void deflate_runs(std::span<const uint8_t> in, std::vector<uint8_t>& out);

}  // namespace p3d::image
