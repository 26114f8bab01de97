// A WAD map as a map source, with Doom's art: the importer repairs what Doom
// tolerates, as Doom behaves, and says so in a located warning; only a map that
// cannot be built at all (no art, a broken lump, a vertex out of range) is an error.
//
// Repairs (each warned about, "<wad>:<map>: LINEDEFS #n: warning: ..."):
//  - zero-length lines are dropped;
//  - a line whose front sidedef (or its sector) does not exist is dropped; a bad
//    back sidedef makes the line one-sided;
//  - where collinear lines overlap and could be seen together, the later line
//    keeps only what the earlier ones leave (lines facing apart are both kept);
//  - unknown textures and flats are missing: a missing upper or lower part shows
//    the far sector's plane, a missing middle the near sector's planes;
// Kept as they are, with a warning: ceilings below floors, lines crossing other
// lines, sectors that do not close, lines with the same sector on both sides.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/map/source.h"
#include "engine/wad/map_data.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

class ArtCache;

// A sprite frame a thing may show: its four-letter name, frame letter and full bright.
struct FrameName {
  std::string sprite;
  char frame;
  bool bright;
};

struct ImportOptions {
  size_t max_warnings_per_kind = SIZE_MAX;  // further warnings of a kind are counted, not listed
  // The frames a thing type may show or make shown as it walks its states (the rules
  // above the importer know them: bsp::build_wad_map asks engine/play), embedded
  // beside its first for each type placed; none when unset.
  std::function<std::vector<FrameName>(int editor_number)> thing_frames;
  // Frames embedded in every map whatever its things (the player's, puffs, blood...).
  // Frames of either list whose sprite lumps the WADs lack are left out silently.
  std::vector<FrameName> always_frames;
  // Pictures made once for many maps of the same Stack (see art_cache.h); when unset,
  // the import makes its own.
  std::shared_ptr<ArtCache> art_cache;
  // False for a level that is only written (pseudo3d-mapc): its pictures keep their
  // palette indices and which pixels are drawn, not their colours (a compiled level
  // stores no more; reading it back colours them).
  bool colours = true;
};

struct ImportResult {
  map::Source source;
  std::vector<std::string> warnings;  // "<wad>:<map>: <record>: warning: <message>"
  size_t warning_count = 0;           // every warning, listed above or only counted (max_warnings_per_kind)
};

// Throws Error("<wad>:<map>: ...") when the map does not exist or cannot be built.
ImportResult import_map(const Stack& stack, std::string_view map_name, const ImportOptions& options = {});

// The same from decoded records (tests write records directly). With the map's lumps,
// things stand in the sectors the map's own nodes place them in, as in Doom.
ImportResult import_map_data(const Stack& stack, const MapData& data, const ImportOptions& options = {},
                             const MapLumps* lumps = nullptr);

}  // namespace p3d::wad
