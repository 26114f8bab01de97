#include "engine/front/finale.h"

#include <cctype>
#include <cstdio>

#include "engine/play/screen.h"

namespace p3d::front {

namespace {

constexpr int kTextSpeed = 3, kTextWait = 250;  // tics a letter, tics the whole text stays

struct TextScreen {
  bool doom2;
  int episode, map;
  const char* text;  // BEX mnemonics
  const char* flat;
};
constexpr TextScreen kScreens[] = {
    {false, 1, 8, "E1TEXT", "BGFLATE1"}, {false, 2, 8, "E2TEXT", "BGFLATE2"}, {false, 3, 8, "E3TEXT", "BGFLATE3"},
    {false, 4, 8, "E4TEXT", "BGFLATE4"}, {true, 0, 6, "C1TEXT", "BGFLAT06"},  {true, 0, 11, "C2TEXT", "BGFLAT11"},
    {true, 0, 20, "C3TEXT", "BGFLAT20"}, {true, 0, 30, "C4TEXT", "BGFLAT30"}, {true, 0, 15, "C5TEXT", "BGFLAT15"},
    {true, 0, 31, "C6TEXT", "BGFLAT31"},
};

}  // namespace

bool has_finale(GameMode mode, int /*episode*/, int map, bool secret_exit) {
  if (mode != GameMode::kCommercial) return map == 8;
  return map == 6 || map == 11 || map == 20 || map == 30 || ((map == 15 || map == 31) && secret_exit);
}

Finale::Finale(GameMode mode, int episode, int map, const std::function<std::string(const std::string&)>& doom_text)
    : mode_(mode), episode_(episode), map_(map) {
  const bool doom2 = mode == GameMode::kCommercial;
  music_ = play::finale_track(doom2);
  for (const TextScreen& s : kScreens)
    if (s.doom2 == doom2 && (doom2 || s.episode == episode) && s.map == map) {
      text_ = doom_text(s.text);
      flat_ = doom_text(s.flat);
    }
}

Finale::Next Finale::tic(bool pressed) {
  const bool commercial = mode_ == GameMode::kCommercial;
  // Doom II goes on at a button once the text has shown for 50 tics.
  if (commercial && count_ > 50 && pressed) return map_ == 30 ? Next::kEnd : Next::kNextMap;
  ++count_;
  if (commercial) return Next::kStay;
  if (stage_ == Stage::kText && count_ > int(text_.size()) * kTextSpeed + kTextWait) {
    count_ = 0;
    stage_ = Stage::kArt;
    screen_changed_ = true;
    if (episode_ == 3) music_ = play::bunny_track();
  }
  if (stage_ == Stage::kArt && episode_ == 3 && count_ >= 1180) {  // THE END, a letter at a shot
    const int stage = std::min((count_ - 1180) / 5, 6);
    if (stage > last_bunny_stage_) {
      sounds_.push_back(play::Sound::kPistol);
      last_bunny_stage_ = stage;
    }
  }
  return Next::kStay;
}

void Finale::draw(const MenuArt& art, const wad::Stack& wads, image::Image& frame,
                  const std::vector<uint32_t>& palette) const {
  std::fill(frame.pixels.begin(), frame.pixels.end(), palette[0]);
  if (stage_ == Stage::kText) return draw_text(art, wads, frame, palette);
  if (episode_ == 3) return draw_bunny(art, frame, palette);
  const char* page = episode_ == 1 ? (mode_ == GameMode::kRetail ? "CREDIT" : "HELP2")
                     : episode_ == 2 ? "VICTORY2"
                     : episode_ == 4 ? "ENDPIC"
                                     : nullptr;
  if (page) art.draw_page(page, frame, palette);
}

// Doom's F_TextWrite: the flat tiled over the screen, then as many letters as the
// tics allow from (10, 10), lines 11 rows apart.
void Finale::draw_text(const MenuArt& art, const wad::Stack& wads, image::Image& frame,
                       const std::vector<uint32_t>& palette) const {
  const play::ScreenPlace at = play::ScreenPlace::in(frame);
  if (const wad::Lump* flat = wads.find(flat_); flat && flat->bytes.size() >= 64 * 64) {
    for (int y = 0; y < play::kScreenHeight * at.scale; ++y)
      for (int x = 0; x < play::kScreenWidth * at.scale; ++x) {
        const int px = at.left + x, py = at.top + y;
        if (px >= 0 && py >= 0 && px < frame.width && py < frame.height)
          frame.at(px, py) = palette[flat->bytes[size_t((y / at.scale) % 64 * 64 + (x / at.scale) % 64)]];
      }
  }
  const int letters = std::max(0, (count_ - 10) / kTextSpeed);
  art.write_text(10, 10, text_.substr(0, std::min<size_t>(size_t(letters), text_.size())), frame, palette, at, 11);
}

// Doom's F_BunnyScroll: PFUB2 scrolling off to the left as PFUB1 comes in, then THE
// END drawn a letter at a time.
void Finale::draw_bunny(const MenuArt& art, image::Image& frame, const std::vector<uint32_t>& palette) const {
  const play::ScreenPlace at = play::ScreenPlace::in(frame);
  const int scrolled = std::clamp(play::kScreenWidth - (count_ - 230) / 2, 0, play::kScreenWidth);
  const wad::IndexedImage* left = art.picture("PFUB2");
  const wad::IndexedImage* right = art.picture("PFUB1");
  for (int x = 0; x < play::kScreenWidth; ++x) {
    const bool first = x + scrolled < play::kScreenWidth;
    const wad::IndexedImage* pic = first ? left : right;
    if (pic) art.draw_column(*pic, first ? x + scrolled : x + scrolled - play::kScreenWidth, x, frame, palette, at);
  }
  if (count_ < 1130) return;
  char name[8];
  std::snprintf(name, sizeof name, "END%d", count_ < 1180 ? 0 : std::min((count_ - 1180) / 5, 6));
  if (const wad::IndexedImage* end = art.picture(name))
    play::draw_picture(frame, *end, (play::kScreenWidth - 13 * 8) / 2, (play::kScreenHeight - 8 * 8) / 2, at, palette);
}

}  // namespace p3d::front
