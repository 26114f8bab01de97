#include "engine/play/hud_font.h"

#include <cctype>
#include <cstdio>

namespace p3d::play {

namespace {
constexpr int kSpaceWidth = 4;  // Doom's HU_TextLine: an unknown character advances 4
}  // namespace

std::optional<HudFont> HudFont::load(const wad::Stack& wads) {
  HudFont font;
  bool any = false;
  for (char c = kFirst; c <= kLast; ++c) {
    char name[9];
    std::snprintf(name, sizeof name, "STCFN%03d", int(c));
    font.glyphs_[size_t(c - kFirst)] = wad::find_picture(wads, name);  // broken or missing: drawn as a space
    any = any || font.glyphs_[size_t(c - kFirst)];
  }
  if (!any) return std::nullopt;
  if (const auto& a = font.glyphs_[size_t('A' - kFirst)]) font.height_ = a->height;
  return font;
}

const wad::IndexedImage* HudFont::glyph(char raw) const {
  const char c = char(std::toupper(static_cast<unsigned char>(raw)));
  if (c < kFirst || c > kLast || !glyphs_[size_t(c - kFirst)]) return nullptr;
  return &*glyphs_[size_t(c - kFirst)];
}

int HudFont::width(const std::string& text) const {
  int w = 0;
  for (char c : text) {
    const wad::IndexedImage* g = glyph(c);
    w += g ? g->width : kSpaceWidth;
  }
  return w;
}

int HudFont::draw(image::Image& frame, const std::string& text, int x, int y, int scale, int left, int top,
                  const std::vector<uint32_t>& palette) const {
  for (char c : text) {
    const wad::IndexedImage* letter = glyph(c);
    if (!letter) {
      x += kSpaceWidth;
      continue;
    }
    const wad::IndexedImage& g = *letter;
    if (x + g.width > kScreenWidth) break;  // Doom stops at the screen's edge
    draw_picture(frame, g, x, y, {scale, left, top}, palette);
    x += g.width;
  }
  return (height_ + 1) * scale;
}

}  // namespace p3d::play
