#include "game/menu.h"

namespace p3d::game {

std::vector<std::string> Menu::lines() const {
  static const char* const kNames[kItems] = {"Resume", "Keys", "Quit"};
  std::vector<std::string> out = {"pseudo3d", ""};
  for (int i = 0; i < kItems; ++i) out.push_back(std::string(i == index_ ? "> " : "  ") + kNames[i]);
  out.push_back("");
  out.push_back("Up/Down, Enter; Esc resumes");
  return out;
}

}  // namespace p3d::game
