// The player's settings, kept between runs in a text file under the user's XDG config
// directory ($XDG_CONFIG_HOME/pseudo3d/settings.cfg, else ~/.config/...): what Doom's
// menus change (mouse, messages, detail, screen size, volumes, gamma), the keys, the
// window, the renderer and the last WAD played. `name = value` lines; unknown names
// and bad values are warned about and skipped, so a damaged file never stops the
// game. Written atomically. No SDL here.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/front/menu.h"

namespace p3d::game {

// What the keys do in a level, each bound to one or more of Doom's key codes.
enum class Action : uint8_t {
  kForward, kBack, kTurnLeft, kTurnRight, kStrafeLeft, kStrafeRight, kUse, kFire, kRun, kStrafe, kAutomap, kCount
};
const char* action_name(Action action);
using KeyBindings = std::array<std::vector<int>, size_t(Action::kCount)>;
// W/S/A/D and the arrows, Space or E to use, Ctrl to fire, Shift to run, Alt to
// strafe with the turn keys, Tab for the map.
KeyBindings default_key_bindings();

struct Settings {
  front::MenuSettings menu;
  KeyBindings keys = default_key_bindings();
  int window_width = 960, window_height = 600;
  bool fullscreen = false;
  std::string renderer = "bsp";
  std::filesystem::path last_wad;  // the IWAD played last: played again when none is named
};

// Where the settings live: $XDG_CONFIG_HOME/pseudo3d/settings.cfg, or
// ~/.config/pseudo3d/settings.cfg; empty when neither HOME nor XDG_CONFIG_HOME is set.
std::filesystem::path settings_path();
// Where saved games live: $XDG_DATA_HOME/pseudo3d/savegames/<iwad>/, or
// ~/.local/share/pseudo3d/savegames/<iwad>/ (the IWAD's file name, as Chocolate Doom's).
std::filesystem::path save_directory(const std::filesystem::path& iwad);

// An IWAD to play when none is named, found as Chocolate Doom finds them: in
// $DOOMWADDIR, each directory of $DOOMWADPATH, then /usr/share/games/doom,
// /usr/local/share/games/doom, /usr/share/doom; Doom II, Doom, then Freedoom's.
// Empty when there is none.
std::filesystem::path find_iwad();

// The settings as a file's text, and back. parse_settings starts from the defaults
// and warns (one line each, "<where>:<line>: ...") about what it skips.
std::string format_settings(const Settings& settings);
Settings parse_settings(const std::string& text, const std::string& where, std::vector<std::string>& warnings);

// Reads the file (the defaults, and a warning, when it is missing... unreadable or
// damaged: never an exception); writes it atomically, creating its directory. save_settings
// returns false (with the reason in `why`) when it cannot write.
Settings load_settings(const std::filesystem::path& path, std::vector<std::string>& warnings);
bool save_settings(const Settings& settings, const std::filesystem::path& path, std::string& why);

}  // namespace p3d::game
