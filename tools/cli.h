// Small helpers shared by the command-line tools: argument value parsing with
// clear errors, timing, and the one place errors are turned into exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "engine/bsp/load.h"
#include "engine/geom/geom.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::cli {

constexpr double kAnyFinite = 1e300;

// A number in [lo, hi]: unlike CLI::Range (every comparison with NaN is false), NaN
// and infinities are refused.
inline CLI::Validator finite_range(double lo, double hi) {
  char desc[64];
  std::snprintf(desc, sizeof desc, "FLOAT in [%g - %g]", lo, hi);
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != 0) return "'" + text + "' is not a number";
        if (!std::isfinite(v) || v < lo || v > hi) {
          char buf[128];
          if (lo == -kAnyFinite)
            std::snprintf(buf, sizeof buf, "must be a finite number, got '%s'", text.c_str());
          else
            std::snprintf(buf, sizeof buf, "must be a finite number from %g to %g, got '%s'", lo, hi, text.c_str());
          return buf;
        }
        return "";
      },
      desc);
}

// Any finite number.
inline CLI::Validator finite() { return finite_range(-kAnyFinite, kAnyFinite); }

// "X,Y" -> point within the camera range; throws CLI::ValidationError.
inline geom::Vec2 parse_point(const std::string& text, const char* option) {
  double x = 0, y = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &x, &y, &extra) != 2 || !std::isfinite(x) || !std::isfinite(y))
    throw CLI::ValidationError(option, "expected X,Y with finite numbers, got '" + text + "'");
  if (std::fabs(x) > render::kMaxCameraCoord || std::fabs(y) > render::kMaxCameraCoord)
    throw CLI::ValidationError(option, "X,Y must lie within +-" + std::to_string(int64_t(render::kMaxCameraCoord)));
  return {x, y};
}

// An eye height within the camera range; throws CLI::ValidationError.
inline void check_eye(double eye) {
  if (!std::isfinite(eye) || std::fabs(eye) > render::kMaxCameraCoord)
    throw CLI::ValidationError("--eye", "must be finite and within +-" + std::to_string(int64_t(render::kMaxCameraCoord)));
}

// "WxH" -> size; throws CLI::ValidationError naming the option.
inline void parse_size(const std::string& text, int& w, int& h, const char* option = "--size") {
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw CLI::ValidationError(option, "expected WxH between 1x1 and 16384x16384, got '" + text + "'");
}

// Edit distance (insertions, deletions, substitutions), for "did you mean".
inline size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// Every long option name of the app and its subcommands ("--size").
inline std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& long_name : o->get_lnames()) names.push_back("--" + long_name);
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    const std::vector<std::string> more = long_options(*sub);
    names.insert(names.end(), more.begin(), more.end());
  }
  return names;
}

