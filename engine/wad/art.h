// Doom's art from a WAD stack: PLAYPAL and COLORMAP (the light tables), composite
// wall textures (PNAMES, TEXTURE1, TEXTURE2: patches in the picture format placed
// on a canvas, holes left transparent), flats (64x64 raw, between F_START/F_END or
// FF_START/FF_END), and the sky texture a map uses by Doom's rules.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/util/doom.h"
#include "engine/util/limits.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

constexpr int kPaletteColors = limits::kPaletteSize;
constexpr int kColormaps = 34;  // limits::kLightMaps light levels, the invulnerability map, an all-black map
constexpr int kFlatSide = 64;
constexpr int kMaxTextureSide = limits::kMaxTextureSize;

struct PatchPlacement {
  int x = 0, y = 0;
  std::string patch;  // lump name
};

struct TextureDef {
  std::string name;
  int width = 0, height = 0;
  std::vector<PatchPlacement> patches;
};

class Art {
 public:
  // Reads the palette, colormaps and texture directory; throws Error when PLAYPAL,
  // COLORMAP, PNAMES or TEXTURE1 is missing or malformed (the WADs hold no Doom art).
  explicit Art(const Stack& stack);

  // PLAYPAL's first palette as RGBA8 (alpha 255).
  const std::vector<uint32_t>& palette() const { return palette_; }
  // Every whole palette of PLAYPAL (Doom's has 14: the normal one, 8 reds for damage
  // and berserk, 4 golds for pickups, the radiation suit's green).
  const std::vector<std::vector<uint32_t>>& palettes() const { return palettes_; }
  // kColormaps x 256 palette indices (COLORMAP).
  const std::vector<uint8_t>& colormap() const { return colormap_; }

  bool has_texture(std::string_view name) const { return textures_.count(normalize_name(name)) > 0; }
  bool has_flat(std::string_view name) const { return flats_.count(normalize_name(name)) > 0; }

  // A composite texture; patches that are missing or corrupt are skipped with a
  // message in `problems`. nullopt for an unknown name.
  std::optional<IndexedImage> texture(std::string_view name, std::vector<std::string>& problems) const;
  // A flat (64x64, opaque); nullopt for an unknown name or a lump too small to be a flat.
  std::optional<IndexedImage> flat(std::string_view name, std::vector<std::string>& problems) const;

  const std::map<std::string, TextureDef>& texture_defs() const { return textures_; }
  // Every definition's name in TEXTURE1 then TEXTURE2 order: Doom's texture numbers.
  const std::vector<std::string>& texture_numbers() const { return texture_numbers_; }

  // The frames of one of Doom's animated ranges, in Doom's order (texture definitions;
  // flats as their lumps lie), and Doom's number of the first frame; no names when
  // the range is not in these WADs or is broken (an end missing, a marker inside).
  struct AnimationFrames {
    std::vector<std::string> names;
    int first_number = 0;
  };
  AnimationFrames animation_frames(const doom::AnimatedRange& range) const;

 private:
  void read_texture_lump(const Lump& lump, const std::vector<std::string>& patch_names);
  // A patch decoded once however many textures use it, or the problem with it.
  struct DecodedPatch {
    std::optional<IndexedImage> image;
    std::string problem;
  };
  const DecodedPatch& patch(const std::string& name) const;

  const Stack& stack_;
  std::vector<uint32_t> palette_;
  std::vector<std::vector<uint32_t>> palettes_;
  std::vector<uint8_t> colormap_;
  std::map<std::string, TextureDef> textures_;  // TEXTURE1, then TEXTURE2: the first definition of a name wins
  std::vector<std::string> texture_numbers_;     // every definition's name in order: Doom's texture numbers
  std::map<std::string, const Lump*> flats_;
  mutable std::map<std::string, DecodedPatch, std::less<>> patches_;
};

// The name of the flat that means "sky" on a ceiling.
constexpr std::string_view kSkyFlat = "F_SKY1";

// The sky texture Doom uses for a map: ExMy maps use SKY1..SKY4 by episode; MAPxx
// maps SKY1 (maps 1-11), SKY2 (12-20), SKY3 (21 and later); any other name SKY1.
std::string sky_texture_name(std::string_view map_name);

}  // namespace p3d::wad
