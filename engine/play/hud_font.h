// Doom's heads-up font (STCFN033 to STCFN095: '!' to '_'), for the message line at
// the top left of the screen; Doom shows messages in capitals, spaces 4 pixels wide.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/play/screen.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::play {

class HudFont {
 public:
  // nullopt when the WADs hold none of the font's letters.
  static std::optional<HudFont> load(const wad::Stack& wads);
  // Draws the text from Doom's screen place (x, y) of a 320x200 screen, each texel a
  // scale x scale square offset by (left, top) in the frame; returns the rows used.
  int draw(image::Image& frame, const std::string& text, int x, int y, int scale, int left, int top,
           const std::vector<uint32_t>& palette) const;
  int height() const { return height_; }
  // A letter's picture ('!' to '_', lower case as upper), or nullptr: drawn as a space.
  const wad::IndexedImage* glyph(char c) const;
  // Doom's M_StringWidth: the letters' widths, 4 for a space or unknown letter.
  int width(const std::string& text) const;
  // Doom's line height for menus and their messages: its first letter's ('!').
  int first_height() const { return glyphs_[0] ? glyphs_[0]->height : height_; }

 private:
  static constexpr char kFirst = '!', kLast = '_';
  std::array<std::optional<wad::IndexedImage>, kLast - kFirst + 1> glyphs_;
  int height_ = 8;
};

}  // namespace p3d::play
