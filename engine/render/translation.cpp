// Translated copies of sprite pictures (Doom's player colours), made on first use.
#include "engine/render/translation.h"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace p3d::render {

const level::Texture& translated_texture(const level::Level& level, size_t texture, int t) {
  const level::Texture& source = level.textures[texture];
  if (t < 1 || t > kTranslations || !level.paletted() || source.indices.empty()) return source;
  static std::mutex mutex;
  static std::map<std::tuple<uint64_t, size_t, int>, std::unique_ptr<level::Texture>> copies;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& copy = copies[{level.generation, texture, t}];
  if (!copy) {
    copy = std::make_unique<level::Texture>(source);
    for (size_t i = 0; i < copy->indices.size(); ++i) {
      const uint8_t shown = translate_index(copy->indices[i], t);
      if (shown == copy->indices[i]) continue;
      copy->indices[i] = shown;
      copy->texels[i] = (level.palette[shown] & 0x00ffffffu) | (copy->texels[i] & 0xff000000u);
    }
  }
  return *copy;
}

}  // namespace p3d::render
