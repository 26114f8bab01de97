#include "engine/wad/art_cache.h"

#include <stdexcept>
#include <utility>

#include "engine/util/error.h"

namespace p3d::wad {

ArtCache::ArtCache(const Stack& stack, bool shared) : stack_(stack), shared_(shared), art_(stack) {}

ArtCache::Picture ArtCache::share(Entry& entry, bool colours) const {
  if (shared_) return colours ? coloured(*entry.picture, entry.picture->indices) : uncoloured(*entry.picture);
  if (entry.handed_over) throw std::logic_error("ArtCache: a picture of a cache that is not shared was asked for twice");
  entry.handed_over = true;
  return colours ? colour(std::move(*entry.picture)) : uncoloured(std::move(*entry.picture));
}

ArtCache::Picture ArtCache::uncoloured(IndexedImage img) {
  Picture out;
  out.colours.width = img.width, out.colours.height = img.height;
  out.indices = std::move(img.indices);
  out.opaque = std::move(img.opaque);
  out.left = img.left_offset;
  out.top = img.top_offset;
  return out;
}

ArtCache::Picture ArtCache::colour(IndexedImage img) const {
  std::vector<uint8_t> indices = std::move(img.indices);
  return coloured(img, std::move(indices));
}

// The picture's shape, offsets and opacity from img, its palette indices from `indices`.
ArtCache::Picture ArtCache::coloured(const IndexedImage& img, std::vector<uint8_t> indices) const {
  Picture out;
  out.colours = image::Image(img.width, img.height);
  const uint32_t* palette = art_.palette().data();
  for (size_t p = 0; p < indices.size(); ++p) out.colours.pixels[p] = palette[indices[p]] & (img.opaque[p] ? ~0u : 0u);
  out.indices = std::move(indices);
  out.left = img.left_offset;
  out.top = img.top_offset;
  return out;
}

ArtCache::Entry& ArtCache::texture(const std::string& name) {
  auto [it, added] = textures_.try_emplace(name);
  if (added)
    if (auto img = art_.texture(name, it->second.problems)) it->second.picture = std::move(*img);
  return it->second;
}

ArtCache::Entry& ArtCache::flat(const std::string& name) {
  auto [it, added] = flats_.try_emplace(name);
  if (added)
    if (auto img = art_.flat(name, it->second.problems)) it->second.picture = std::move(*img);
  return it->second;
}

ArtCache::Entry& ArtCache::sprite(const Lump& lump) {
  auto [it, added] = sprites_.try_emplace(lump.name);
  if (added) {
    try {
      it->second.picture = decode_picture(lump.bytes, "sprite " + lump.name);
    } catch (const Error& e) {
      it->second.problems.push_back(e.what());
    }
  }
  return it->second;
}

const std::vector<const Lump*>& ArtCache::sprite_lumps() {
  if (!sprite_lumps_) {
    sprite_lumps_.emplace();
    for (const Lump* l : stack_.namespace_lumps({"S", "SS"})) sprite_lumps_->push_back(l);
  }
  return *sprite_lumps_;
}

const std::vector<uint32_t>& ArtCache::sprite_lumps_named(std::string_view sprite) {
  if (sprite_lumps_by_name_.empty()) {
    const std::vector<const Lump*>& lumps = sprite_lumps();
    for (size_t k = 0; k < lumps.size(); ++k)
      if (lumps[k]->name.size() >= 6) sprite_lumps_by_name_[lumps[k]->name.substr(0, 4)].push_back(uint32_t(k));
  }
  static const std::vector<uint32_t> kNone;
  const auto it = sprite_lumps_by_name_.find(std::string(sprite));
  return it == sprite_lumps_by_name_.end() ? kNone : it->second;
}

}  // namespace p3d::wad
