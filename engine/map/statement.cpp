#include "engine/map/statement.h"

namespace p3d::map::detail {

Texture load_texture(const Statement& s, const std::string& name, const std::filesystem::path& map_path,
                     std::string_view file_name) {
  const std::filesystem::path file = map_path.parent_path() / std::string(file_name);
  if (!std::filesystem::exists(file)) s.fail("texture file '" + file.string() + "' does not exist");
  Texture t{name, {}, {}, s.loc()};
  try {
    t.image = image::load_png(file);
  } catch (const Error& e) {
    s.fail(e.what());
  }
  if (t.image.width > kMaxTextureSize || t.image.height > kMaxTextureSize)
    s.fail("texture '" + name + "' is " + std::to_string(t.image.width) + "x" + std::to_string(t.image.height) +
           ": sides must be at most " + std::to_string(kMaxTextureSize));
  return t;
}

}  // namespace p3d::map::detail
