// Opening a level by what a command line names: a compiled .bsp is read (and
// validated); a .map or .grid source, or a map in WADs (Doom's -iwad, -file and a
// map name), is compiled on the fly with the given options. The one place that
// reads level files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/bsp/build.h"
#include "engine/wad/import.h"
#include "engine/wad/wad.h"

namespace p3d::bsp {

struct LevelSource {
  std::filesystem::path file;               // a .bsp, .map or .grid; empty for a WAD map
  std::vector<std::filesystem::path> wads;  // the IWAD, then each PWAD (later ones override)
  std::string map;                          // the WAD map's name; empty: the first map of the last WAD holding maps
  map::LoadOptions load;                    // for a .map or .grid: where its pictures may come from

  bool is_wad() const { return !wads.empty(); }
};

bool is_source_path(const std::filesystem::path& path);  // .map or .grid

// What a file is, by its first bytes (a compiled level's magic, a WAD's or PNG's
// header) and only then by its extension (.map, .grid text).
enum class FileKind { kMapSource, kGridSource, kCompiled, kWad, kPng, kNotRegular, kUnknown };
FileKind file_kind(const std::filesystem::path& path);
// Why a file of this kind is not what a program wanted, for messages: "a PNG image".
const char* describe(FileKind kind);
// A .bsp, .map or .grid file, recognised by content; throws Error naming what the file
// is when it is none of these.
level::Level load_level(const std::filesystem::path& path, const Options& options = {},
                        const map::LoadOptions& load = {});

// Reads the WADs, later ones overriding earlier ones; throws Error for an unreadable or broken WAD.
wad::Stack read_wads(const std::vector<std::filesystem::path>& paths);
// The map a LevelSource means in these WADs (resolving an empty name); throws Error when there is none.
std::string resolve_map_name(const wad::Stack& wads, const std::string& name);
// "MAP01: Entryway": the map's name and, when the WADs' DEHACKED strings give one, its title.
std::string map_title(const wad::Stack& wads, const std::string& map);

// Compiles a WAD map; the importer's warnings (and a player start outside every
// sector) are appended to `warnings`.
level::Level build_wad_map(const wad::Stack& wads, const std::string& map, const Options& options,
                           std::vector<std::string>* warnings, Stats* stats = nullptr,
                           const wad::ImportOptions& import = {});

struct OpenedLevel {
  level::Level level;
  std::string name;                   // the file, or "<last wad>:<map>" with the map resolved
  std::vector<std::string> warnings;  // the importer's, for WAD maps
};
// Any LevelSource. Throws Error for an unreadable, broken or invalid input.
OpenedLevel open_level(const LevelSource& source, const Options& options = {},
                       const wad::ImportOptions& import = {});

}  // namespace p3d::bsp
