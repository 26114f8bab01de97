#include "game/settings.h"

#include <charconv>
#include <cstdlib>
#include <sstream>

#include "engine/front/keys.h"
#include "engine/util/file.h"

namespace p3d::game {

namespace {

constexpr const char* kActionNames[] = {"forward", "back",  "turn_left", "turn_right", "strafe_left", "strafe_right",
                                        "use",     "fire",  "run",       "strafe",     "automap"};
static_assert(std::size(kActionNames) == size_t(Action::kCount));

std::string trim(std::string s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::filesystem::path xdg_dir(const char* variable, const char* fallback_under_home) {
  if (const char* v = std::getenv(variable); v && *v == '/') return v;
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / fallback_under_home;
  return {};
}

// An integer setting: name, where it lives, its range.
struct IntSetting {
  const char* name;
  int front::MenuSettings::*member;
  int lo, hi;
};
constexpr IntSetting kMenuInts[] = {
    {"mouse_sensitivity", &front::MenuSettings::mouse_sensitivity, 0, 9},
    {"screen_blocks", &front::MenuSettings::screen_blocks, front::kMinScreenBlocks, front::kMaxScreenBlocks},
    {"sfx_volume", &front::MenuSettings::sfx_volume, 0, 15},
    {"music_volume", &front::MenuSettings::music_volume, 0, 15},
    {"gamma", &front::MenuSettings::gamma, 0, 4},
};
struct BoolSetting {
  const char* name;
  bool front::MenuSettings::*member;
};
constexpr BoolSetting kMenuBools[] = {
    {"show_messages", &front::MenuSettings::show_messages},
    {"low_detail", &front::MenuSettings::low_detail},
};

bool parse_int(const std::string& s, int lo, int hi, int& out) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) return false;
  out = v;
  return true;
}

bool parse_bool(const std::string& s, bool& out) {
  if (s == "1" || s == "true" || s == "yes" || s == "on") return out = true, true;
  if (s == "0" || s == "false" || s == "no" || s == "off") return out = false, true;
  return false;
}

// "w up": keys by their names, between spaces (',' is a key).
bool parse_keys(const std::string& s, std::vector<int>& out) {
  std::vector<int> keys;
  std::stringstream in(s);
  for (std::string name; in >> name;) {
    const auto key = front::key_from_name(name);
    if (!key) return false;
    keys.push_back(*key);
  }
  if (keys.empty()) return false;
  out = keys;
  return true;
}

}  // namespace

const char* action_name(Action action) { return kActionNames[size_t(action)]; }

KeyBindings default_key_bindings() {
  using namespace front;
  KeyBindings k;
  k[size_t(Action::kForward)] = {'w', kKeyUp};
  k[size_t(Action::kBack)] = {'s', kKeyDown};
  k[size_t(Action::kTurnLeft)] = {kKeyLeft};
  k[size_t(Action::kTurnRight)] = {kKeyRight};
  k[size_t(Action::kStrafeLeft)] = {'a', ','};
  k[size_t(Action::kStrafeRight)] = {'d', '.'};
  k[size_t(Action::kUse)] = {kKeySpace, 'e'};
  k[size_t(Action::kFire)] = {kKeyRCtrl};
  k[size_t(Action::kRun)] = {kKeyRShift};
  k[size_t(Action::kStrafe)] = {kKeyRAlt};
  k[size_t(Action::kAutomap)] = {kKeyTab};
  return k;
}

std::filesystem::path settings_path() {
  const std::filesystem::path dir = xdg_dir("XDG_CONFIG_HOME", ".config");
  return dir.empty() ? dir : dir / "pseudo3d" / "settings.cfg";
}

std::filesystem::path save_directory(const std::filesystem::path& iwad) {
  const std::filesystem::path dir = xdg_dir("XDG_DATA_HOME", ".local/share");
  return dir.empty() ? dir : dir / "pseudo3d" / "savegames" / iwad.filename();
}

