// TEXTURE1/TEXTURE2 layout: i32 count, count x i32 offset; at each offset a
// texture: name[8], i32 flags, i16 width, i16 height, i32 (obsolete), i16 patch
// count, then patches of i16 x, i16 y, i16 PNAMES index, i16, i16 (unused).
// PNAMES: i32 count, count x name[8].
#include "engine/wad/art.h"

#include <algorithm>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::wad {

namespace {

constexpr size_t kPaletteBytes = 3 * kPaletteColors;
constexpr size_t kTextureHeader = 22;
constexpr size_t kPatchRecord = 10;
constexpr size_t kFlatBytes = size_t(kFlatSide) * kFlatSide;

std::string read_name(ByteReader& in) {
  const auto raw = in.raw(kNameSize);
  return normalize_name(std::string_view(reinterpret_cast<const char*>(raw.data()), kNameSize));
}

const Lump& require(const Stack& stack, std::string_view name) {
  const Lump* l = stack.find(name);
  if (!l) {
    std::string wads;
    for (const Wad& w : stack.wads()) wads += (wads.empty() ? "" : ", ") + w.name();
    throw Error(wads + ": no " + std::string(name) + " lump: the WADs hold no Doom art (give an IWAD with --iwad)");
  }
  return *l;
}

std::string lump_what(const Stack& stack, const Lump& lump) {
  for (const Wad& w : stack.wads())
    if (!w.lumps().empty() && &lump >= &w.lumps().front() && &lump <= &w.lumps().back()) return w.name() + ": " + lump.name;
  return lump.name;
}

}  // namespace

std::string sky_texture_name(std::string_view map_name) {
  const std::string m = normalize_name(map_name);
  if (m.size() == 4 && m[0] == 'E' && m[2] == 'M' && m[1] >= '1' && m[1] <= '4') return std::string("SKY") + m[1];
  if (m.size() >= 4 && m.compare(0, 3, "MAP") == 0) {
    const int n = std::atoi(m.c_str() + 3);
    return n < 12 ? "SKY1" : n < 21 ? "SKY2" : "SKY3";
  }
  return "SKY1";
}

Art::Art(const Stack& stack) : stack_(stack) {
  const Lump& playpal = require(stack, "PLAYPAL");
  if (playpal.bytes.size() < kPaletteBytes)
    throw Error(lump_what(stack, playpal) + ": " + std::to_string(playpal.bytes.size()) + " bytes, a palette needs " +
                std::to_string(kPaletteBytes));
  for (size_t p = 0; (p + 1) * kPaletteBytes <= playpal.bytes.size(); ++p) {
    std::vector<uint32_t>& palette = palettes_.emplace_back();
    const uint8_t* rgb = playpal.bytes.data() + p * kPaletteBytes;
    for (int i = 0; i < kPaletteColors; ++i)
      palette.push_back(uint32_t(rgb[3 * i]) | uint32_t(rgb[3 * i + 1]) << 8 | uint32_t(rgb[3 * i + 2]) << 16 | 0xFF000000u);
  }
  palette_ = palettes_.front();

  const Lump& colormap = require(stack, "COLORMAP");
  if (colormap.bytes.size() < size_t(limits::kLightMaps) * kPaletteColors)
    throw Error(lump_what(stack, colormap) + ": " + std::to_string(colormap.bytes.size()) +
                " bytes, the light tables need " + std::to_string(limits::kLightMaps * kPaletteColors));
  colormap_.assign(colormap.bytes.begin(),
                   colormap.bytes.begin() + std::min(colormap.bytes.size(), size_t(kColormaps) * kPaletteColors));
  colormap_.resize(size_t(kColormaps) * kPaletteColors, 0);  // the last (all black) map may be absent

  const Lump& pnames = require(stack, "PNAMES");
  ByteReader in(pnames.bytes, lump_what(stack, pnames));
  const uint32_t count = in.count(kNameSize, "patch names");
  std::vector<std::string> patch_names;
  for (uint32_t i = 0; i < count; ++i) patch_names.push_back(read_name(in));

  read_texture_lump(require(stack, "TEXTURE1"), patch_names);
  if (const Lump* t2 = stack.find("TEXTURE2")) read_texture_lump(*t2, patch_names);

  for (const Lump* l : stack.namespace_lumps({"F", "FF"})) flats_[l->name] = l;
}

