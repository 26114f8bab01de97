// The command line of the tools and the game: options declared on an App, parsed with
// clear errors, values checked, and the one place errors are turned into exit codes.
// CLI11 stays behind this header (compiled once in cli.cpp): its inline code was most
// of each program's compile time.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/bsp/load.h"
#include "engine/geom/geom.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"

namespace CLI {
class App;
class Option;
class Validator;
}  // namespace CLI

namespace p3d::cli {

// A bad value found after parsing: the program exits 2 with "OPTION: message".
class ValidationError : public std::runtime_error {
 public:
  ValidationError(const std::string& option, const std::string& message) : std::runtime_error(option + ": " + message) {}
};

// A check on an option's text, named in --help ("INT in [1 - 5]").
class Validator {
 public:
  explicit Validator(std::shared_ptr<const CLI::Validator> impl) : impl_(std::move(impl)) {}
  const CLI::Validator& impl() const { return *impl_; }

 private:
  std::shared_ptr<const CLI::Validator> impl_;
};

Validator Range(int lo, int hi);
Validator Range(size_t lo, size_t hi);
Validator IsMember(std::vector<std::string> names);
Validator existing_file();
Validator existing_directory();

constexpr double kAnyFinite = 1e300;

// A number in [lo, hi]: unlike a plain range (every comparison with NaN is false), NaN
// and infinities are refused.
Validator finite_range(double lo, double hi);
// Any finite number.
Validator finite();

// One option of an App; each setter returns the option, to chain them.
class Option {
 public:
  explicit Option(CLI::Option* impl) : impl_(impl) {}
  Option* check(const Validator& validator);
  Option* capture_default_str();  // --help shows the value before parsing
  Option* required();
  Option* delimiter(char separator);        // "--x a,b" as two values
  Option* type_name(const std::string& name);
  Option* expected(int min, int max);       // how many values it takes

 private:
  CLI::Option* impl_;
};

// A program's command line: options bound to variables, filled by run().
class App {
 public:
  App(const std::string& description, const std::string& name);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // A value option ("--size", "-o,--output") or a positional one ("level"). Defined in
  // cli.cpp for the value types the programs use.
  template <typename T>
  Option* add_option(const std::string& name, T& value, const std::string& help);
  Option* add_flag(const std::string& name, bool& value, const std::string& help);
  const std::string& get_name() const { return name_; }

 private:
  friend int run(App& app, int argc, char** argv, const std::function<int()>& body);
  std::unique_ptr<CLI::App> impl_;
  std::vector<std::unique_ptr<Option>> options_;
  std::string name_;
};

// Parses the command line, then runs the program's body. Usage errors exit 2 with a
// message under the program's name (an unknown option with "did you mean"), and so does
// a ValidationError from the body; p3d::Error and I/O errors exit 1; --help and
// --version print and exit 0.
int run(App& app, int argc, char** argv, const std::function<int()>& body);

// "X,Y" -> point within the camera range; throws ValidationError naming the option.
geom::Vec2 parse_point(const std::string& text, const char* option);
// An eye height within the camera range; throws ValidationError.
void check_eye(double eye);
// "WxH" -> size; throws ValidationError naming the option.
void parse_size(const std::string& text, int& w, int& h, const char* option = "--size");

// Edit distance (insertions, deletions, substitutions), for "did you mean".
size_t edit_distance(const std::string& a, const std::string& b);

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The sphere tracers' settings and the thread count, shared by capture and compare.
void add_renderer_options(App& app, render::RendererOptions& o);

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
void add_wad_options(App& app, LevelArgs& a);
// A level file as the positional argument, or a map in WADs.
void add_level_options(App& app, LevelArgs& a);
// Doom's -skill: which things are present (default: level::kDefaultSkill).
void add_skill_option(App& app, int& skill);

// Whether a file starts like a WAD (IWAD or PWAD).
bool is_wad_file(const std::string& path);
// Throws ValidationError for a contradictory or missing choice.
bsp::LevelSource level_source(const LevelArgs& a);
// Prints importer warnings: all of them, or a one-line count that says where to see them.
void report_warnings(const bsp::OpenedLevel& opened, bool all);

// The project's bundled data (maps/, with maps/textures/): beside the built tools
// (build/tools/x -> maps/) or installed ones (bin/x -> share/pseudo3d/maps/), else
// the source tree the tools were built from. Any working directory will do.
std::filesystem::path bundled_maps_dir();

// An output file: it must end in `extension` (the format the tool writes), and its
// directory is created. Throws ValidationError naming `option`.
std::filesystem::path output_file(const std::string& path, const char* extension, const char* option);
// An output directory, created if need be. A name with a file's extension (out/x.png)
// is refused: it is a slip for a file, not a directory anyone wants.
std::filesystem::path output_dir(const std::string& path, const char* option = "--output");
// The default name of what a tool writes about a level: out/<level>.<extension>,
// <level> being the file's stem or the WAD map's name in lower case.
std::string default_output(const bsp::LevelSource& source, const std::string& suffix);

// Warns (on stderr) about a camera standing outside every sector (in the void, which
// Doom's rule gives the sector of its leaf): rarely what was meant.
void warn_if_outside(const char* tool, const level::Level& level, const render::CameraSpec& camera);

}  // namespace p3d::cli
