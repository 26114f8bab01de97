// mapgen: random levels for tests and benchmarks: segment soups, room grids and
// shapes hostile to a compiler (.map), mazes and caves (.grid tile maps).
#include "engine/map/generate.h"
#include "engine/util/file.h"
#include "tools/cli.h"

using namespace p3d;

namespace {

// The bundled textures a generated map uses, by bare file name: a map finds them
// among the bundled textures wherever it is moved (map::LoadOptions).
std::vector<std::string> texture_files(const std::string& texture_dir, const std::vector<std::string>& names) {
  std::vector<std::string> files;
  for (const std::string& name : names) {
    const std::filesystem::path file = std::filesystem::path(texture_dir) / (name + ".png");
    if (!std::filesystem::is_regular_file(file)) throw Error(file.string() + ": bundled texture not found");
    files.push_back(file.filename().string());
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-mapgen: write a random level: a .map (soup, rooms, shapes) or a .grid (maze, caves)", "pseudo3d-mapgen"};
  const std::string texture_dir = (cli::bundled_maps_dir() / "textures").string();
  std::string kind, output, grid_size = "64x64";
  map::GenerateOptions options;
  map::GridOptions grid;
  std::vector<std::string> kinds = {"soup", "rooms", "maze", "caves", "arena"};
  kinds.insert(kinds.end(), map::shape_kinds().begin(), map::shape_kinds().end());
  app.add_option("kind", kind,
                 "soup (plain non-crossing segments), rooms (sectors joined by doorways), "
                 "maze (a tile labyrinth with rooms), caves (random tiles), arena (an open hall with pillars); "
                 "shapes: circle, ellipse, jitter (a circle's vertices moved in or out), star, fan, spiral, comb, rings "
                 "(nested circular rooms), each vertex on the 1/256 grid")
      ->required()
      ->check(cli::IsMember(kinds));
  app.add_option("--walls", options.walls, "soup, rooms, shapes: number of walls (rooms: at least this many)")
      ->check(cli::Range(size_t{1}, limits::kMaxWalls / 2))
      ->capture_default_str();
  app.add_option("--grid", grid_size, "maze, caves, arena: tiles WxH")->capture_default_str();
  app.add_option("--cell", grid.cell, "maze, caves, arena: cell size in map units")->check(cli::Range(8, 512))->capture_default_str();
  app.add_option("--seed", options.seed, "random seed")->capture_default_str();
  app.add_option("-o,--output", output, "file to write")->required();

  return cli::run(app, argc, argv, [&] {
    const bool grid_kind = kind == "maze" || kind == "caves" || kind == "arena";
    const std::string ext = std::filesystem::path(output).extension().string();
    if (ext != (grid_kind ? ".grid" : ".map"))
      throw cli::ValidationError("--output", kind + " writes a " + (grid_kind ? ".grid tile map" : ".map") + ": name it " +
                                                 std::filesystem::path(output).replace_extension(grid_kind ? ".grid" : ".map").string());
    if (const auto parent = std::filesystem::path(output).parent_path(); !parent.empty())
      std::filesystem::create_directories(parent);
    if (grid_kind) {
      cli::parse_size(grid_size, grid.cols, grid.rows);
      if (grid.cols < 8 || grid.rows < 8 || grid.cols > 4096 || grid.rows > 4096)
        throw cli::ValidationError("--grid", "between 8x8 and 4096x4096 tiles");
      grid.kind = kind;
      grid.seed = options.seed;
      grid.texture_files = texture_files(texture_dir, {"brick", "stone", "metal", "wood", "tech", "tiles", "ceiling"});
      const std::string text = map::generate_grid_text(grid);
      map::validate(map::parse_grid(text, output, {.bundled_textures = texture_dir}));  // never write what mapc refuses
      write_file_atomically(output, text);
      std::printf("%s: %dx%d tiles\n", output.c_str(), grid.cols, grid.rows);
      return 0;
    }
    const std::vector<std::string> names = {"brick", "stone", "metal", "wood", "tech", "rock"};
    const auto files = texture_files(texture_dir, names);
    for (size_t i = 0; i < names.size(); ++i)
      options.textures.push_back({names[i], image::load_png(std::filesystem::path(texture_dir) / (names[i] + ".png")), {}});
    const map::Source source = kind == "soup"    ? map::generate_soup(options)
                               : kind == "rooms" ? map::generate_rooms(options)
                                                 : map::generate_shape(kind, options);
    map::validate(source);
    write_file_atomically(output, map::to_map_text(source, files));
    std::printf("%s: %zu walls, %zu sectors, %zu vertices\n", output.c_str(), source.walls.size(),
                source.sectors.size(), source.vertices.size());
    return 0;
  });
}
