#include "engine/front/menu_art.h"

#include <sstream>

namespace p3d::front {

namespace {

constexpr int kSkullOffset = -32;  // Doom's SKULLXOFF

}  // namespace

MenuArt::MenuArt(const wad::Stack& wads) : wads_(wads), font_(play::HudFont::load(wads)) {}

bool MenuArt::complete() const { return font_ && picture("M_DOOM") && picture("M_SKULL1"); }

const wad::IndexedImage* MenuArt::picture(const std::string& name) const {
  auto [it, fresh] = pictures_.try_emplace(name);
  if (fresh) it->second = wad::find_picture(wads_, name);  // a broken picture is left out, as a missing one
  return it->second ? &*it->second : nullptr;
}

void MenuArt::put(const std::string& name, int x, int y, image::Image& frame, const std::vector<uint32_t>& palette,
                  const play::ScreenPlace& at) const {
  if (const wad::IndexedImage* pic = picture(name)) play::draw_picture(frame, *pic, x, y, at, palette);
}

void MenuArt::write_text(int x, int y, const std::string& text, image::Image& frame,
                         const std::vector<uint32_t>& palette, const play::ScreenPlace& at, int line_height) const {
  if (!font_) return;
  int cx = x, cy = y;
  for (char c : text) {
    if (c == '\n') {
      cx = x;
      cy += line_height;
      continue;
    }
    const wad::IndexedImage* glyph = font_->glyph(c);
    if (!glyph) {
      cx += 4;
      continue;
    }
    if (cx + glyph->width > play::kScreenWidth) break;  // Doom stops writing at the edge
    play::draw_picture(frame, *glyph, cx, cy, at, palette);
    cx += glyph->width;
  }
}

void MenuArt::draw_column(const wad::IndexedImage& pic, int column, int x, image::Image& frame,
                          const std::vector<uint32_t>& palette, const play::ScreenPlace& at) const {
  if (column < 0 || column >= pic.width) return;
  const int s = at.scale;
  for (int r = 0; r < pic.height; ++r) {
    if (!pic.opaque[pic.at(column, r)]) continue;
    const uint32_t colour = palette[pic.indices[pic.at(column, r)]];
    for (int dy = 0; dy < s; ++dy)
      for (int dx = 0; dx < s; ++dx) {
        const int px = at.left + x * s + dx, py = at.top + r * s + dy;
        if (px >= 0 && py >= 0 && px < frame.width && py < frame.height) frame.at(px, py) = colour;
      }
  }
}

void MenuArt::draw(const Menu& menu, image::Image& frame, const std::vector<uint32_t>& palette) const {
  const play::ScreenPlace at = play::ScreenPlace::in(frame);
  if (menu.message()) {
    draw_message(*menu.message(), frame, palette, at);
    return;
  }
  if (menu.active()) draw_menu(menu, frame, palette, at);
}

// Each line centred across the screen, the whole centred down it.
void MenuArt::draw_message(const std::string& message, image::Image& frame, const std::vector<uint32_t>& palette,
                           const play::ScreenPlace& at) const {
  if (!font_) return;
  const int line_height = font_->first_height();
  std::vector<std::string> lines;
  std::istringstream in(message);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  if (!message.empty() && message.back() == '\n') lines.emplace_back();
  int y = play::kScreenHeight / 2 - line_height * int(lines.size()) / 2;
  for (const std::string& line : lines) {
    write_text(play::kScreenWidth / 2 - font_->width(line) / 2, y, line, frame, palette, at);
    y += line_height;
  }
}

void MenuArt::thermometer(int x, int y, int width, int dot, image::Image& frame, const std::vector<uint32_t>& palette,
                          const play::ScreenPlace& at) const {
  put("M_THERML", x, y, frame, palette, at);
  int xx = x + 8;
  for (int i = 0; i < width; ++i, xx += 8) put("M_THERMM", xx, y, frame, palette, at);
  put("M_THERMR", xx, y, frame, palette, at);
  put("M_THERMO", x + 8 + dot * 8, y, frame, palette, at);
}

void MenuArt::save_load_border(int x, int y, image::Image& frame, const std::vector<uint32_t>& palette,
                               const play::ScreenPlace& at) const {
  put("M_LSLEFT", x - 8, y + 7, frame, palette, at);
  for (int i = 0; i < kSaveStringSize; ++i, x += 8) put("M_LSCNTR", x, y + 7, frame, palette, at);
  put("M_LSRGHT", x, y + 7, frame, palette, at);
}

// Each page's own drawing (Doom's menu routines), then its items and the skull.
void MenuArt::draw_menu(const Menu& menu, image::Image& frame, const std::vector<uint32_t>& palette,
                        const play::ScreenPlace& at) const {
  const Menu::Screen s = menu.screen();
  const MenuSettings& settings = menu.settings();
  using Page = Menu::Page;
  switch (s.page) {
    case Page::kMain: put("M_DOOM", 94, 2, frame, palette, at); break;
    case Page::kEpisode: put("M_EPISOD", 54, 38, frame, palette, at); break;
    case Page::kNewGame:
      put("M_NEWG", 96, 14, frame, palette, at);
      put("M_SKILL", 54, 38, frame, palette, at);
      break;
    case Page::kOptions:
      put("M_OPTTTL", 108, 15, frame, palette, at);
      put(settings.low_detail ? "M_GDLOW" : "M_GDHIGH", s.x + 175, s.y + kMenuLineHeight * 2, frame, palette, at);
      put(settings.show_messages ? "M_MSGON" : "M_MSGOFF", s.x + 120, s.y + kMenuLineHeight * 1, frame, palette, at);
      thermometer(s.x, s.y + kMenuLineHeight * 6, 10, settings.mouse_sensitivity, frame, palette, at);
      thermometer(s.x, s.y + kMenuLineHeight * 4, 9, menu.screen_size_slider(), frame, palette, at);
      break;
    case Page::kReadThis1:  // Doom II's one help page, or Doom's first
      put(menu.mode() == GameMode::kCommercial ? "HELP" : "HELP2", 0, 0, frame, palette, at);
      break;
    case Page::kReadThis2: put("HELP1", 0, 0, frame, palette, at); break;
    case Page::kSound:
      put("M_SVOL", 60, 38, frame, palette, at);
      thermometer(s.x, s.y + kMenuLineHeight * 1, 16, settings.sfx_volume, frame, palette, at);
      thermometer(s.x, s.y + kMenuLineHeight * 3, 16, settings.music_volume, frame, palette, at);
      break;
    case Page::kLoad:
    case Page::kSave:
      put(s.page == Page::kLoad ? "M_LOADG" : "M_SAVEG", 72, 28, frame, palette, at);
      for (int i = 0; i < kSaveSlots; ++i) {
        save_load_border(s.x, s.y + kMenuLineHeight * i, frame, palette, at);
        write_text(s.x, s.y + kMenuLineHeight * i, menu.slot_texts()[size_t(i)], frame, palette, at);
      }
      if (s.page == Page::kSave && menu.entering_save_name()) {
        const int slot = menu.save_slot();
        write_text(s.x + text_width(menu.slot_texts()[size_t(slot)]), s.y + kMenuLineHeight * slot, "_", frame, palette, at);
      }
      break;
  }
  int y = s.y;
  for (const Menu::Item& item : s.items) {
    if (!item.picture.empty()) put(item.picture, s.x, y, frame, palette, at);
    y += kMenuLineHeight;
  }
  put(s.skull ? "M_SKULL2" : "M_SKULL1", s.x + kSkullOffset, s.y - 5 + s.item_on * kMenuLineHeight, frame, palette, at);
}

bool MenuArt::draw_page(const std::string& lump, image::Image& frame, const std::vector<uint32_t>& palette) const {
  const wad::IndexedImage* pic = picture(lump);
  if (!pic) return false;
  play::draw_picture(frame, *pic, 0, 0, play::ScreenPlace::in(frame), palette);
  return true;
}

void MenuArt::draw_pause(int view_x, int view_width, int view_y, image::Image& frame,
                         const std::vector<uint32_t>& palette) const {
  put("M_PAUSE", view_x + (view_width - 68) / 2, view_y + 4, frame, palette, play::ScreenPlace::in(frame));
}

}  // namespace p3d::front