std::filesystem::path find_iwad() {
  std::vector<std::filesystem::path> dirs;
  if (const char* d = std::getenv("DOOMWADDIR"); d && *d) dirs.emplace_back(d);
  if (const char* p = std::getenv("DOOMWADPATH"); p && *p) {
    std::stringstream in(p);
    for (std::string dir; std::getline(in, dir, ':');)
      if (!dir.empty()) dirs.emplace_back(dir);
  }
  for (const char* d : {"/usr/share/games/doom", "/usr/local/share/games/doom", "/usr/share/doom"}) dirs.emplace_back(d);
  for (const char* name : {"doom2.wad", "plutonia.wad", "tnt.wad", "doom.wad", "doom1.wad", "freedoom2.wad",
                           "freedoom1.wad", "freedm.wad"})
    for (const std::filesystem::path& dir : dirs) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(dir / name, ec)) return dir / name;
    }
  return {};
}

std::string format_settings(const Settings& s) {
  std::string out = "# pseudo3d's settings: written by the game, read at its start (command-line options win).\n";
  for (const IntSetting& i : kMenuInts) out += std::string(i.name) + " = " + std::to_string(s.menu.*i.member) + "\n";
  for (const BoolSetting& b : kMenuBools) out += std::string(b.name) + " = " + (s.menu.*b.member ? "1" : "0") + "\n";
  out += "window = " + std::to_string(s.window_width) + "x" + std::to_string(s.window_height) + "\n";
  out += std::string("fullscreen = ") + (s.fullscreen ? "1" : "0") + "\n";
  out += "renderer = " + s.renderer + "\n";
  if (!s.last_wad.empty()) out += "last_wad = " + s.last_wad.string() + "\n";
  for (size_t a = 0; a < size_t(Action::kCount); ++a) {
    std::string keys;
    for (int k : s.keys[a]) keys += (keys.empty() ? "" : " ") + front::key_name(k);
    out += std::string("key_") + kActionNames[a] + " = " + keys + "\n";
  }
  return out;
}

Settings parse_settings(const std::string& text, const std::string& where, std::vector<std::string>& warnings) {
  Settings s;
  std::stringstream in(text);
  int line_number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++line_number;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    auto warn = [&](const std::string& what) {
      warnings.push_back(where + ":" + std::to_string(line_number) + ": " + what);
    };
    const size_t eq = line.find('=');
    if (eq == std::string::npos) {
      warn("not 'name = value', skipped");
      continue;
    }
    const std::string name = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
    bool known = false, ok = false;
    for (const IntSetting& i : kMenuInts)
      if (name == i.name) known = true, ok = parse_int(value, i.lo, i.hi, s.menu.*i.member);
    for (const BoolSetting& b : kMenuBools)
      if (name == b.name) known = true, ok = parse_bool(value, s.menu.*b.member);
    for (size_t a = 0; a < size_t(Action::kCount); ++a)
      if (name == std::string("key_") + kActionNames[a]) known = true, ok = parse_keys(value, s.keys[a]);
    if (name == "window") {
      known = true;
      const size_t x = value.find('x');
      int w = 0, h = 0;
      ok = x != std::string::npos && parse_int(value.substr(0, x), 16, 16384, w) &&
           parse_int(value.substr(x + 1), 16, 16384, h);
      if (ok) s.window_width = w, s.window_height = h;
    }
    if (name == "fullscreen") known = true, ok = parse_bool(value, s.fullscreen);
    if (name == "renderer") known = true, ok = !value.empty(), s.renderer = ok ? value : s.renderer;
    if (name == "last_wad") known = true, ok = !value.empty(), s.last_wad = value;
    if (!known)
      warn("unknown setting '" + name + "', skipped");
    else if (!ok)
      warn("bad value '" + value + "' for " + name + ", the default kept");
  }
  return s;
}

Settings load_settings(const std::filesystem::path& path, std::vector<std::string>& warnings) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec)) return {};
  try {
    return parse_settings(read_file_text(path), path.string(), warnings);
  } catch (const std::exception& e) {
    warnings.push_back(std::string(e.what()) + " (the defaults used)");
    return {};
  }
}

bool save_settings(const Settings& settings, const std::filesystem::path& path, std::string& why) {
  try {
    std::filesystem::create_directories(path.parent_path());
    write_file_atomically(path, format_settings(settings));
    return true;
  } catch (const std::exception& e) {
    why = e.what();
    return false;
  }
}

}  // namespace p3d::game
