// The window: the only file that includes SDL. Events become Controls and key
// actions; a fixed 35 Hz loop feeds the session; frames go to the screen through
// one streaming texture.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/input.h"
#include "game/autopilot.h"
#include "game/session.h"

namespace p3d::game {

struct WindowOptions {
  int window_width = 960, window_height = 600;
  int render_width = 0, render_height = 0;  // 0: render at the window's size
  bool fullscreen = false, vsync = true;
  bool sound = true;                        // Doom's sound effects (and music) from the level's WADs
  bool music = true;                        // Doom's music, through FluidSynth (game/music_player.h)
  std::string soundfont;                    // the music's sound font; empty: find_soundfont's
  int music_volume = 8;                     // Doom's 0..15
  bool map_reload = false;                  // recompile the source map when it changes on disk
  std::filesystem::path record;             // write the tics played to this demo on exit
  std::optional<play::Demo> play;            // replay this demo, then quit
  bool timedemo = false;                    // replay one tic per frame, as fast as possible (Doom's -timedemo)
  std::optional<std::vector<Waypoint>> autopilot;  // walk these waypoints, then quit
  InputSettings input;
  uint64_t quit_after_tics = 0;             // 0: play until the window closes
};

// Returns the process exit status.
int run_window(Session& session, const WindowOptions& options);

}  // namespace p3d::game
