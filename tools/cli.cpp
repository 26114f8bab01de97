#include "tools/cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <thread>
#include <utility>

#include "engine/util/error.h"

namespace p3d::cli {
namespace {

// Every long option name of the app and its subcommands ("--size").
std::vector<std::string> long_options(const CLI::App& app) {
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
std::string nearest_option(const CLI::App& app, const std::string& arg) {
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

}  // namespace

App::App(const std::string& description, const std::string& name)
    : impl_(std::make_unique<CLI::App>(description, name)), name_(name) {}

App::~App() = default;

template <typename T>
Option* App::add_option(const std::string& name, T& value, const std::string& help) {
  options_.push_back(std::make_unique<Option>(impl_->add_option(name, value, help)));
  return options_.back().get();
}

// The value types the programs' options hold.
template Option* App::add_option(const std::string&, int&, const std::string&);
template Option* App::add_option(const std::string&, unsigned&, const std::string&);
template Option* App::add_option(const std::string&, long&, const std::string&);
template Option* App::add_option(const std::string&, unsigned long&, const std::string&);
template Option* App::add_option(const std::string&, long long&, const std::string&);
template Option* App::add_option(const std::string&, unsigned long long&, const std::string&);
template Option* App::add_option(const std::string&, double&, const std::string&);
template Option* App::add_option(const std::string&, std::string&, const std::string&);
template Option* App::add_option(const std::string&, std::optional<int>&, const std::string&);
template Option* App::add_option(const std::string&, std::optional<double>&, const std::string&);
template Option* App::add_option(const std::string&, std::vector<std::string>&, const std::string&);
template Option* App::add_option(const std::string&, std::vector<int>&, const std::string&);
template Option* App::add_option(const std::string&, std::vector<size_t>&, const std::string&);
template Option* App::add_option(const std::string&, std::vector<std::pair<size_t, std::string>>&, const std::string&);

Option* App::add_flag(const std::string& name, bool& value, const std::string& help) {
  options_.push_back(std::make_unique<Option>(impl_->add_flag(name, value, help)));
  return options_.back().get();
}

Option* Option::check(const Validator& validator) {
  impl_->check(validator.impl());
  return this;
}

Option* Option::capture_default_str() {
  impl_->capture_default_str();
  return this;
}

Option* Option::required() {
  impl_->required();
  return this;
}

Option* Option::delimiter(char separator) {
  impl_->delimiter(separator);
  return this;
}

Option* Option::type_name(const std::string& name) {
  impl_->type_name(name);
  return this;
}

Option* Option::expected(int min, int max) {
  impl_->expected(min, max);
  return this;
}

Validator Range(int lo, int hi) { return Validator(std::make_shared<CLI::Range>(lo, hi)); }
Validator Range(size_t lo, size_t hi) { return Validator(std::make_shared<CLI::Range>(lo, hi)); }
Validator IsMember(std::vector<std::string> names) { return Validator(std::make_shared<CLI::IsMember>(std::move(names))); }
Validator existing_file() { return Validator(std::make_shared<CLI::Validator>(CLI::ExistingFile)); }
Validator existing_directory() { return Validator(std::make_shared<CLI::Validator>(CLI::ExistingDirectory)); }

int run(App& app, int argc, char** argv, const std::function<int()>& body) {
  CLI::App& cli = *app.impl_;
  const char* name = app.get_name().c_str();
  cli.set_version_flag("--version", app.get_name() + " " + P3D_VERSION);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg.rfind("--", 0) != 0) continue;
      if (const std::string near = nearest_option(cli, arg); !near.empty())
        std::fprintf(stderr, "%s: %s: did you mean %s?\n", name, arg.c_str(), near.c_str());
    }
    std::fprintf(stderr, "Run with --help for more information.\n");
    return 2;
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {  // every usage error exits 2, as documented, under the program's name
    std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n", name, escape_controls(e.what()).c_str());
    return 2;
  }
  try {
    return body();
  } catch (const ValidationError& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 2;
  } catch (const std::exception& e) {  // bad input: the file's own message, under the program's name
    std::fprintf(stderr, "%s: %s\n", name, escape_controls(e.what()).c_str());
    return 1;
  }
}

Validator finite_range(double lo, double hi) {
  char desc[64];
  std::snprintf(desc, sizeof desc, "FLOAT in [%g - %g]", lo, hi);
  return Validator(std::make_shared<CLI::Validator>(
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
      desc));
}

Validator finite() { return finite_range(-kAnyFinite, kAnyFinite); }

geom::Vec2 parse_point(const std::string& text, const char* option) {
  double x = 0, y = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &x, &y, &extra) != 2 || !std::isfinite(x) || !std::isfinite(y))
    throw ValidationError(option, "expected X,Y with finite numbers, got '" + text + "'");
  if (std::fabs(x) > render::kMaxCameraCoord || std::fabs(y) > render::kMaxCameraCoord)
    throw ValidationError(option, "X,Y must lie within +-" + std::to_string(std::int64_t(render::kMaxCameraCoord)));
  return {x, y};
}

void check_eye(double eye) {
  if (!std::isfinite(eye) || std::fabs(eye) > render::kMaxCameraCoord)
    throw ValidationError("--eye", "must be finite and within +-" + std::to_string(std::int64_t(render::kMaxCameraCoord)));
}

void parse_size(const std::string& text, int& w, int& h, const char* option) {
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw ValidationError(option, "expected WxH between 1x1 and 16384x16384, got '" + text + "'");
}

