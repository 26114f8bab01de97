#include "engine/bsp/load.h"

#include <algorithm>
#include <cstdio>
#include <string_view>

#include "engine/level/io.h"
#include "engine/play/things.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "engine/wad/doom_segs.h"

namespace p3d::bsp {

bool is_source_path(const std::filesystem::path& path) {
  return path.extension() == ".map" || path.extension() == ".grid";
}

FileKind file_kind(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) return FileKind::kNotRegular;
  char head[8] = {};
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    const size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    const std::string_view bytes(head, n);
    if (bytes.starts_with("P3DBSP")) return FileKind::kCompiled;
    if (bytes.starts_with("IWAD") || bytes.starts_with("PWAD")) return FileKind::kWad;
    if (bytes.starts_with("\x89PNG")) return FileKind::kPng;
  }
  if (path.extension() == ".map") return FileKind::kMapSource;
  if (path.extension() == ".grid") return FileKind::kGridSource;
  if (path.extension() == ".bsp") return FileKind::kCompiled;  // a damaged one: the reader says what is wrong
  return FileKind::kUnknown;
}

const char* describe(FileKind kind) {
  switch (kind) {
    case FileKind::kMapSource: return "a .map source";
    case FileKind::kGridSource: return "a .grid tile map";
    case FileKind::kCompiled: return "a compiled level (.bsp)";
    case FileKind::kWad: return "a WAD";
    case FileKind::kPng: return "a PNG image, not a level";
    case FileKind::kNotRegular: return "not a regular file (a directory, device, FIFO or socket)";
    case FileKind::kUnknown: break;
  }
  return "not a level (levels are .map and .grid sources, compiled .bsp files and WADs)";
}

level::Level load_level(const std::filesystem::path& path, const Options& options, const map::LoadOptions& load) {
  switch (const FileKind kind = file_kind(path)) {
    case FileKind::kCompiled: return level::read(path);
    case FileKind::kMapSource:
    case FileKind::kGridSource: return build(map::load_source(path, load), options);
    case FileKind::kWad: throw Error(path.string() + ": a WAD: name its map with --iwad and --map");
    default: throw Error(path.string() + ": " + describe(kind));
  }
}

wad::Stack read_wads(const std::vector<std::filesystem::path>& paths) {
  wad::Stack stack;
  for (const auto& path : paths) {
    auto file = std::make_shared<const MappedFile>(path);
    stack.add(wad::Wad(file->bytes(), file, path.filename().string()));
  }
  return stack;
}

std::string resolve_map_name(const wad::Stack& wads, const std::string& name) {
  if (!name.empty()) return wad::normalize_name(name);
  for (auto w = wads.wads().rbegin(); w != wads.wads().rend(); ++w) {
    const auto& lumps = w->lumps();
    for (size_t i = 0; i + 1 < lumps.size(); ++i)
      if (lumps[i + 1].name == "THINGS" || lumps[i + 1].name == "TEXTMAP") return lumps[i].name;
  }
  throw Error(wads.wads().back().name() + ": the WADs hold no maps");
}

// BEX strings in DEHACKED: HUSTR_E1M1 for ExMy maps, HUSTR_<n> for MAPnn.
std::string map_title(const wad::Stack& wads, const std::string& map) {
  const wad::Lump* dehacked = wads.find("DEHACKED");
  if (!dehacked) return map;
  std::string key = "HUSTR_" + map;
  if (map.size() > 3 && map.compare(0, 3, "MAP") == 0) key = "HUSTR_" + std::to_string(std::atoi(map.c_str() + 3));
  const std::string_view text(reinterpret_cast<const char*>(dehacked->bytes.data()), dehacked->bytes.size());
  for (size_t pos = 0; pos < text.size();) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (line.substr(0, key.size()) != key) continue;
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos || line.substr(key.size(), eq - key.size()).find_first_not_of(" \t") != std::string_view::npos)
      continue;
    std::string_view value = line.substr(eq + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    while (!value.empty() && (value.back() == '\r' || value.back() == ' ')) value.remove_suffix(1);
    if (value.empty() || value.size() > 120) return map;
    std::string title = wad::printable(value);
    // Freedoom's titles carry their own code ("C1M1: Outer Prison"): keep the map's name in front.
    const size_t colon = title.find(": ");
    return map + ": " + (colon != std::string::npos && colon < 8 ? title.substr(colon + 2) : title);
  }
  return map;
}

level::Level build_wad_map(const wad::Stack& wads, const std::string& map, const Options& options,
                           std::vector<std::string>* warnings, Stats* stats, const wad::ImportOptions& import) {
  wad::ImportOptions with_frames = import;
  if (!with_frames.thing_frames) {  // every frame Doom's rules may show on the map
    with_frames.thing_frames = play::reachable_frames;
    with_frames.always_frames = play::always_frames();
  }
  wad::ImportResult imported = wad::import_map(wads, map, with_frames);
  imported.source.title = map_title(wads, wad::normalize_name(map));
  Options o = options;
  o.player_must_be_inside = false;
  const FileLoc player = imported.source.player.loc;
  level::Level level = build(std::move(imported.source), o, stats);  // its pictures move into the level
  wad::attach_doom_data(wads, wad::normalize_name(map), level, import.art_cache.get());  // to draw by Doom's rules
  const bool player_outside =
      !level.sectors.empty() && level::sector_at_brute_force(level, level.player_start) == level::kNone;
  if (warnings) {
    warnings->insert(warnings->end(), imported.warnings.begin(), imported.warnings.end());
    if (player_outside) warnings->push_back(player.str() + ": warning: the player start lies outside every sector");
  }
  if (stats) stats->warnings = imported.warning_count + (player_outside ? 1 : 0);
  return level;
}

OpenedLevel open_level(const LevelSource& source, const Options& options, const wad::ImportOptions& import) {
  if (!source.is_wad()) return {load_level(source.file, options, source.load), source.file.string(), {}};
  const wad::Stack wads = read_wads(source.wads);
  const std::string map = resolve_map_name(wads, source.map);
  OpenedLevel out;
  out.level = build_wad_map(wads, map, options, &out.warnings, nullptr, import);
  out.name = source.wads.back().filename().string() + ":" + map;
  return out;
}

}  // namespace p3d::bsp
