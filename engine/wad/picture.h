// Doom's picture format (patches and sprites): a header (width, height, left and
// top offsets), one offset per column, and per column a list of posts, each a run
// of opaque palette indices starting at a row. Pixels no post covers are transparent.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace p3d::wad {

// An image of palette indices with a transparency mask, column-major as Doom keeps its
// pictures (and as level::Texture keeps texels), so that a post is one copy.
struct IndexedImage {
  int width = 0, height = 0;
  int left_offset = 0, top_offset = 0;  // pictures: where the origin lies (sprites hang from it)
  std::vector<uint8_t> indices;         // width * height
  std::vector<uint8_t> opaque;          // width * height, 1 where a pixel is drawn

  IndexedImage() = default;
  IndexedImage(int w, int h) : width(w), height(h), indices(size_t(w) * h, 0), opaque(size_t(w) * h, 0) {}
  size_t at(int x, int y) const { return size_t(x) * height + y; }
};

constexpr int kMaxPictureSide = 4096;

// Decodes a picture; throws Error("<what>: ...") when the header, a column offset or a
// post lies outside the lump. Posts running past the bottom are clipped (Doom draws
// them; the rows below the picture are never shown). Tall patches (DeePsea's
// relative post offsets) are understood.
IndexedImage decode_picture(std::span<const uint8_t> bytes, const std::string& what);

class Stack;
// The picture lump `name` of the WADs, decoded; none when it is missing or broken (the
// status bar, the intermission, the menus and the HUD font leave such a piece out).
std::optional<IndexedImage> find_picture(const Stack& wads, const std::string& name);

// Whether a lump looks like a picture (a plausible header and column offsets); used
// to tell pictures from PNGs and raw data.
bool looks_like_picture(std::span<const uint8_t> bytes);

}  // namespace p3d::wad
