// The Esc menu: Resume, Keys, Quit. Up and down choose, Enter acts; the game waits
// while it is open. No SDL here: the window feeds it keys and reads what was chosen.
#pragma once

#include <string>
#include <vector>

namespace p3d::game {

class Menu {
 public:
  enum class Item { kResume, kKeys, kQuit };

  bool is_open() const { return open_; }
  void open() { open_ = true, index_ = 0; }
  void close() { open_ = false; }
  void up() { index_ = (index_ + kItems - 1) % kItems; }
  void down() { index_ = (index_ + 1) % kItems; }
  Item selected() const { return Item(index_); }
  // The menu's text, the chosen item marked.
  std::vector<std::string> lines() const;

 private:
  static constexpr int kItems = 3;
  bool open_ = false;
  int index_ = 0;
};

}  // namespace p3d::game
