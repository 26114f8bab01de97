// Level -> bytes, following format.h field by field.
#include <cstring>
#include <stdexcept>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "engine/level/format.h"
#include "engine/level/io.h"
#include "engine/util/bytes.h"
#include "engine/util/checksum.h"
#include "engine/util/file.h"

namespace p3d::level {

namespace {

// A wall's or a free line's two ends.
void write_ends(ByteWriter& out, const geom::IPoint& p1, const geom::IPoint& p2) {
  for (int64_t c : {p1.x, p1.y, p2.x, p2.y}) out.i64(c);
}

void write_side(ByteWriter& out, const Side& s) {
  out.i32(s.sector);
  out.i32(s.upper);
  out.i32(s.middle);
  out.i32(s.lower);
  out.f64(s.x_offset);
  out.f64(s.y_offset);
  out.i32(s.parts);
  out.i32(s.light);
}

// Bit k of byte b set where opaque[8b + k] is not 0: sixteen texels a step, as most of
// a WAD's sprites and masked textures are written (by pseudo3d-mapc, without colours).
void pack_opacity_bytes(const uint8_t* opaque, size_t n, uint8_t* bits) {
  size_t p = 0;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128();
  for (; p + 16 <= n; p += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(opaque + p));
    const unsigned drawn = ~unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, zero)));
    bits[p / 8] = uint8_t(drawn), bits[p / 8 + 1] = uint8_t(drawn >> 8);
  }
#endif
  for (; p < n; ++p) {
    if (p % 8 == 0) bits[p / 8] = 0;
    bits[p / 8] |= uint8_t((opaque[p] != 0) << (p % 8));
  }
}

// Palette indices, then one opacity bit per texel; or RGBA8: column-major, as a
// Texture keeps them, so that each is one copy. A texture without colours (only
// paletted levels have them) gives its opacity from Texture::opaque.
void write_texels(ByteWriter& out, const Texture& t, bool paletted) {
  const size_t n = size_t(t.width) * size_t(t.height);
  if (!paletted) {
    if (t.texels.size() != n) throw std::logic_error("write_texels: an RGBA level's texture without its colours");
    uint8_t* bytes = out.extend(n * 4);
    for (size_t p = 0; p < n; ++p) {
      const uint32_t c = t.texels[p];  // R,G,B,A byte order
      bytes[4 * p] = uint8_t(c), bytes[4 * p + 1] = uint8_t(c >> 8), bytes[4 * p + 2] = uint8_t(c >> 16),
                bytes[4 * p + 3] = uint8_t(c >> 24);
    }
    return;
  }
  std::memcpy(out.extend(n), t.indices.data(), n);
  uint8_t* bits = out.extend((n + 7) / 8);
  if (!t.holes) {  // most textures: every bit set
    std::memset(bits, 0xFF, n / 8);
    if (n % 8) bits[n / 8] = uint8_t((1u << (n % 8)) - 1);
    return;
  }
  if (!t.texels.empty()) {
    std::memset(bits, 0, (n + 7) / 8);
    for (size_t p = 0; p < n; ++p) bits[p / 8] |= uint8_t(((t.texels[p] >> 24) != 0) << (p % 8));
    return;
  }
  pack_opacity_bytes(t.opaque.data(), n, bits);
}

