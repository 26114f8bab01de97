// The .map text parser: one statement per line, positional arguments then
// key=value options. Every mistake is reported as "file:line: message".
#include "engine/map/name_index.h"
#include "engine/map/source.h"
#include "engine/map/statement.h"
#include "engine/util/file.h"

namespace p3d::map {

using detail::same_word;
using detail::Statement;

namespace {

class Parser {
 public:
  Parser(const std::filesystem::path& path, const LoadOptions& options) : options_(options), file_(path.string(), 0) {
    source_.path = path;
  }

  Source run(std::string_view text) {
    reserve(text);
    detail::LineReader lines(text);
    detail::Words words;
    // The first NUL byte, found once: the line holding it is the first to end past it.
    const size_t nul = text.find('\0');
    const char* const first_nul = nul == std::string_view::npos ? nullptr : text.data() + nul;
    std::string_view line;
    for (int line_number = 1; lines.next(line); ++line_number) {
      if (first_nul && line.data() + line.size() > first_nul) throw Error(file_.at(line_number), "binary data in a text map");
      detail::split_words(line, words.args);
      if (!words.args.empty()) statement(Statement(file_, line_number, words));
    }
    if (!have_player_) throw Error(file_, "no player start (add 'player X Y ANGLE')");
    if (source_.walls.empty()) throw Error(file_, "the map has no walls");
    if (source_.sectors.empty() && source_.default_sector == kNone) add_builtin_default_sector();
    sprites_.assign(source_);
    return std::move(source_);
  }

 private:
  // Room for the records the lines announce, so that a big map's vectors and indices
  // are allocated once rather than grown (a rough count is enough: it is only room).
  void reserve(std::string_view text) {
    size_t walls = 0, vertices = 0, sectors = 0;
    detail::LineReader lines(text);
    for (std::string_view line; lines.next(line);) {
      if (line.empty()) continue;
      const auto starts = [&](std::string_view word) { return same_word(line.substr(0, word.size()), word); };
      switch (line[0]) {  // one compare a line at most
        case 'w': walls += starts("wall "); break;
        case 'v': vertices += starts("vertex "); break;
        case 's': sectors += starts("sector "); break;
      }
    }
    source_.walls.reserve(walls);
    source_.vertices.reserve(vertices);
    vertex_index_.reserve(vertices);
    source_.sectors.reserve(sectors + 1);
    sector_index_.reserve(sectors + 1);
  }

  void statement(Statement s) {
    const std::string_view k = s.keyword();
    if (same_word(k, "vertex")) return vertex(s);  // the many first
    if (same_word(k, "wall")) return wall(s);
    if (same_word(k, "segment")) return segment(s);
    if (same_word(k, "sector")) return sector(s, false);
    if (same_word(k, "title")) return title(s);
    if (same_word(k, "texture")) return texture(s);
    if (same_word(k, "sky")) return sky(s);
    if (same_word(k, "default")) return sector(s, true);
    if (same_word(k, "player")) return player(s);
    if (same_word(k, "thing")) return thing(s);
    if (same_word(k, "sprite")) return sprites_.statement(s, source_, options_);
    s.fail("unknown statement '" + std::string(k) + "'");
  }

  void title(Statement& s) {
    s.finish();
    source_.title = s.title();
  }

  void texture(Statement& s) {
    s.expect_args(2, "texture NAME FILE.png");
    s.finish();
    const std::string name = s.name(0, "texture");
    if (name == "sky" || name == "-") s.fail("'" + name + "' is reserved and cannot name a texture");
    if (texture_index_.find(name) != detail::NameIndex::kMissing) s.fail("texture '" + name + "' is defined twice");
    Texture t = detail::load_texture(s, name, source_.path, s.arg(1), options_);
    texture_index_.insert(name, static_cast<int>(source_.textures.size()));
    source_.textures.push_back(std::move(t));
  }

  void sky(Statement& s) {
    s.expect_args(1, "sky TEXTURE");
    s.finish();
    source_.sky_texture = texture_ref(s, s.arg(0));
  }

