// Doom's front-end screens drawn from the WAD's own pictures, on Doom's 320x200
// screen placed in the frame (play::ScreenPlace: a whole scale, centred): the menus
// with their skull, sliders and save slots (m_menu.c's M_Drawer), the questions in
// Doom's font, the title loop's pages (D_PageDrawer), the pause sign. A pure
// function of the menu's state and the art.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/front/menu.h"
#include "engine/image/image.h"
#include "engine/play/hud_font.h"
#include "engine/play/screen.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::front {

class MenuArt {
 public:
  // Keeps a reference to `wads`, whose pictures are decoded when first drawn.
  explicit MenuArt(const wad::Stack& wads);

  // Whether the WADs have Doom's menus (M_DOOM and the font).
  bool complete() const;
  // Doom's M_Drawer: the open menu, or the question on screen (drawn alone).
  void draw(const Menu& menu, image::Image& frame, const std::vector<uint32_t>& palette) const;
  // A 320x200 picture filling Doom's screen (TITLEPIC, CREDIT, HELP...); false if
  // the WADs lack it.
  bool draw_page(const std::string& lump, image::Image& frame, const std::vector<uint32_t>& palette) const;
  // M_PAUSE, centred across the view window (x, width) and 4 rows below its top,
  // in Doom's screen coordinates.
  void draw_pause(int view_x, int view_width, int view_y, image::Image& frame,
                  const std::vector<uint32_t>& palette) const;
  // Doom's M_WriteText: lines 12 rows apart (the finale's 11), stopping at the screen's
  // right edge.
  void write_text(int x, int y, const std::string& text, image::Image& frame, const std::vector<uint32_t>& palette,
                  const play::ScreenPlace& at, int line_height = 12) const;
  // Column `column` of a picture at Doom's screen column x, its posts from the top row
  // (Doom's F_DrawPatchCol: no offsets).
  void draw_column(const wad::IndexedImage& pic, int column, int x, image::Image& frame,
                   const std::vector<uint32_t>& palette, const play::ScreenPlace& at) const;
  // Doom's M_StringWidth, for the menu's typed descriptions.
  int text_width(const std::string& text) const { return font_ ? font_->width(text) : int(text.size()) * 8; }

  // A picture by its lump name (decoded once), or nullptr when missing or broken.
  const wad::IndexedImage* picture(const std::string& name) const;

 private:
  void draw_menu(const Menu& menu, image::Image& frame, const std::vector<uint32_t>& palette,
                 const play::ScreenPlace& at) const;
  void draw_message(const std::string& message, image::Image& frame, const std::vector<uint32_t>& palette,
                    const play::ScreenPlace& at) const;
  void put(const std::string& name, int x, int y, image::Image& frame, const std::vector<uint32_t>& palette,
           const play::ScreenPlace& at) const;
  void thermometer(int x, int y, int width, int dot, image::Image& frame, const std::vector<uint32_t>& palette,
                   const play::ScreenPlace& at) const;
  void save_load_border(int x, int y, image::Image& frame, const std::vector<uint32_t>& palette,
                        const play::ScreenPlace& at) const;

  const wad::Stack& wads_;
  std::optional<play::HudFont> font_;
  mutable std::map<std::string, std::optional<wad::IndexedImage>> pictures_;
};

}  // namespace p3d::front
