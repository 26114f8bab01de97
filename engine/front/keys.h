// Doom's key codes (its doomkeys.h): printable keys are their lower-case ASCII, the
// others codes of their own. The front end speaks them, so that Doom's menus, its
// letter shortcuts and its typed save names behave as Doom's; the window maps its
// keys to them, and key scripts and the settings file name them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace p3d::front {

enum Key : int {
  kKeyNone = 0,
  kKeyTab = 9,
  kKeyEnter = 13,
  kKeyEscape = 27,
  kKeySpace = ' ',
  kKeyMinus = '-',
  kKeyEquals = '=',
  kKeyBackspace = 0x7f,
  kKeyLeft = 0xac,
  kKeyUp = 0xad,
  kKeyRight = 0xae,
  kKeyDown = 0xaf,
  kKeyRCtrl = 0x80 + 0x1d,
  kKeyRShift = 0x80 + 0x36,
  kKeyRAlt = 0x80 + 0x38,
  kKeyCapsLock = 0x80 + 0x3a,
  kKeyF1 = 0x80 + 0x3b,
  kKeyF2,
  kKeyF3,
  kKeyF4,
  kKeyF5,
  kKeyF6,
  kKeyF7,
  kKeyF8,
  kKeyF9,
  kKeyF10,
  kKeyNumLock = 0x80 + 0x45,
  kKeyScrollLock = 0x80 + 0x46,
  kKeyHome = 0x80 + 0x47,
  kKeyPageUp = 0x80 + 0x49,
  kKeyEnd = 0x80 + 0x4f,
  kKeyPageDown = 0x80 + 0x51,
  kKeyInsert = 0x80 + 0x52,
  kKeyDelete = 0x80 + 0x53,
  kKeyF11 = 0x80 + 0x57,
  kKeyF12 = 0x80 + 0x58,
  kKeyPrintScreen = 0x80 + 0x59,
  kKeyPause = 0xff,
};

// A key's name as scripts and the settings file write it: "escape", "f1", "up", "a",
// "space"...; printable keys other than letters and digits by their character.
std::string key_name(int key);
// The key of a name (case-insensitive), or nullopt.
std::optional<int> key_from_name(std::string_view name);

}  // namespace p3d::front
