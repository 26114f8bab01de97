// mapgen: random levels for tests and benchmarks (segment soups, room grids).
#include "engine/map/generate.h"
#include "engine/util/file.h"
#include "tools/cli.h"

using namespace p3d;

int main(int argc, char** argv) {
  CLI::App app{"mapgen: write a random level as a .map source", "mapgen"};
  std::string kind, output, texture_dir = "maps/textures";
  map::GenerateOptions options;
  app.add_option("kind", kind, "soup (plain non-crossing segments) or rooms (sectors joined by doorways)")
      ->required()
      ->check(CLI::IsMember({"soup", "rooms"}));
  app.add_option("--walls", options.walls, "number of walls (rooms: at least this many)")
      ->check(CLI::Range(size_t{1}, size_t{4000000}))
      ->capture_default_str();
  app.add_option("--seed", options.seed, "random seed")->capture_default_str();
  app.add_option("--textures", texture_dir, "directory with brick, stone, metal, wood, tech and rock PNGs")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  app.add_option("-o,--output", output, ".map file to write")->required();

  return cli::run(app, argc, argv, [&] {
    const std::vector<std::string> names = {"brick", "stone", "metal", "wood", "tech", "rock"};
    const std::filesystem::path out_dir = std::filesystem::absolute(output).parent_path();
    std::vector<std::string> files;
    for (const std::string& name : names) {
      const std::filesystem::path file = std::filesystem::absolute(std::filesystem::path(texture_dir) / (name + ".png"));
      options.textures.push_back({name, image::load_png(file), {}});
      files.push_back(std::filesystem::relative(file, out_dir).string());
    }
    const map::Source source = kind == "soup" ? map::generate_soup(options) : map::generate_rooms(options);
    map::validate(source);
    write_file_atomically(output, map::to_map_text(source, files));
    std::printf("%s: %zu walls, %zu sectors, %zu vertices\n", output.c_str(), source.walls.size(),
                source.sectors.size(), source.vertices.size());
    return 0;
  });
}
