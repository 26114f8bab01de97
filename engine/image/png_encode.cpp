// PNG encoding: each row filtered by whichever of PNG's five filters leaves the
// smallest sum of absolute differences (libpng's heuristic), or at level 1 a row of
// palette indices by Paeth alone (png_filters.h); the rows deflated in one zlib stream:
// as runs and literals (deflate_runs.h), or by libdeflate's search; or, at level 0,
// stored as they are. An opaque image is written as RGB, else RGBA; an 8-bit frame as
// palette indices. The bytes depend only on the pixels and the level: captures are
// reproducible on any thread count and any processor.
#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>

#include "engine/image/deflate_runs.h"
#include "engine/image/image.h"
#include "engine/image/png_filters.h"
#include "engine/util/error.h"

namespace p3d::image {

namespace {

constexpr uint8_t kPaletteColourType = 3;  // IHDR's colour type of palette indices

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

void chunk(std::vector<uint8_t>& out, const char type[4], std::span<const uint8_t> data) {
  put32(out, uint32_t(data.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put32(out, libdeflate_crc32(0, out.data() + start, data.size() + 4));
}

// A zlib stream of stored blocks (RFC 1951, 3.2.4), appended to out as its bytes come:
// each block the next 65,535 bytes or fewer, after its header (its last bit 0, for
// now; finish() sets the last block's) and its length twice.
class StoredStream {
 public:
  explicit StoredStream(std::vector<uint8_t>& out) : out_(out) {
    out_.insert(out_.end(), {0x78, 0x01});  // deflate with a 32 KB window, the fastest level; a multiple of 31
  }
  void append(const uint8_t* bytes, size_t n) {
    adler_ = libdeflate_adler32(adler_, bytes, n);
    while (n > 0) {
      if (in_block_ == kMaxBlock || block_ == 0) start_block();
      const size_t take = std::min(n, kMaxBlock - in_block_);
      out_.insert(out_.end(), bytes, bytes + take);
      bytes += take, n -= take, in_block_ += take;
    }
  }
  void finish() {
    if (block_ == 0) start_block();  // an empty stream is one empty block
    end_block();
    out_[block_] = 1;  // the last block
    put32(out_, adler_);
  }

 private:
  static constexpr size_t kMaxBlock = 65535;
  void start_block() {
    if (block_ != 0) end_block();
    block_ = out_.size();
    out_.insert(out_.end(), 5, 0);  // the header byte, then the length twice, filled in by end_block
    in_block_ = 0;
  }
  void end_block() {
    const uint16_t length = uint16_t(in_block_), complement = uint16_t(~length);
    const uint8_t sizes[4] = {uint8_t(length), uint8_t(length >> 8), uint8_t(complement), uint8_t(complement >> 8)};
    std::memcpy(&out_[block_ + 1], sizes, 4);
  }
  std::vector<uint8_t>& out_;
  size_t block_ = 0, in_block_ = 0;  // where the open block's header is in out_ (0: none yet), and its bytes
  uint32_t adler_ = 1;
};

struct CompressorFree {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// This thread's libdeflate compressor at `level` (2 to 12), made at its first use.
libdeflate_compressor& compressor(int level) {
  thread_local std::array<std::unique_ptr<libdeflate_compressor, CompressorFree>, kPngMaxLevel + 1> compressors;
  auto& c = compressors[size_t(level)];
  if (!c) c.reset(libdeflate_alloc_compressor(level));
  if (!c) throw Error("cannot encode PNG: out of memory");
  return *c;
}

// Appends the zlib stream of the image's rows (`height` rows of `stride` bytes,
// `channels` bytes a pixel; palette indices or colours) at `level` to out. Paeth alone
// suits the runs of level 1, not libdeflate's matches: with it, levels 2-12 wrote
// MAP01's 8-bit frames 0.4-6% bigger.
void deflate_rows(int height, const uint8_t* rows, size_t stride, size_t channels, bool indices, int level,
                  std::vector<uint8_t>& out) {
  thread_local std::vector<uint8_t> filtered, zeros;
  zeros.assign(stride, 0);
  auto filter = [&](int y, uint8_t* into) {
    const uint8_t* up = y ? rows + size_t(y - 1) * stride : zeros.data();
    if (indices && level == kPngRuns) return paeth_row(rows + size_t(y) * stride, up, stride, channels, into);
    filter_row(rows + size_t(y) * stride, up, stride, channels, into);
  };
  if (level == kPngStored) {
    StoredStream stream(out);
    const uint8_t none = 0;  // each row's filter: None
    for (int y = 0; y < height; ++y) stream.append(&none, 1), stream.append(rows + size_t(y) * stride, stride);
    stream.finish();
  } else if (level == kPngRuns) {  // each row deflated as it is filtered: the filtered bytes stay in the cache
    DeflateRuns deflater(out);
    for (int y = 0; y < height; ++y) {
      filter(y, deflater.room(stride + 1));
      deflater.wrote(stride + 1);
    }
    deflater.finish();
  } else {
    filtered.resize(size_t(height) * (stride + 1));
    for (int y = 0; y < height; ++y) filter(y, &filtered[size_t(y) * (stride + 1)]);
    libdeflate_compressor& c = compressor(level);
    const size_t at = out.size();
    out.resize(at + libdeflate_zlib_compress_bound(&c, filtered.size()));
    const size_t size = libdeflate_zlib_compress(&c, filtered.data(), filtered.size(), out.data() + at, out.size() - at);
    if (size == 0) throw Error("cannot encode PNG");
    out.resize(at + size);
  }
}

// The PNG of `height` rows of `stride` bytes each (`channels` bytes a pixel), with its
// colour type and the chunks that go before the pixels (a palette). The pixels' chunk
// is deflated into the file where it goes, its length and checksum written after.
std::vector<uint8_t> encode_rows(int width, int height, const uint8_t* rows, size_t channels, uint8_t colour_type,
                                 const std::vector<std::pair<const char*, std::vector<uint8_t>>>& before_pixels,
                                 int level) {
  if (level < 0 || level > kPngMaxLevel)
    throw Error("cannot encode PNG at level " + std::to_string(level) + ": levels are 0 to " +
                std::to_string(kPngMaxLevel));
  const size_t stride = size_t(width) * channels;
  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  // Room for the whole file, so that it is not copied as it grows: at level 0 exactly (the
  // chunks before the pixels are at most 1,100 bytes); else an eighth of the rows, more
  // than a rendered frame's PNG needs (about a tenth): captures 1% faster, in turns.
  const size_t raw = size_t(height) * (stride + 1);
  out.reserve(level == kPngStored ? 1200 + raw + (raw / 65535 + 1) * 5 : 1200 + raw / 8);
  std::vector<uint8_t> header;
  put32(header, uint32_t(width));
  put32(header, uint32_t(height));
  header.insert(header.end(), {8, colour_type, 0, 0, 0});  // 8 bits, deflate, adaptive filters, no interlace
  chunk(out, "IHDR", header);
  for (const auto& [type, data] : before_pixels) chunk(out, type, data);
  const size_t length_at = out.size();
  put32(out, 0);  // the chunk's length, once known
  out.insert(out.end(), {'I', 'D', 'A', 'T'});
  deflate_rows(height, rows, stride, channels, colour_type == kPaletteColourType, level, out);
  const size_t length = out.size() - length_at - 8;
  if (length > 0x7FFFFFFF) throw Error("cannot encode PNG: its pixels deflate to more than 2 GB");
  for (int k = 0; k < 4; ++k) out[length_at + size_t(k)] = uint8_t(length >> (24 - 8 * k));
  put32(out, libdeflate_crc32(0, out.data() + length_at + 4, length + 4));
  chunk(out, "IEND", {});
  return out;
}

}  // namespace

std::vector<uint8_t> encode_png(const Image& image, int level) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot encode an empty image as PNG");
  // Buffers kept from frame to frame: fresh ones of this size cost a page fault per 4 KB.
  thread_local std::vector<uint8_t> rows;
  const size_t n = image.pixels.size();
  rows.resize(n * 4 + 1);  // pixels as bytes, R G B (A); one byte of room
  // Packed as RGB in the pass that finds whether every pixel is opaque (the bits set in
  // every pixel: opaque when all of alpha's are); else copied again as RGBA. Four
  // pixels go to twelve bytes in two stores (R, G, B, A in memory: little-endian).
  const uint32_t* p = image.pixels.data();
  uint8_t* o = rows.data();
  uint32_t all = ~0u;
  size_t i = 0;
  for (; i + 4 <= n; i += 4, o += 12) {
    const uint32_t a = p[i], b = p[i + 1], c = p[i + 2], d = p[i + 3];
    all &= a & b & c & d;
    const uint64_t first = uint64_t(a & 0xFFFFFF) | uint64_t(b & 0xFFFFFF) << 24 | uint64_t(c) << 48;
    const uint32_t second = (c >> 16 & 0xFF) | (d & 0xFFFFFF) << 8;
    std::memcpy(o, &first, 8), std::memcpy(o + 8, &second, 4);
  }
  for (; i < n; ++i, o += 3) all &= p[i], std::memcpy(o, &p[i], 4);  // its alpha overwritten by the next red
  const bool opaque = (all >> 24) == 255;
  const size_t channels = opaque ? 3 : 4;
  if (!opaque) std::memcpy(rows.data(), p, n * 4);
  return encode_rows(image.width, image.height, rows.data(), channels, opaque ? 2 : 6, {}, level);  // RGB or RGBA
}

std::vector<uint8_t> encode_png(int width, int height, std::span<const uint8_t> indices, std::span<const uint32_t> palette,
                                int level) {
  if (width <= 0 || height <= 0) throw Error("cannot encode an empty image as PNG");
  if (indices.size() != size_t(width) * size_t(height) || palette.empty() || palette.size() > 256)
    throw Error("cannot encode PNG: the indices do not fill the image, or the palette is not 1 to 256 colours");
  std::vector<uint8_t> colours, alphas;
  for (const uint32_t c : palette) colours.insert(colours.end(), {uint8_t(red(c)), uint8_t(green(c)), uint8_t(blue(c))});
  if (!std::all_of(palette.begin(), palette.end(), [](uint32_t c) { return c >> 24 == 255; }))
    for (const uint32_t c : palette) alphas.push_back(uint8_t(c >> 24));
  if (palette.size() < 256)  // else every byte is a colour of it
    for (const uint8_t i : indices)
      if (i >= palette.size()) throw Error("cannot encode PNG: an index outside the palette");
  std::vector<std::pair<const char*, std::vector<uint8_t>>> chunks{{"PLTE", std::move(colours)}};
  if (!alphas.empty()) chunks.push_back({"tRNS", std::move(alphas)});
  return encode_rows(width, height, indices.data(), 1, kPaletteColourType, chunks, level);
}

}  // namespace p3d::image
