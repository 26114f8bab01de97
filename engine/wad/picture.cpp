#include "engine/wad/picture.h"

#include <algorithm>
#include <cstring>

#include "engine/util/bytes.h"
#include "engine/util/error.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

namespace {

constexpr size_t kPictureHeader = 8;

struct Header {
  int width, height, left, top;
};

bool read_header(std::span<const uint8_t> bytes, Header& h) {
  if (bytes.size() < kPictureHeader) return false;
  ByteReader in(bytes, "");
  h.width = int16_t(in.u16());
  h.height = int16_t(in.u16());
  h.left = int16_t(in.u16());
  h.top = int16_t(in.u16());
  return h.width > 0 && h.height > 0 && h.width <= kMaxPictureSide && h.height <= kMaxPictureSide &&
         bytes.size() >= kPictureHeader + 4 * size_t(h.width);
}

}  // namespace

bool looks_like_picture(std::span<const uint8_t> bytes) {
  Header h;
  if (!read_header(bytes, h)) return false;
  ByteReader in(bytes.subspan(kPictureHeader), "");
  for (int x = 0; x < h.width; ++x) {
    const uint32_t offset = in.u32();
    if (offset < kPictureHeader + 4 * uint32_t(h.width) || offset >= bytes.size()) return false;
  }
  return true;
}

IndexedImage decode_picture(std::span<const uint8_t> bytes, const std::string& what) {
  Header h;
  if (!read_header(bytes, h)) throw Error(what + ": not a picture (bad header or too small)");
  IndexedImage img(h.width, h.height);
  img.left_offset = h.left;
  img.top_offset = h.top;
  ByteReader offsets(bytes.subspan(kPictureHeader), what);
  for (int x = 0; x < h.width; ++x) {
    const uint32_t offset = offsets.u32();
    if (offset >= bytes.size())
      throw Error(what + ": column " + std::to_string(x) + " starts at byte " + std::to_string(offset) +
                  ", past the end of the picture (" + std::to_string(bytes.size()) + " bytes)");
    ByteReader post(bytes.subspan(offset), what + ": column " + std::to_string(x));
    int top = -1;
    for (int posts = 0;; ++posts) {
      const uint8_t delta = post.u8();
      if (delta == 0xFF) break;
      // Tall patches: a delta not below the previous post's is relative to it.
      top = delta <= top ? top + delta : delta;
      const int length = post.u8();
      post.u8();  // padding byte
      const auto run = post.raw(length);
      post.u8();  // padding byte
      const int shown = std::min(length, h.height - top);
      if (shown > 0) {
        std::memcpy(&img.indices[img.at(x, top)], run.data(), size_t(shown));
        std::memset(&img.opaque[img.at(x, top)], 1, size_t(shown));
      }
      if (posts > 4 * h.height + 256) throw Error(what + ": column " + std::to_string(x) + " never ends");
    }
  }
  return img;
}

std::optional<IndexedImage> find_picture(const Stack& wads, const std::string& name) {
  const Lump* lump = wads.find(name);
  if (!lump) return std::nullopt;
  try {
    return decode_picture(lump->bytes, name);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace p3d::wad