void Art::read_texture_lump(const Lump& lump, const std::vector<std::string>& patch_names) {
  const std::string what = lump_what(stack_, lump);
  ByteReader in(lump.bytes, what);
  const uint32_t count = in.count(4, "texture offsets");
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t offset = in.u32();
    const std::string entry = what + " #" + std::to_string(i);
    if (uint64_t(offset) + kTextureHeader > lump.bytes.size())
      throw Error(entry + ": texture at byte " + std::to_string(offset) + " lies outside the lump");
    ByteReader t(lump.bytes.subspan(offset), entry);
    TextureDef def;
    def.name = read_name(t);
    t.u32();  // flags (masked: unused by Doom)
    def.width = int16_t(t.u16());
    def.height = int16_t(t.u16());
    t.u32();  // column directory (obsolete)
    const int patches = int16_t(t.u16());
    if (def.width <= 0 || def.height <= 0 || def.width > kMaxTextureSide || def.height > kMaxTextureSide)
      throw Error(entry + ": texture '" + printable(def.name) + "' has a bad size " + std::to_string(def.width) + "x" +
                  std::to_string(def.height));
    if (patches < 0 || size_t(patches) * kPatchRecord > t.remaining())
      throw Error(entry + ": texture '" + printable(def.name) + "' lists " + std::to_string(patches) +
                  " patches that do not fit in the lump");
    for (int p = 0; p < patches; ++p) {
      PatchPlacement placement;
      placement.x = int16_t(t.u16());
      placement.y = int16_t(t.u16());
      const int index = int16_t(t.u16());
      t.u16();
      t.u16();
      if (index < 0 || size_t(index) >= patch_names.size())
        throw Error(entry + ": texture '" + printable(def.name) + "' uses patch number " + std::to_string(index) +
                    ", PNAMES has " + std::to_string(patch_names.size()));
      placement.patch = patch_names[size_t(index)];
      def.patches.push_back(placement);
    }
    texture_numbers_.push_back(def.name);
    textures_.emplace(def.name, std::move(def));  // Doom takes the first texture of a name
  }
}

Art::AnimationFrames Art::animation_frames(const doom::AnimatedRange& range) const {
  AnimationFrames out;
  if (range.texture) {
    const auto begin = texture_numbers_.begin(), end = texture_numbers_.end();
    const auto first = std::find(begin, end, range.first), last = std::find(begin, end, range.last);
    if (first == end || last == end || last <= first) return out;
    out.names.assign(first, last + 1);
    out.first_number = int(first - begin);
    return out;
  }
  // A flat's number is its place after F_START in the WAD that holds it (Doom's
  // lump numbers); the last WAD holding the first frame decides.
  for (auto w = stack_.wads().rbegin(); w != stack_.wads().rend(); ++w) {
    const std::vector<Lump>& lumps = w->lumps();
    auto named = [&](size_t from, std::string_view name) {
      size_t found = lumps.size();
      for (size_t i = from; i < lumps.size(); ++i)
        if (lumps[i].name == name) found = i;
      return found;
    };
    const size_t first = named(0, range.first);
    if (first == lumps.size()) continue;
    const size_t last = named(first + 1, range.last);
    if (last == lumps.size()) return out;
    size_t start = 0;  // the F_START (or FF_START) before the range
    for (size_t i = 0; i < first; ++i)
      if (lumps[i].name == "F_START" || lumps[i].name == "FF_START") start = i + 1;
    for (size_t i = first; i <= last; ++i) {
      if (lumps[i].bytes.size() < kFlatBytes) return {};  // a marker or a broken flat inside the range
      out.names.push_back(lumps[i].name);
    }
    out.first_number = int(first - start);
    return out;
  }
  return out;
}