size_t edit_distance(const std::string& a, const std::string& b) {
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

void add_renderer_options(App& app, render::RendererOptions& o) {
  app.add_option("--epsilon", o.sphere_epsilon, "sphere: distance at which walls are tested exactly")
      ->check(finite_range(1e-6, 1e6))
      ->capture_default_str();
  app.add_option("--relaxation", o.sphere_relaxation, "sphere: over-relaxation factor (1 = plain)")
      ->check(finite_range(1.0, 1.99))
      ->capture_default_str();
  app.add_option("--max-steps", o.sphere_max_steps, "sphere: steps before a ray gives up")
      ->check(Range(1, 1000000))
      ->capture_default_str();
  o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--threads", o.threads,
                 "threads drawing each frame (bsp: column strips; capture --cameras: whole frames, each drawn "
                 "and encoded by one thread); frames and statistics are the same for any count (default: every core)")
      ->check(Range(1, 256))
      ->capture_default_str();
}


void add_wad_options(App& app, LevelArgs& a) {
  app.add_option("--iwad", a.iwad, "the IWAD whose maps and art to use, as Doom's -iwad")->check(existing_file());
  app.add_option("--file", a.files, "PWADs loaded after the IWAD, later ones overriding (Doom's -file)")
      ->check(existing_file());
  app.add_option("--map", a.map, "the WAD's map: MAP01, E1M1 (default: the first map of the last WAD holding maps)");
}

void add_level_options(App& app, LevelArgs& a) {
  app.add_option("level", a.path, "level: a compiled .bsp, a .map or .grid (compiled on the fly), or a WAD")
      ->check(existing_file());
  app.add_flag("--textures-anywhere", a.textures_anywhere,
               "let a .map or .grid read pictures outside its own directory (absolute or ../ paths)");
  add_wad_options(app, a);
}

void add_skill_option(App& app, int& skill) {
  app.add_option("--skill", skill, "skill 1-5 as Doom's: the things present at it are drawn")
      ->check(Range(1, 5))
      ->capture_default_str();
}

bool is_wad_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;  // never open a FIFO: it would block
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  char magic[4] = {};
  const bool wad = std::fread(magic, 1, 4, f) == 4 && (std::string_view(magic, 4) == "IWAD" || std::string_view(magic, 4) == "PWAD");
  std::fclose(f);
  return wad;
}

bsp::LevelSource level_source(const LevelArgs& a) {
  bsp::LevelSource s;
  s.map = a.map;
  if (!a.iwad.empty()) {
    if (!a.path.empty())
      throw ValidationError("--iwad", "name either a level file or --iwad, not both ('" + a.path + "')");
    s.wads.push_back(a.iwad);
  } else if (!a.path.empty() && is_wad_file(a.path)) {
    s.wads.push_back(a.path);  // a WAD named alone: its own maps and art
  } else if (!a.files.empty()) {
    throw ValidationError("--file", "PWADs need the IWAD they build on: add --iwad");
  } else if (a.path.empty()) {
    throw ValidationError("level", "name a level file, or a WAD map with --iwad [--file ...] [--map ...]");
  } else {
    if (!a.map.empty()) throw ValidationError("--map", "names a map in WADs: use it with --iwad");
    s.file = a.path;
    s.load.textures_anywhere = a.textures_anywhere;
    s.load.bundled_textures = bundled_maps_dir() / "textures";
    return s;
  }
  for (const std::string& f : a.files) s.wads.push_back(f);
  return s;
}

void report_warnings(const bsp::OpenedLevel& opened, bool all) {
  const auto& warnings = opened.warnings;
  if (warnings.empty()) return;
  if (all) {
    for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
    return;
  }
  std::fprintf(stderr, "%s: %zu warning%s about quirks Doom tolerates (pseudo3d-mapc lists them)\n", opened.name.c_str(),
               warnings.size(), warnings.size() == 1 ? "" : "s");
}

std::filesystem::path bundled_maps_dir() {
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

std::filesystem::path output_file(const std::string& path, const char* extension, const char* option) {
  const std::filesystem::path p(path);
  if (p.extension() != extension)
    throw ValidationError(option, std::string("writes ") + extension + " files: name it " +
                                           std::filesystem::path(p).replace_extension(extension).string());
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  return p;
}

std::filesystem::path output_dir(const std::string& path, const char* option) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* file_ext : {".png", ".csv", ".json", ".bsp", ".svg", ".map", ".grid", ".wad", ".txt"})
    if (ext == file_ext && !std::filesystem::is_directory(path))
      throw ValidationError(option, "writes a directory here (one file per camera or map), and '" + path +
                                             "' is named like a file");
  std::filesystem::create_directories(path);
  return path;
}

std::string default_output(const bsp::LevelSource& source, const std::string& suffix) {
  std::string stem = source.is_wad() ? source.map : source.file.stem().string();
  if (stem.empty()) stem = source.wads.back().stem().string();
  for (char& c : stem) c = char(std::tolower(static_cast<unsigned char>(c)));
  return "out/" + stem + suffix;
}

void warn_if_outside(const char* tool, const level::Level& level, const render::CameraSpec& camera) {
  if (level.sectors.empty() || level.default_sector != level::kNone ||
      level::sector_at_brute_force(level, camera.pos) != level::kNone)
    return;
  std::fprintf(stderr, "%s: warning: camera%s%s at (%g, %g) is outside every sector\n", tool,
               camera.name.empty() ? "" : " ", camera.name.c_str(), camera.pos.x, camera.pos.y);
}

}  // namespace p3d::cli