  void vertex(Statement& s) {
    s.expect_args(3, "vertex NAME X Y");
    s.finish();
    const std::string name = s.name(0, "vertex");
    if (!vertex_index_.insert(name, static_cast<int>(source_.vertices.size())))
      s.fail("vertex '" + name + "' is defined twice");
    source_.vertices.push_back({{s.coordinate(s.arg(1), "x"), s.coordinate(s.arg(2), "y")}});
  }

  void sector(Statement& s, bool is_default) {
    Sector sec;
    sec.loc = s.loc();
    if (is_default) {
      s.expect_args(0, "default floor=F ceiling=C light=L floor_tex=T ceiling_tex=T");
      if (source_.default_sector != kNone) s.fail("default sector is defined twice");
      sec.name = "(default)";
    } else {
      s.expect_args(1, "sector NAME floor=F ceiling=C light=L floor_tex=T ceiling_tex=T");
      sec.name = s.name(0, "sector");
      if (sector_index_.find(sec.name) != detail::NameIndex::kMissing) s.fail("sector '" + sec.name + "' is defined twice");
    }
    sec.floor = height(s, s.require("floor"), "floor");
    sec.ceiling = height(s, s.require("ceiling"), "ceiling");
    if (sec.ceiling < sec.floor) s.fail("ceiling is below the floor");
    if (auto l = s.take("light")) sec.light = s.integer(*l, "light", 0, 255);
    sec.floor_texture = texture_ref(s, s.require("floor_tex"));
    const std::string_view ceiling = s.require("ceiling_tex");
    if (ceiling == "sky") {
      if (source_.sky_texture == kNone) s.fail("ceiling_tex=sky needs a 'sky TEXTURE' statement before it");
      sec.ceiling_texture = kSkyTexture;
    } else {
      sec.ceiling_texture = texture_ref(s, ceiling);
    }
    s.finish();
    const int index = static_cast<int>(source_.sectors.size());
    if (is_default)
      source_.default_sector = index;
    else
      sector_index_.insert(sec.name, index);
    source_.sectors.push_back(std::move(sec));
  }

  double height(const Statement& s, std::string_view text, const char* what) const {
    const double v = s.number(text, what);
    if (std::fabs(v) > geom::kMaxCoord) s.fail(std::string(what) + " height is out of range");
    return v;
  }

  void wall(Statement& s) {
    s.expect_args(2, "wall V1 V2 front=SECTOR [back=SECTOR] [middle=T] [upper=T] [lower=T] ...");
    Wall w = endpoints(s);
    w.front = side(s, "", sector_ref(s, s.require("front")));
    if (auto back = s.take("back")) {
      w.back = side(s, "back_", sector_ref(s, *back));
      // Upper and lower textures default to the same on both sides.
      if (w.back.upper == kNone) w.back.upper = w.front.upper;
      if (w.back.lower == kNone) w.back.lower = w.front.lower;
    } else {
      if (w.front.middle == kNone) s.fail("one-sided wall needs a middle= texture");
    }
    if (auto peg = s.take("unpeg")) {
      if (*peg == "upper") w.flags = kUnpegUpper;
      else if (*peg == "lower") w.flags = kUnpegLower;
      else if (*peg == "both") w.flags = kUnpegUpper | kUnpegLower;
      else s.fail("unpeg must be upper, lower or both");
    }
    s.finish();
    if (source_.walls.size() >= limits::kMaxWalls) s.fail(limits::too_many_walls());
    source_.walls.push_back(w);
  }

  void segment(Statement& s) {
    s.expect_args(2, "segment V1 V2 texture=T [xoff=N] [yoff=N]");
    Wall w = endpoints(s);
    w.segment = true;
    w.front.middle = texture_ref(s, s.require("texture"));
    if (auto x = s.take("xoff")) w.front.x_offset = s.bounded(*x, "xoff", limits::kMaxOffset);
    if (auto y = s.take("yoff")) w.front.y_offset = s.bounded(*y, "yoff", limits::kMaxOffset);
    w.back = w.front;
    s.finish();
    if (source_.walls.size() >= limits::kMaxWalls) s.fail(limits::too_many_walls());
    source_.walls.push_back(w);
  }

