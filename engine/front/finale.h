// Doom's finale (f_finale.c): after an episode's last map (Doom) or between Doom II's
// clusters, the story typed out letter by letter over a flat with the victory music;
// then Doom's episodes end on a picture (the third on the bunny scrolling by), and
// Doom II goes on to its next map. Doom II's cast of monsters after MAP30 is not
// played: the finale ends there.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/front/game_mode.h"
#include "engine/front/menu_art.h"
#include "engine/play/info.h"
#include "engine/play/music.h"

namespace p3d::front {

// Whether Doom shows a finale after this map (F_StartFinale's callers): Doom's
// episodes after their eighth map (instead of the tally), Doom II after MAP06, 11, 20
// and 30, and after 15 and 31 when left by their secret exits (after the tally).
bool has_finale(GameMode mode, int episode, int map, bool secret_exit);

class Finale {
 public:
  // `doom_text` gives a text by its BEX mnemonic as the WADs word it ("E1TEXT",
  // "BGFLATE1"): Menu::doom_text.
  Finale(GameMode mode, int episode, int map, const std::function<std::string(const std::string&)>& doom_text);

  play::Track music() const { return music_; }
  // F_Ticker; `pressed`: the player pressed a button this tic. What comes next.
  enum class Next : uint8_t { kStay, kNextMap, kEnd };
  Next tic(bool pressed);
  // F_Drawer: the text over its flat, or the episode's last picture.
  void draw(const MenuArt& art, const wad::Stack& wads, image::Image& frame, const std::vector<uint32_t>& palette) const;
  std::vector<play::Sound> take_sounds() { return std::exchange(sounds_, {}); }
  // The art screen begins: Doom melts into it.
  bool screen_changed() { return std::exchange(screen_changed_, false); }

 private:
  void draw_text(const MenuArt& art, const wad::Stack& wads, image::Image& frame, const std::vector<uint32_t>& palette) const;
  void draw_bunny(const MenuArt& art, image::Image& frame, const std::vector<uint32_t>& palette) const;

  GameMode mode_;
  int episode_, map_;
  std::string text_, flat_;
  play::Track music_;
  enum class Stage : uint8_t { kText, kArt } stage_ = Stage::kText;
  int count_ = 0;
  int last_bunny_stage_ = 0;
  std::vector<play::Sound> sounds_;
  bool screen_changed_ = false;
};

}  // namespace p3d::front
