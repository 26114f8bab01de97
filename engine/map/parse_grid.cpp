// The .grid parser (Wolfenstein-style tile maps) and the conversion of a tile grid
// into walls, so that the BSP renderer and the grid ray caster see the same level.
#include <map>
#include <unordered_map>

#include "engine/map/statement.h"
#include "engine/util/file.h"

namespace p3d::map {

using detail::Statement;

namespace {

constexpr int kMaxGridSide = 4096;
constexpr int kFaceEast = 0, kFaceNorth = 1, kFaceWest = 2, kFaceSouth = 3;

bool is_marker(char c) { return c == '>' || c == '^' || c == '<' || c == 'v'; }
double marker_angle(char c) { return c == '>' ? 0 : c == '^' ? 90 : c == '<' ? 180 : 270; }
bool is_empty_tile(char c) { return c == '.' || c == ' ' || is_marker(c); }

class GridParser {
 public:
  GridParser(const std::filesystem::path& path, const LoadOptions& options) : options_(options), file_(path.string(), 0) {
    src_.path = path;
  }

  Source run(const std::string& text) {
    const std::vector<std::string_view> lines = detail::split_lines(text);
    detail::Words words;
    size_t i = 0;
    for (; i < lines.size(); ++i) {
      const FileLoc loc = file_.at(int(i) + 1);
      if (lines[i].find('\0') != std::string_view::npos) throw Error(loc, "binary data in a text map");
      detail::split_words(lines[i], words.args);
      if (words.args.empty()) continue;
      if (words.args[0] == "map") {
        if (words.args.size() != 1) throw Error(loc, "map: expected nothing after 'map'; the rows follow on the next lines");
        if (map_line_ > 0)
          throw Error(loc, "a second map block (the first is at line " + std::to_string(map_line_) + "); a .grid holds one");
        map_line_ = int(i) + 1;
        i = read_rows(lines, i + 1);
        continue;
      }
      Statement s(file_, int(i) + 1, words);
      statement(s);
    }
    finish();
    return std::move(src_);
  }

 private:
  void statement(Statement& s) {
    const std::string_view k = s.keyword();
    if (!tiles_.empty()) s.fail("statements must come before the map rows");
    if (k == "title") {
      src_.title = s.title();
    } else if (k == "texture") {
      s.expect_args(2, "texture NAME FILE.png");
      const std::string name = s.name(0, "texture");
      if (name == "sky") s.fail("'sky' is reserved and cannot name a texture");
      if (textures_.count(name)) s.fail("texture '" + name + "' is defined twice");
      textures_[name] = int(src_.textures.size());
      src_.textures.push_back(detail::load_texture(s, name, src_.path, s.arg(1), options_));
    } else if (k == "sky") {
      s.expect_args(1, "sky TEXTURE");
      src_.sky_texture = texture_ref(s, s.arg(0));
    } else if (k == "cell") {
      s.expect_args(1, "cell SIZE");
      cell_ = s.integer(s.arg(0), "cell size", 1, 4096);
    } else if (k == "floor" || k == "ceiling") {
      s.expect_args(2, k == "floor" ? "floor HEIGHT TEXTURE" : "ceiling HEIGHT TEXTURE|sky");
      const double h = s.number(s.arg(0), std::string(k) + " height");
      if (std::fabs(h) > geom::kMaxCoord) s.fail(std::string(k) + " height is out of range");
      int tex;
      if (k == "ceiling" && s.arg(1) == "sky") {
        if (src_.sky_texture == kNone) s.fail("ceiling sky needs a 'sky TEXTURE' statement before it");
        tex = kSkyTexture;
      } else {
        tex = texture_ref(s, s.arg(1));
      }
      (k == "floor" ? floor_ : ceiling_) = {h, tex, s.loc().line};
    } else if (k == "light") {
      s.expect_args(1, "light LEVEL");
      light_ = s.integer(s.arg(0), "light", 0, 255);
    } else if (k == "tile") {
      s.expect_args(2, "tile CHARACTER TEXTURE");
      if (s.arg(0).size() != 1 || is_empty_tile(s.arg(0)[0]) || s.arg(0)[0] == '#' || s.arg(0)[0] == '=')
        s.fail("a tile is one character other than '.', space, '#', '=' and the player markers > ^ < v");
      if (!legend_.emplace(s.arg(0)[0], texture_ref(s, s.arg(1))).second)
        s.fail("tile '" + std::string(s.arg(0)) + "' is defined twice");
    } else if (k == "sprite") {
      sprites_.statement(s, src_, options_);
      return;
    } else if (k == "thing") {
      s.expect_args(4, "thing TYPE X Y ANGLE");
      Thing t;
      t.type = s.integer(s.arg(0), "thing type", 0, 1 << 30);
      t.pos = geom::to_world({s.coordinate(s.arg(1), "x"), s.coordinate(s.arg(2), "y")});
      t.angle = s.number(s.arg(3), "angle");
      src_.things.push_back(t);
    } else {
      s.fail("unknown statement '" + std::string(k) + "'");
    }
    s.finish();
  }