// The option nearest an unknown argument: the one it begins ("--head" -> "--headless",
// the shortest when several do), else a real near miss ("--sise" -> "--size": a few
// edits, fewer for short names); "" when the argument is an option that exists or
// nothing is near.
inline std::string nearest_option(const CLI::App& app, const std::string& arg) {
  const std::string name = arg.substr(0, arg.find('='));
  const std::vector<std::string> names = long_options(app);
  if (std::find(names.begin(), names.end(), name) != names.end()) return "";
  std::string best;
  for (const std::string& option : names)
    if (name.size() > 3 && option.rfind(name, 0) == 0 && (best.empty() || option.size() < best.size())) best = option;
  if (!best.empty()) return best;
  size_t best_distance = std::max<size_t>(2, name.size() / 4) + 1;
  for (const std::string& option : names) {
    const size_t d = edit_distance(name, option);
    if (d < best_distance) best_distance = d, best = option;
  }
  return best;
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The sphere tracers' settings, shared by capture and compare.
inline void add_renderer_options(CLI::App& app, render::RendererOptions& o) {
  app.add_option("--epsilon", o.sphere_epsilon, "sphere: distance at which walls are tested exactly")
      ->check(finite_range(1e-6, 1e6))
      ->capture_default_str();
  app.add_option("--relaxation", o.sphere_relaxation, "sphere: over-relaxation factor (1 = plain)")
      ->check(finite_range(1.0, 1.99))
      ->capture_default_str();
  app.add_option("--max-steps", o.sphere_max_steps, "sphere: steps before a ray gives up")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--threads", o.threads,
                 "threads drawing each frame (bsp: column strips; capture: also encoding PNGs); "
                 "frames and statistics are the same for any count (default: every core)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
}

// The level a tool works on: a file (.bsp, .map, .grid, or a WAD), or a map in WADs
// named Doom's way (--iwad, --file, --map).
struct LevelArgs {
  std::string path;                // positional
  std::string iwad;
  std::vector<std::string> files;  // PWADs
  std::string map;
  bool textures_anywhere = false;
};

// --iwad, --file, --map: a map in WADs, Doom's way.
inline void add_wad_options(CLI::App& app, LevelArgs& a) {
  app.add_option("--iwad", a.iwad, "the IWAD whose maps and art to use, as Doom's -iwad")->check(CLI::ExistingFile);
  app.add_option("--file", a.files, "PWADs loaded after the IWAD, later ones overriding (Doom's -file)")
      ->check(CLI::ExistingFile);
  app.add_option("--map", a.map, "the WAD's map: MAP01, E1M1 (default: the first map of the last WAD holding maps)");
}

// A level file as the positional argument, or a map in WADs.
inline void add_level_options(CLI::App& app, LevelArgs& a) {
  app.add_option("level", a.path, "level: a compiled .bsp, a .map or .grid (compiled on the fly), or a WAD")
      ->check(CLI::ExistingFile);
  app.add_flag("--textures-anywhere", a.textures_anywhere,
               "let a .map or .grid read pictures outside its own directory (absolute or ../ paths)");
  add_wad_options(app, a);
}

// Doom's -skill: which things are present (default: level::kDefaultSkill).
inline void add_skill_option(CLI::App& app, int& skill) {
  app.add_option("--skill", skill, "skill 1-5 as Doom's: the things present at it are drawn")
      ->check(CLI::Range(1, 5))
      ->capture_default_str();
}

// Whether a file starts like a WAD (IWAD or PWAD).
inline bool is_wad_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;  // never open a FIFO: it would block
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  char magic[4] = {};
  const bool wad = std::fread(magic, 1, 4, f) == 4 && (std::string_view(magic, 4) == "IWAD" || std::string_view(magic, 4) == "PWAD");
  std::fclose(f);
  return wad;
}

inline std::filesystem::path bundled_maps_dir();

// Throws CLI::ValidationError for a contradictory or missing choice.
inline bsp::LevelSource level_source(const LevelArgs& a) {
  bsp::LevelSource s;
  s.map = a.map;
  if (!a.iwad.empty()) {
    if (!a.path.empty())
      throw CLI::ValidationError("--iwad", "name either a level file or --iwad, not both ('" + a.path + "')");
    s.wads.push_back(a.iwad);
  } else if (!a.path.empty() && is_wad_file(a.path)) {
    s.wads.push_back(a.path);  // a WAD named alone: its own maps and art
  } else if (!a.files.empty()) {
    throw CLI::ValidationError("--file", "PWADs need the IWAD they build on: add --iwad");
  } else if (a.path.empty()) {
    throw CLI::ValidationError("level", "name a level file, or a WAD map with --iwad [--file ...] [--map ...]");
  } else {
    if (!a.map.empty()) throw CLI::ValidationError("--map", "names a map in WADs: use it with --iwad");
    s.file = a.path;
    s.load.textures_anywhere = a.textures_anywhere;
    s.load.bundled_textures = bundled_maps_dir() / "textures";
    return s;
  }
  for (const std::string& f : a.files) s.wads.push_back(f);
  return s;
}

// Prints importer warnings: all of them, or a one-line count that says where to see them.
inline void report_warnings(const bsp::OpenedLevel& opened, bool all) {
  const auto& warnings = opened.warnings;
  if (warnings.empty()) return;
  if (all) {
    for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
    return;
  }
  std::fprintf(stderr, "%s: %zu warning%s about quirks Doom tolerates (pseudo3d-mapc lists them)\n", opened.name.c_str(),
               warnings.size(), warnings.size() == 1 ? "" : "s");
}

