#include "engine/front/keys.h"

#include <cctype>
#include <cstdio>
#include <utility>

namespace p3d::front {

namespace {

constexpr std::pair<int, const char*> kNames[] = {
    {kKeyTab, "tab"},           {kKeyEnter, "enter"},         {kKeyEscape, "escape"},   {kKeySpace, "space"},
    {kKeyBackspace, "backspace"}, {kKeyLeft, "left"},         {kKeyUp, "up"},           {kKeyRight, "right"},
    {kKeyDown, "down"},         {kKeyRCtrl, "ctrl"},          {kKeyRShift, "shift"},    {kKeyRAlt, "alt"},
    {kKeyCapsLock, "capslock"}, {kKeyNumLock, "numlock"},     {kKeyScrollLock, "scrolllock"},
    {kKeyHome, "home"},         {kKeyPageUp, "pageup"},       {kKeyEnd, "end"},         {kKeyPageDown, "pagedown"},
    {kKeyInsert, "insert"},     {kKeyDelete, "delete"},       {kKeyF11, "f11"},         {kKeyF12, "f12"},
    {kKeyPrintScreen, "printscreen"}, {kKeyPause, "pause"},
};

}  // namespace

std::string key_name(int key) {
  for (const auto& [k, name] : kNames)
    if (k == key) return name;
  if (key >= kKeyF1 && key <= kKeyF10) return "f" + std::to_string(key - kKeyF1 + 1);
  if (key > ' ' && key < 0x7f) return std::string(1, char(key));
  char code[16];
  std::snprintf(code, sizeof code, "key%d", key);
  return code;
}

std::optional<int> key_from_name(std::string_view name) {
  std::string lower;
  for (char c : name) lower += char(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& [k, n] : kNames)
    if (lower == n) return k;
  if (lower.size() == 1 && lower[0] > ' ' && lower[0] < 0x7f) return int(lower[0]);
  int n = 0;
  char tail = 0;
  if (std::sscanf(lower.c_str(), "f%d%c", &n, &tail) == 1 && n >= 1 && n <= 12)
    return n <= 10 ? kKeyF1 + n - 1 : n == 11 ? kKeyF11 : kKeyF12;
  if (std::sscanf(lower.c_str(), "key%d%c", &n, &tail) == 1 && n > 0 && n < 256) return n;
  return std::nullopt;
}

}  // namespace p3d::front