  // Rows until "end"; the first row is the northernmost.
  size_t read_rows(const std::vector<std::string_view>& lines, size_t i) {
    std::vector<std::pair<std::string_view, int>> rows;
    for (; i < lines.size(); ++i) {
      std::string_view row = lines[i];
      if (row == "end") break;
      rows.push_back({row, int(i) + 1});
    }
    if (i == lines.size()) throw Error(file_.at(map_line_), "map rows are not closed by a line 'end'");
    if (rows.empty()) throw Error(file_.at(map_line_), "the map has no rows");
    cols_ = int(rows.front().first.size());
    rows_ = int(rows.size());
    if (cols_ == 0) throw Error(file_.at(rows.front().second), "the first row is empty");
    if (cols_ > kMaxGridSide || rows_ > kMaxGridSide)
      throw Error(file_.at(map_line_), "the grid is larger than " + std::to_string(kMaxGridSide) + "x" +
                                                           std::to_string(kMaxGridSide));
    if (double(std::max(cols_, rows_)) * cell_ > geom::kMaxCoord)
      throw Error(file_.at(map_line_), "the grid does not fit in the coordinate range");
    tiles_.assign(size_t(cols_) * rows_, '.');
    row_lines_.resize(rows_);
    for (int k = 0; k < rows_; ++k) {
      const auto& [text, line] = rows[k];
      const int r = rows_ - 1 - k;  // row 0 is the south
      row_lines_[r] = line;
      if (int(text.size()) != cols_)
        throw Error(file_.at(line), "row has " + std::to_string(text.size()) + " tiles, expected " +
                                                        std::to_string(cols_));
      for (int c = 0; c < cols_; ++c) {
        const char t = text[c];
        if (!is_empty_tile(t) && !legend_.count(t))
          throw Error(file_.at(line),
                      "unknown tile '" + std::string(1, t) + "' in column " + std::to_string(c + 1) +
                          " (add 'tile " + std::string(1, t) + " TEXTURE')");
        if (is_marker(t)) {
          if (have_player_) throw Error(file_.at(line), "a second player marker");
          have_player_ = true;
          src_.player = {{(c + 0.5) * cell_, (r + 0.5) * cell_}, marker_angle(t), file_.at(line)};
        }
        tiles_[size_t(r) * cols_ + c] = t;
      }
    }
    return i;
  }

  void finish() {
    if (tiles_.empty()) throw Error(file_, "no map rows (add 'map', the rows, then 'end')");
    if (!have_player_) throw Error(file_, "no player marker (> ^ < or v) in the map rows");
    if (floor_.texture == kNone) throw Error(file_, "no floor (add 'floor HEIGHT TEXTURE')");
    if (ceiling_.texture == kNone) throw Error(file_, "no ceiling (add 'ceiling HEIGHT TEXTURE')");
    if (legend_.empty()) throw Error(file_, "no tiles (add 'tile CHARACTER TEXTURE')");
    if (ceiling_.height < floor_.height) throw Error(file_.at(ceiling_.line), "ceiling is below the floor");
    sprites_.assign(src_);

    Sector sector;
    sector.name = "floor";
    sector.floor = floor_.height;
    sector.ceiling = ceiling_.height;
    sector.light = light_;
    sector.floor_texture = floor_.texture;
    sector.ceiling_texture = ceiling_.texture;
    sector.loc = file_.at(floor_.line);
    src_.sectors.push_back(sector);

    GridInfo grid;
    grid.cols = cols_;
    grid.rows = rows_;
    grid.cell = cell_;
    grid.solid.resize(tiles_.size());
    std::vector<int> tile_texture(tiles_.size(), kNone);
    for (size_t i = 0; i < tiles_.size(); ++i) {
      grid.solid[i] = !is_empty_tile(tiles_[i]);
      if (grid.solid[i]) tile_texture[i] = legend_.at(tiles_[i]);
    }
    grid_to_walls(src_, std::move(grid), tile_texture, legend_.begin()->second, 0);
    const FileLoc rows = file_.at(map_line_);
    for (Wall& w : src_.walls) w.loc = rows;
  }

  int texture_ref(const Statement& s, std::string_view name) const {
    auto it = textures_.find(std::string(name));
    if (it == textures_.end()) s.fail("unknown texture '" + std::string(name) + "'");
    return it->second;
  }

  struct Plane {
    double height = 0;
    int texture = kNone;
    int line = 0;
  };

