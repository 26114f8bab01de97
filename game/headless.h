// Replaying a demo with no window: frames as PNG files every N tics and a CSV of
// where the player stands and what it carries beside each frame's statistics. Same
// demo, same files, byte for byte.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/play/demo.h"
#include "game/session.h"

namespace p3d::game {

struct HeadlessOptions {
  int capture_every = 35;  // tics between frames; frame 0 is the view before the first tic
  std::filesystem::path out_dir;
  int width = 640, height = 400;
  bool json = false;  // also stats.json: the same fields by name
  bool frames = true;  // false: the statistics alone (no PNG, no rendering)
  // Savegames at any tic: after the demo's tic N (0 the first), the game written to the
  // file (Doom's format with our extension), or replaced by the file's, the demo's
  // input going on. At the same tic, saves come before loads.
  struct SaveAt {
    size_t tic = 0;
    std::filesystem::path file;
  };
  std::vector<SaveAt> saves, loads;
  bool loads_doom_only = false;  // load as Doom does, ignoring our extension
  // stats.csv (and JSON): also the player's exact values as Doom keeps them: 16.16 x, y,
  // z, momentum and view height, the binary angle, Doom's random index.
  bool raw = false;
  // Also every thing after every tic, as play::dump_things writes them (empty: none).
  std::filesystem::path thing_dump;
};

struct HeadlessResult {
  int frames = 0;     // rows written (PNG files too, unless frames is off)
  size_t tics = 0;    // tics replayed: all of them, or up to where the game ended
  play::ExitKind exit = play::ExitKind::kNone;  // the last map's, when the game ended there
  std::vector<std::string> maps;                // the maps played, in order
  // Empty, or the demo's tic and what the game did there first that Chocolate Doom
  // leaves undefined (play::World::beyond_chocolate).
  std::string beyond_chocolate;
};

// Replays from the demo's start (its start, keys and cheats as recorded). A Doom demo
// that exits goes on as Doom's does, through the tally (and Doom II's text between its
// clusters, drawn in the frames) into the next map; where the game ends (an episode's
// end, the last map, the exit of a level that is no Doom map) the replay stops, and that
// tic gets a last row. The things are dumped after each tic in a level, numbered on
// across levels. Throws Error if the demo was recorded on another level.
HeadlessResult replay_headless(Session& session, const play::Demo& demo, const HeadlessOptions& options);

// "normal", "secret" or "none".
const char* exit_name(play::ExitKind exit);

}  // namespace p3d::game
