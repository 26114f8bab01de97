// The pictures a WAD level embeds, made once for every map of the same WADs
// (pseudo3d-mapc --all compiles each map of a WAD with one cache): Doom's art
// directory read once; each wall texture, flat and sprite lump decoded and coloured
// once, with the problems found on the way (each map using the picture still warns
// about them); the sprite lumps found by name; each texture's columns as Doom's
// renderer reads them. Every map of a WAD shares most of its art with the others:
// made per map, the art was more than half of a whole WAD's compile (freedoom2: 4.9
// of 8.3 billion instructions).
// One cache serves one Stack, on one thread at a time.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "engine/image/image.h"
#include "engine/wad/art.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

class ArtCache {
 public:
  // Throws Error as Art does when the WADs hold no Doom art. A cache that serves one
  // import alone (shared = false) hands its pictures over instead of copying them.
  explicit ArtCache(const Stack& stack, bool shared = true);

  const Stack& stack() const { return stack_; }
  const Art& art() const { return art_; }

  // A picture in the level's colours: RGBA (alpha 0 where transparent) and palette
  // indices, both a column after another. Without colours (share's `colours` false),
  // `colours` has the size but no pixels and `opaque` is 1 where a pixel is drawn.
  struct Picture {
    image::Image colours;
    std::vector<uint8_t> indices;
    std::vector<uint8_t> opaque;
    int left = 0, top = 0;  // sprites: the origin's place (IndexedImage's offsets)
  };
  // A picture or why there is none: `problems` are warnings for every map that uses it
  // (broken patches, a lump that does not decode). Kept as palette indices, two bytes a
  // texel where a coloured picture takes five: a whole WAD's art is held at once.
  struct Entry {
    std::optional<IndexedImage> picture;
    std::vector<std::string> problems;
    bool handed_over = false;  // share() moved the picture out
  };

  Entry& texture(const std::string& name);  // a composite wall texture; none if unknown
  Entry& flat(const std::string& name);     // none if unknown or too small
  Entry& sprite(const Lump& lump);          // a sprite lump decoded; none if broken
  // An entry's picture in colours for a level: from a copy of its indices, or from the
  // indices themselves in a cache that is not shared (each name is asked for once by one
  // import).
  Picture share(Entry& entry, bool colours = true) const;

  // The sprite lumps between S_START and S_END (and SS_), in the WADs' order, and the
  // positions among them of those whose names begin with `sprite` (4 letters).
  const std::vector<const Lump*>& sprite_lumps();
  const std::vector<uint32_t>& sprite_lumps_named(std::string_view sprite);

  // A texture's columns as Doom's renderer reads them (wad/doom_segs.h), made by `make`
  // the first time the name is asked for.
  template <typename Make>
  const std::vector<uint8_t>& doom_columns(const std::string& name, Make&& make) {
    auto [it, added] = doom_columns_.try_emplace(name);
    if (added) it->second = make();
    return it->second;
  }

  Picture colour(IndexedImage img) const;

 private:
  Picture coloured(const IndexedImage& img, std::vector<uint8_t> indices) const;
  static Picture uncoloured(IndexedImage img);

  const Stack& stack_;
  const bool shared_;
  Art art_;
  std::unordered_map<std::string, Entry> textures_, flats_, sprites_;
  std::optional<std::vector<const Lump*>> sprite_lumps_;
  std::unordered_map<std::string, std::vector<uint32_t>> sprite_lumps_by_name_;
  std::unordered_map<std::string, std::vector<uint8_t>> doom_columns_;
};

}  // namespace p3d::wad