  Source src_;
  LoadOptions options_;
  FileLoc file_;  // the path as messages name it, shared by every record
  detail::Sprites sprites_;
  std::unordered_map<std::string, int> textures_;
  std::map<char, int> legend_;  // ordered: the first tile textures the border
  double cell_ = 64;
  int light_ = 192;
  Plane floor_, ceiling_;
  int cols_ = 0, rows_ = 0, map_line_ = 0;
  std::vector<char> tiles_;
  std::vector<int> row_lines_;
  bool have_player_ = false;
};

}  // namespace

namespace {

// The runs of grid_to_walls: along each grid line, the longest stretches of edges
// between an empty and a solid cell with the empty cell on the same side and one
// texture. horizontal(c0, c1, r, north_empty, texture) for line y = r, cells c0..c1-1;
// vertical(r0, r1, c, east_empty, texture) for line x = c.
template <typename TextureOf, typename Horizontal, typename Vertical>
void for_each_run(const GridInfo& grid, const TextureOf& texture_of, Horizontal&& horizontal, Vertical&& vertical) {
  for (int r = 0; r <= grid.rows; ++r)
    for (int c = 0; c < grid.cols;) {
      const bool above = !grid.is_solid(c, r), below = !grid.is_solid(c, r - 1);
      if (above == below) {
        ++c;
        continue;
      }
      const int texture = above ? texture_of(c, r - 1) : texture_of(c, r);
      int end = c + 1;
      while (end < grid.cols && !grid.is_solid(end, r) == above && !grid.is_solid(end, r - 1) == below &&
             (above ? texture_of(end, r - 1) : texture_of(end, r)) == texture)
        ++end;
      horizontal(c, end, r, above, texture);
      c = end;
    }
  for (int c = 0; c <= grid.cols; ++c)
    for (int r = 0; r < grid.rows;) {
      const bool east = !grid.is_solid(c, r), west = !grid.is_solid(c - 1, r);
      if (east == west) {
        ++r;
        continue;
      }
      const int texture = east ? texture_of(c - 1, r) : texture_of(c, r);
      int end = r + 1;
      while (end < grid.rows && !grid.is_solid(c, end) == east && !grid.is_solid(c - 1, end) == west &&
             (east ? texture_of(c - 1, end) : texture_of(c, end)) == texture)
        ++end;
      vertical(r, end, c, east, texture);
      r = end;
    }
}

}  // namespace

void grid_to_walls(Source& src, GridInfo grid, const std::vector<int>& tile_texture, int border_texture, int sector) {
  auto texture_of = [&](int c, int r) {
    return c < 0 || r < 0 || c >= grid.cols || r >= grid.rows ? border_texture : tile_texture[size_t(r) * grid.cols + c];
  };
  // Counted first: a grid with too many walls is refused before any is made.
  size_t walls = 0;
  auto count = [&](int, int, int, bool, int) { ++walls; };
  for_each_run(grid, texture_of, count, count);
  if (walls > limits::kMaxWalls) throw Error(FileLoc{src.path.string(), 0}, limits::too_many_walls());
  src.walls.reserve(src.walls.size() + walls);

  grid.faces.assign(size_t(grid.cols) * grid.rows * 4, kNone);
  std::unordered_map<int64_t, int> vertex_at;
  auto vertex = [&](int gx, int gy) {
    const int64_t key = int64_t(gx) * (grid.rows + 1) + gy;
    auto [it, added] = vertex_at.try_emplace(key, int(src.vertices.size()));
    if (added) {
      int64_t x = 0, y = 0;
      geom::to_fixed(gx * grid.cell, x);
      geom::to_fixed(gy * grid.cell, y);
      src.vertices.push_back({{x, y}});
    }
    return it->second;
  };
  auto add_wall = [&](int v1, int v2, int texture) {
    Wall w;
    w.v1 = v1;
    w.v2 = v2;
    w.front.sector = sector;
    w.front.middle = texture;
    src.walls.push_back(w);
    return int(src.walls.size() - 1);
  };
  auto set_face = [&](int c, int r, int face, int wall) { grid.faces[(size_t(r) * grid.cols + c) * 4 + face] = wall; };

  // Horizontal grid lines y = r: the empty cell above (north) or below (south) gets a wall facing it.
  auto horizontal = [&](int c, int end, int r, bool above, int texture) {
    const int wall = above ? add_wall(vertex(end, r), vertex(c, r), texture)   // walking west: north on the right
                           : add_wall(vertex(c, r), vertex(end, r), texture);  // walking east: south on the right
    for (int k = c; k < end; ++k) above ? set_face(k, r, kFaceSouth, wall) : set_face(k, r - 1, kFaceNorth, wall);
  };
  // Vertical grid lines x = c: the empty cell to the east or west.
  auto vertical = [&](int r, int end, int c, bool east, int texture) {
    const int wall = east ? add_wall(vertex(c, r), vertex(c, end), texture)   // walking north: east on the right
                          : add_wall(vertex(c, end), vertex(c, r), texture);  // walking south: west on the right
    for (int k = r; k < end; ++k) east ? set_face(c, k, kFaceWest, wall) : set_face(c - 1, k, kFaceEast, wall);
  };
  for_each_run(grid, texture_of, horizontal, vertical);
  src.grid = std::move(grid);
}

Source parse_grid(const std::string& text, const std::filesystem::path& path, const LoadOptions& options) {
  return GridParser(path, options).run(text);
}

Source load_grid(const std::filesystem::path& path, const LoadOptions& options) {
  Source source = parse_grid(read_file_text(path), path, options);
  validate(source);
  return source;
}

Source load_source(const std::filesystem::path& path, const LoadOptions& options) {
  return path.extension() == ".grid" ? load_grid(path, options) : load_map(path, options);
}

}  // namespace p3d::map