  Wall endpoints(const Statement& s) {
    Wall w;
    w.loc = s.loc();
    w.v1 = vertex_ref(s, s.arg(0));
    w.v2 = vertex_ref(s, s.arg(1));
    if (source_.point(w.v1) == source_.point(w.v2)) s.fail("zero-length wall: both ends are at the same point");
    return w;
  }

  Side side(Statement& s, const std::string& prefix, int sector) {
    Side sd;
    sd.sector = sector;
    if (auto t = s.take(prefix + "upper")) sd.upper = texture_ref(s, *t);
    if (auto t = s.take(prefix + "middle")) sd.middle = texture_ref(s, *t);
    if (auto t = s.take(prefix + "lower")) sd.lower = texture_ref(s, *t);
    if (auto x = s.take(prefix + "xoff")) sd.x_offset = s.bounded(*x, prefix + "xoff", limits::kMaxOffset);
    if (auto y = s.take(prefix + "yoff")) sd.y_offset = s.bounded(*y, prefix + "yoff", limits::kMaxOffset);
    return sd;
  }

  void player(Statement& s) {
    s.expect_args(3, "player X Y ANGLE");
    s.finish();
    if (have_player_) s.fail("player start is defined twice");
    have_player_ = true;
    source_.player.pos = geom::to_world({s.coordinate(s.arg(0), "x"), s.coordinate(s.arg(1), "y")});
    source_.player.angle = s.number(s.arg(2), "angle");
    source_.player.loc = s.loc();
  }

  void thing(Statement& s) {
    s.expect_args(4, "thing TYPE X Y ANGLE");
    s.finish();
    Thing t;
    t.type = s.integer(s.arg(0), "thing type", 0, 1 << 30);
    t.pos = geom::to_world({s.coordinate(s.arg(1), "x"), s.coordinate(s.arg(2), "y")});
    t.angle = s.number(s.arg(3), "angle");
    source_.things.push_back(t);
  }

  int vertex_ref(const Statement& s, std::string_view name) const {
    const int index = vertex_index_.find(name);
    if (index == detail::NameIndex::kMissing) s.fail("unknown vertex '" + std::string(name) + "'");
    return index;
  }
  int sector_ref(const Statement& s, std::string_view name) const {
    const int index = sector_index_.find(name);
    if (index == detail::NameIndex::kMissing) s.fail("unknown sector '" + std::string(name) + "'");
    return index;
  }
  int texture_ref(const Statement& s, std::string_view name) const {
    const int index = texture_index_.find(name);
    if (index == detail::NameIndex::kMissing) s.fail("unknown texture '" + std::string(name) + "'");
    return index;
  }

  // A map of plain segments still needs a floor and a ceiling: flat grey, 128 high.
  void add_builtin_default_sector() {
    Texture flat{"(default flat)", image::Image(64, 64), {}};
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const uint32_t v = ((x / 8 + y / 8) & 1) ? 96 : 80;
        flat.image.at(x, y) = image::rgba(v, v, v);
      }
    const int tex = static_cast<int>(source_.textures.size());
    source_.textures.push_back(std::move(flat));
    Sector sec;
    sec.name = "(default)";
    sec.floor_texture = sec.ceiling_texture = tex;
    source_.default_sector = static_cast<int>(source_.sectors.size());
    source_.sectors.push_back(sec);
  }

  LoadOptions options_;
  FileLoc file_;  // the path as messages name it, made once and shared by every record
  Source source_;
  detail::Sprites sprites_;
  bool have_player_ = false;
  detail::NameIndex vertex_index_, sector_index_, texture_index_;
};

}  // namespace

Source parse_map(std::string_view text, const std::filesystem::path& path, const LoadOptions& options) {
  return Parser(path, options).run(text);
}

Source load_map(const std::filesystem::path& path, const LoadOptions& options) {
  Source source;
  {
    const MappedFile file(path);  // mapped, not copied: a million-wall map is 90 MB of text
    const std::span<const uint8_t> bytes = file.bytes();
    source = parse_map(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path, options);
  }
  validate(source);
  return source;
}

}  // namespace p3d::map
