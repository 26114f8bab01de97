// The window: the only file that includes SDL. Keys become Doom's key codes for the
// front end; a fixed 35 Hz loop runs its tics; its frames go to the screen through
// one streaming texture, seen through Doom's gamma; its sounds to the audio device.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "game/autopilot.h"
#include "game/front_end.h"
#include "game/netgame.h"
#include "game/settings.h"

namespace p3d::game {

struct WindowOptions {
  int render_width = 0, render_height = 0;  // 0: render at the window's size
  bool vsync = true;
  bool sound = true;                        // Doom's sound effects (and music) from the level's WADs
  bool music = true;                        // Doom's music, through FluidSynth (game/music_player.h)
  std::string soundfont;                    // the music's sound font; empty: find_soundfont's
  bool map_reload = false;                  // recompile the source map when it changes on disk
  std::filesystem::path record;             // write the tics played to this demo on exit
  bool long_tics = false;                   // a .lmp record keeps whole turns (Doom v1.91's long tics)
  std::optional<play::Demo> play;           // replay this demo, then quit
  bool timedemo = false;                    // replay one tic per frame, as fast as possible (Doom's -timedemo)
  std::optional<std::vector<Waypoint>> autopilot;  // walk these waypoints, then quit
  uint64_t quit_after_tics = 0;             // 0: play until the window closes
  NetPlay* netplay = nullptr;               // a netgame: its tics run as the server sends them
  // Keeps the settings as the menus and the window left them (main writes the file,
  // leaving out what the command line changed for this run only).
  std::function<void(const Settings&)> keep_settings;
  bool wad_changed = false;  // another WAD than the settings' last one is played: kept at exit
};

// Runs the front end in a window on `settings` (which the menus change); returns the
// process exit status.
int run_window(FrontEnd& front, Settings& settings, const WindowOptions& options);

}  // namespace p3d::game
