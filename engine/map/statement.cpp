#include "engine/map/statement.h"

namespace p3d::map::detail {

namespace {

// Refused before the file system is asked anything, so a message never tells whether a
// file outside the map's directory exists.
void check_stays_beside_the_map(const Statement& s, const std::string& kind, std::string_view file_name) {
  const std::filesystem::path path = std::filesystem::path(std::string(file_name)).lexically_normal();
  if (path.has_root_name() || path.has_root_directory() || path.empty() || *path.begin() == "..")
    s.fail(kind + " file '" + std::string(file_name) +
           "' lies outside the map's directory (name it relative to the map, or allow it with --textures-anywhere)");
}

// Where a picture statement's file is: beside the map, else (a bare file name) among
// the bundled textures.
std::filesystem::path resolve_picture(const Statement& s, const std::string& kind, std::string_view file_name,
                                      const std::filesystem::path& map_path, const LoadOptions& options) {
  if (!options.textures_anywhere) check_stays_beside_the_map(s, kind, file_name);
  const std::filesystem::path name{std::string(file_name)};
  const std::filesystem::path beside = map_path.parent_path() / name;
  std::error_code ec;
  if (std::filesystem::exists(beside, ec)) return beside;
  if (ec) s.fail(kind + " file '" + beside.string() + "' cannot be opened: " + ec.message());
  if (name.filename() == name && !options.bundled_textures.empty() &&
      std::filesystem::exists(options.bundled_textures / name, ec))
    return options.bundled_textures / name;
  s.fail(kind + " file '" + beside.string() + "' does not exist");
}

// kind: "texture" or "sprite"; name: what the map calls it.
image::Image load_picture(const Statement& s, const std::string& kind, const std::string& name,
                          const std::filesystem::path& map_path, std::string_view file_name, const LoadOptions& options) {
  const std::filesystem::path file = resolve_picture(s, kind, file_name, map_path, options);
  const std::string what = kind + " '" + name + "'";
  image::Image img;
  try {
    img = image::load_png(file);
  } catch (const Error& e) {
    s.fail(e.what());
  }
  if (img.width > kMaxTextureSize || img.height > kMaxTextureSize)
    s.fail(what + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) + ": sides must be at most " +
           std::to_string(kMaxTextureSize));
  return img;
}

}  // namespace

Texture load_texture(const Statement& s, const std::string& name, const std::filesystem::path& map_path,
                     std::string_view file_name, const LoadOptions& options) {
  return {name, load_picture(s, "texture", name, map_path, file_name, options), {}, {}, s.loc()};
}

void Sprites::statement(Statement& s, Source& source, const LoadOptions& options) {
  s.expect_args(2, "sprite TYPE FILE.png [anchor=X,Y] [place=floor|ceiling] [bright=yes|no]");
  const int type = s.integer(s.arg(0), "thing type", 0, 1 << 30);
  if (frame_of_type_.count(type)) s.fail("thing type " + std::to_string(type) + " already has a sprite");
  SpriteImage picture;
  picture.name = std::string(s.arg(1));
  picture.image = load_picture(s, "sprite", picture.name, source.path, s.arg(1), options);
  SpriteFrame frame;
  frame.name = picture.name;
  if (auto place = s.take("place")) {
    if (*place != "floor" && *place != "ceiling") s.fail("place must be floor or ceiling");
    frame.hanging = *place == "ceiling";
  }
  if (auto bright = s.take("bright")) {
    if (*bright != "yes" && *bright != "no") s.fail("bright must be yes or no");
    frame.bright = *bright == "yes";
  }
  picture.left = picture.image.width / 2;
  picture.top = frame.hanging ? 0 : picture.image.height;
  if (auto anchor = s.take("anchor")) {
    const size_t comma = anchor->find(',');
    if (comma == std::string_view::npos) s.fail("anchor must be X,Y (pixels of the picture)");
    picture.left = s.integer(anchor->substr(0, comma), "anchor x", -kMaxTextureSize, kMaxTextureSize);
    picture.top = s.integer(anchor->substr(comma + 1), "anchor y", -kMaxTextureSize, kMaxTextureSize);
  }
  s.finish();
  const int image = int(source.sprite_images.size());
  source.sprite_images.push_back(std::move(picture));
  std::fill(std::begin(frame.image), std::end(frame.image), image);
  frame_of_type_[type] = int(source.sprites.size());
  source.sprites.push_back(frame);
}

void Sprites::assign(Source& source) const {
  for (Thing& t : source.things)
    if (auto it = frame_of_type_.find(t.type); it != frame_of_type_.end()) t.sprite = it->second;
}

}  // namespace p3d::map::detail