const Art::DecodedPatch& Art::patch(const std::string& name) const {
  if (const auto it = patches_.find(name); it != patches_.end()) return it->second;
  DecodedPatch& out = patches_[name];
  const Lump* lump = stack_.find(name);
  if (!lump) {
    out.problem = "patch " + printable(name) + " is missing";
    return out;
  }
  try {
    out.image = decode_picture(lump->bytes, "patch " + printable(name));
  } catch (const Error& e) {
    out.problem = e.what();
  }
  return out;
}

std::optional<IndexedImage> Art::texture(std::string_view name, std::vector<std::string>& problems) const {
  const auto it = textures_.find(normalize_name(name));
  if (it == textures_.end()) return std::nullopt;
  const TextureDef& def = it->second;
  IndexedImage img(def.width, def.height);
  // Doom's R_GenerateLookup: a column that only one patch covers is that patch's own
  // column, drawn from the patch's first row whatever the patch's place up or down;
  // only columns of several patches are composed with the patches' places.
  std::vector<uint8_t> patches_over(size_t(def.width), 0);
  for (const PatchPlacement& p : def.patches) {
    const DecodedPatch& decoded = this->patch(p.patch);
    if (!decoded.image) continue;
    for (int x = std::max(0, p.x); x < std::min(def.width, p.x + decoded.image->width); ++x)
      patches_over[size_t(x)] = uint8_t(std::min(2, patches_over[size_t(x)] + 1));
  }
  for (const PatchPlacement& p : def.patches) {
    const DecodedPatch& decoded = this->patch(p.patch);
    if (!decoded.image) {
      problems.push_back("texture " + def.name + ": " + decoded.problem);
      continue;
    }
    const IndexedImage& patch = *decoded.image;
    // The patch's columns that land on the canvas; its holes keep what is below.
    const int x0 = std::max(0, -p.x), x1 = std::min(patch.width, def.width - p.x);
    for (int x = x0; x < x1; ++x) {
      const bool alone = patches_over[size_t(p.x + x)] == 1;
      const int py = alone ? 0 : p.y;
      // Each run of opaque rows (a post) goes down at its place; one that begins above
      // the texture's top is cut to fit but, as R_DrawColumnInCache copies it, from its
      // own first row.
      const uint8_t* opaque = &patch.opaque[patch.at(x, 0)];
      for (int t = 0; t < patch.height;) {
        if (!opaque[t]) {
          ++t;
          continue;
        }
        int end = t;
        while (end < patch.height && opaque[end]) ++end;
        const int position = py + t;
        const int first = position < 0 ? 0 : position;                 // texture row
        const int count = std::min(end - t + std::min(position, 0), def.height - first);
        for (int i = 0; i < count; ++i) {
          img.indices[img.at(p.x + x, first + i)] = patch.indices[patch.at(x, t + i)];
          img.opaque[img.at(p.x + x, first + i)] = 1;
        }
        t = end;
      }
    }
  }
  return img;
}

std::optional<IndexedImage> Art::flat(std::string_view name, std::vector<std::string>& problems) const {
  const auto it = flats_.find(normalize_name(name));
  if (it == flats_.end()) return std::nullopt;
  const Lump& lump = *it->second;
  if (lump.bytes.size() < kFlatBytes) {
    problems.push_back("flat " + lump.name + " is " + std::to_string(lump.bytes.size()) + " bytes, a flat needs " +
                       std::to_string(kFlatBytes));
    return std::nullopt;
  }
  IndexedImage img(kFlatSide, kFlatSide);
  for (int y = 0; y < kFlatSide; ++y)  // the lump is rows
    for (int x = 0; x < kFlatSide; ++x) img.indices[img.at(x, y)] = lump.bytes[size_t(y) * kFlatSide + size_t(x)];
  std::fill(img.opaque.begin(), img.opaque.end(), 1);
  return img;
}

}  // namespace p3d::wad