// The project's bundled data (maps/, with maps/textures/): beside the built tools
// (build/tools/x -> maps/) or installed ones (bin/x -> share/pseudo3d/maps/), else
// the source tree the tools were built from. Any working directory will do.
inline std::filesystem::path bundled_maps_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const auto& candidate : {exe.parent_path() / "../share/pseudo3d/maps", exe.parent_path() / "../../maps"})
      if (std::filesystem::exists(candidate / "textures")) return std::filesystem::weakly_canonical(candidate);
  }
#ifdef P3D_DATA_DIR
  return std::filesystem::path(P3D_DATA_DIR) / "maps";
#else
  return "maps";
#endif
}

// An output file: it must end in `extension` (the format the tool writes), and its
// directory is created. Throws CLI::ValidationError naming `option`.
inline std::filesystem::path output_file(const std::string& path, const char* extension, const char* option) {
  const std::filesystem::path p(path);
  if (p.extension() != extension)
    throw CLI::ValidationError(option, std::string("writes ") + extension + " files: name it " +
                                           std::filesystem::path(p).replace_extension(extension).string());
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  return p;
}

// An output directory, created if need be. A name with a file's extension (out/x.png)
// is refused: it is a slip for a file, not a directory anyone wants.
inline std::filesystem::path output_dir(const std::string& path, const char* option = "--output") {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* file_ext : {".png", ".csv", ".json", ".bsp", ".svg", ".map", ".grid", ".wad", ".txt"})
    if (ext == file_ext && !std::filesystem::is_directory(path))
      throw CLI::ValidationError(option, "writes a directory here (one file per camera or map), and '" + path +
                                             "' is named like a file");
  std::filesystem::create_directories(path);
  return path;
}

// The default name of what a tool writes about a level: out/<level>.<extension>,
// <level> being the file's stem or the WAD map's name in lower case.
inline std::string default_output(const bsp::LevelSource& source, const std::string& suffix) {
  std::string stem = source.is_wad() ? source.map : source.file.stem().string();
  if (stem.empty()) stem = source.wads.back().stem().string();
  for (char& c : stem) c = char(std::tolower(static_cast<unsigned char>(c)));
  return "out/" + stem + suffix;
}

// Warns (on stderr) about a camera standing outside every sector (in the void, which
// Doom's rule gives the sector of its leaf): rarely what was meant.
inline void warn_if_outside(const char* tool, const level::Level& level, const render::CameraSpec& camera) {
  if (level.sectors.empty() || level.default_sector != level::kNone ||
      level::sector_at_brute_force(level, camera.pos) != level::kNone)
    return;
  std::fprintf(stderr, "%s: warning: camera%s%s at (%g, %g) is outside every sector\n", tool,
               camera.name.empty() ? "" : " ", camera.name.c_str(), camera.pos.x, camera.pos.y);
}

// Runs a tool's body: CLI errors exit 2 with usage; p3d::Error and I/O errors exit 1.
template <typename Body>
int run(CLI::App& app, int argc, char** argv, Body&& body) {
  app.set_version_flag("--version", app.get_name() + " " + P3D_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    std::fprintf(stderr, "%s: %s\n", app.get_name().c_str(), e.what());
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg.rfind("--", 0) != 0) continue;
      if (const std::string near = nearest_option(app, arg); !near.empty())
        std::fprintf(stderr, "%s: %s: did you mean %s?\n", app.get_name().c_str(), arg.c_str(), near.c_str());
    }
    std::fprintf(stderr, "Run with --help for more information.\n");
    return 2;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {  // every usage error exits 2, as documented, under the program's name
    std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n", app.get_name().c_str(),
                 escape_controls(e.what()).c_str());
    return 2;
  }
  try {
    return body();
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "%s: %s\n", app.get_name().c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {  // bad input: the file's own message, under the program's name
    std::fprintf(stderr, "%s: %s\n", app.get_name().c_str(), escape_controls(e.what()).c_str());
    return 1;
  }
}

}  // namespace p3d::cli