void write_payload(ByteWriter& out, const Level& level) {
  out.u32(format::kMeta);
  out.str(level.title);
  out.f64(level.player_start.x);
  out.f64(level.player_start.y);
  out.f64(level.player_angle);
  out.i32(level.default_sector);
  out.i32(level.sky_texture);

  out.u32(format::kPalette);
  out.u32(level.paletted() ? 1 : 0);
  if (level.paletted()) {
    for (uint32_t c : level.palette) out.u32(c);
    for (uint32_t c : level.light_maps) out.u32(c);
  }

  out.u32(format::kTextures);
  out.u32(static_cast<uint32_t>(level.textures.size()));
  for (const Texture& t : level.textures) {
    out.str(t.name);
    out.u32(t.width);
    out.u32(t.height);
    write_texels(out, t, level.paletted());
  }

  out.u32(format::kSprites);
  out.u32(static_cast<uint32_t>(level.sprite_images.size()));
  for (const SpriteImage& i : level.sprite_images) {
    out.i32(i.texture);
    out.i32(i.left);
    out.i32(i.top);
  }
  out.u32(static_cast<uint32_t>(level.sprite_frames.size()));
  for (const SpriteFrame& f : level.sprite_frames) {
    out.str(f.name);
    for (int r = 0; r < kRotations; ++r) {
      out.i32(f.image[r]);
      out.u8(f.flip[r] ? 1 : 0);
    }
    out.u8(f.bright ? 1 : 0);
    out.u8(f.hanging ? 1 : 0);
    out.f64(f.drop);
  }

  out.u32(format::kSectors);
  out.u32(static_cast<uint32_t>(level.sectors.size()));
  for (const Sector& s : level.sectors) {
    out.str(s.name);
    out.f64(s.floor);
    out.f64(s.ceiling);
    out.i32(s.light);
    out.i32(s.floor_texture);
    out.i32(s.ceiling_texture);
    out.i32(s.special);
    out.i32(s.tag);
  }

  out.u32(format::kPartOffsets);
  out.u32(static_cast<uint32_t>(level.part_offsets.size()));
  for (const PartOffsets& p : level.part_offsets) {
    for (double v : p.x) out.f64(v);
    for (double v : p.y) out.f64(v);
  }

  out.u32(format::kWalls);
  out.u32(static_cast<uint32_t>(level.walls.size()));
  for (const Wall& w : level.walls) {
    write_ends(out, w.p1, w.p2);
    out.u32(w.flags);
    out.i32(w.source);
    out.i32(w.special);
    out.i32(w.tag);
    write_side(out, w.sides[0]);
    write_side(out, w.sides[1]);
  }

  out.u32(format::kLines);
  out.u32(static_cast<uint32_t>(level.free_lines.size()));
  for (const FreeLine& l : level.free_lines) write_ends(out, l.p1, l.p2);

  out.u32(format::kFragments);
  out.u32(static_cast<uint32_t>(level.fragments.size()));
  for (const Fragment& f : level.fragments) {
    out.u32(f.wall);
    out.i32(f.cut[0]);
    out.i32(f.cut[1]);
    out.f64(f.t0);
    out.f64(f.t1);
    out.u8(uint8_t(f.side));
  }

  out.u32(format::kNodes);
  out.u32(static_cast<uint32_t>(level.nodes.size()));
  for (const Node& n : level.nodes) {
    out.u32(n.splitter);
    out.i32(n.child[0]);
    out.i32(n.child[1]);
    out.u32(n.first_fragment);
    out.u32(n.fragment_count);
    out.f64(n.bbox.min.x);
    out.f64(n.bbox.min.y);
    out.f64(n.bbox.max.x);
    out.f64(n.bbox.max.y);
  }

  out.u32(format::kLeaves);
  out.u32(static_cast<uint32_t>(level.leaves.size()));
  for (const Leaf& l : level.leaves) {
    out.i32(l.sector);
    out.u32(l.first_fragment);
    out.u32(l.fragment_count);
  }

  out.u32(format::kThings);
  out.u32(static_cast<uint32_t>(level.things.size()));
  for (const Thing& t : level.things) {
    out.i32(t.type);
    out.f64(t.pos.x);
    out.f64(t.pos.y);
    out.f64(t.angle);
    out.u32(t.flags);
    out.i32(t.sprite);
    out.i32(t.sector);
  }

  out.u32(format::kAnimations);
  out.u32(static_cast<uint32_t>(level.animations.size()));
  for (const doom::TextureAnimation& a : level.animations) {
    out.i32(a.tics);
    out.i32(a.phase);
    out.u32(static_cast<uint32_t>(a.frames.size()));
    for (int32_t f : a.frames) out.i32(f);
  }

  out.u32(format::kGrid);
  out.u32(level.grid ? 1 : 0);
  if (level.grid) {
    out.u32(static_cast<uint32_t>(level.grid->cols));
    out.u32(static_cast<uint32_t>(level.grid->rows));
    out.f64(level.grid->cell);
    out.raw(level.grid->solid);
    for (int32_t f : level.grid->faces) out.i32(f);
  }
}

// The encoded size, near enough that the buffer is allocated once: the records' sizes
// as write_payload writes them, their names, and the texels.
size_t encoded_size_estimate(const Level& level) {
  size_t bytes = 4096 + level.title.size() + (level.palette.size() + level.light_maps.size()) * 4;
  for (const Texture& t : level.textures) bytes += 16 + t.name.size() + size_t(t.width) * size_t(t.height) * (level.paletted() ? 2 : 4);
  for (const Sector& s : level.sectors) bytes += 48 + s.name.size();
  for (const SpriteFrame& f : level.sprite_frames) bytes += 64 + f.name.size();
  bytes += 12 * level.sprite_images.size() + format::kWallRecord * level.walls.size() + format::kLineRecord * level.free_lines.size() +
           format::kPartOffsetsRecord * level.part_offsets.size() + format::kFragmentRecord * level.fragments.size() +
           format::kNodeRecord * level.nodes.size() + format::kLeafRecord * level.leaves.size() + 40 * level.things.size();
  if (level.grid) bytes += 24 + level.grid->solid.size() + level.grid->faces.size() * 4;
  for (const doom::TextureAnimation& a : level.animations) bytes += 12 + 4 * a.frames.size();
  return bytes;
}

void write_header(ByteWriter& out, uint64_t payload_size, uint64_t checksum) {
  out.raw(std::span(reinterpret_cast<const uint8_t*>(format::kMagic), 8));
  out.u32(format::kVersion);
  out.u32(0);
  out.u64(payload_size);
  out.u64(checksum);
}

}  // namespace

std::vector<uint8_t> encode(const Level& level) {
  ByteWriter out;
  out.reserve(encoded_size_estimate(level));
  write_header(out, 0, 0);  // the size and checksum patched below
  write_payload(out, level);
  const std::span<const uint8_t> payload = out.bytes().subspan(format::kHeaderSize);
  out.patch_u64(16, payload.size());
  out.patch_u64(24, checksum64(payload));
  return out.release();
}

void encode(const Level& level, OutputFile& file) {
  ByteWriter header;
  write_header(header, 0, 0);  // rewritten at the end with the payload's size and checksum
  file.write(header.bytes());
  uint64_t size = 0;
  Checksum64 checksum;
  ByteWriter out(size_t{1} << 20, [&](std::span<const uint8_t> bytes) {
    size += bytes.size();
    checksum.add(bytes);
    file.write(bytes);
  });
  write_payload(out, level);
  out.flush();
  ByteWriter final_header;
  write_header(final_header, size, checksum.value());
  file.write_at(0, final_header.bytes());
}

void write(const Level& level, const std::filesystem::path& path) {
  Outputs outputs;
  outputs.add(path, [&](OutputFile& file) { encode(level, file); });
  outputs.commit();
}

}  // namespace p3d::level
