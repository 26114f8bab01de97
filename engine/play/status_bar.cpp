#include "engine/play/status_bar.h"

#include <algorithm>
#include <cstdio>

namespace p3d::play {

namespace {

constexpr int kBarTop = kScreenHeight - kStatusBarHeight;
constexpr int kPainFaces = 5, kStraightFaces = 3, kFaceStride = 8, kStraightFaceTics = 35 / 2;

// Doom's places on its 320x200 screen (st_stuff.c).
constexpr int kAmmoX = 44, kAmmoY = 171, kHealthX = 90, kHealthY = 171, kArmorX = 221, kArmorY = 171;
constexpr int kArmsX = 111, kArmsY = 172, kArmsBackgroundX = 104, kArmsSpaceX = 12, kArmsSpaceY = 10;
constexpr int kFaceX = 143, kFaceY = 168, kKeyX = 239;
constexpr int kKeyY[3] = {171, 181, 191};
constexpr int kAmmoCountX = 288, kMaxAmmoX = 314;
constexpr int kAmmoCountY[4] = {173, 179, 191, 185};

std::optional<wad::IndexedImage> picture(const wad::Stack& wads, const std::string& name) {
  const wad::Lump* lump = wads.find(name);
  if (!lump) return std::nullopt;
  try {
    return wad::decode_picture(lump->bytes, name);
  } catch (const std::exception&) {
    return std::nullopt;  // a broken piece is left out, as a missing one
  }
}

}  // namespace

void Face::tic(Random& random, int health) {
  if (health <= 0) {  // Doom's dead face, after the 40 of pain and the god's
    random.other();
    index_ = kPainFaces * kFaceStride + 1;
    return;
  }
  const int shown = std::clamp(health, 0, 100);
  const int pain = kFaceStride * (((100 - shown) * kPainFaces) / 101);
  const int glance = random.other();  // Doom draws it every tic, whether used or not
  if (count_ == 0) {
    index_ = pain + glance % kStraightFaces;
    count_ = kStraightFaceTics;
  }
  --count_;
}

std::optional<StatusBarArt> StatusBarArt::load(const wad::Stack& wads) {
  StatusBarArt a;
  a.bar_ = picture(wads, "STBAR");
  if (!a.bar_) return std::nullopt;
  a.percent_ = picture(wads, "STTPRCNT");
  a.minus_ = picture(wads, "STTMINUS");
  a.arms_background_ = picture(wads, "STARMS");
  for (int i = 0; i < 10; ++i) {
    a.tall_[size_t(i)] = picture(wads, "STTNUM" + std::to_string(i));
    a.small_[size_t(i)] = picture(wads, "STYSNUM" + std::to_string(i));
    a.grey_[size_t(i)] = picture(wads, "STGNUM" + std::to_string(i));
  }
  for (int i = 0; i < 6; ++i) a.keys_[size_t(i)] = picture(wads, "STKEYS" + std::to_string(i));
  for (int pain = 0; pain < kPainFaces; ++pain) {
    for (int j = 0; j < kStraightFaces; ++j)
      a.faces_.push_back(picture(wads, "STFST" + std::to_string(pain) + std::to_string(j)));
    for (const char* other : {"STFTR", "STFTL"}) a.faces_.push_back(picture(wads, other + std::to_string(pain) + "0"));
    for (const char* other : {"STFOUCH", "STFEVL", "STFKILL"}) a.faces_.push_back(picture(wads, other + std::to_string(pain)));
  }
  a.faces_.push_back(picture(wads, "STFGOD0"));
  a.faces_.push_back(picture(wads, "STFDEAD0"));
  return a;
}

int StatusBarArt::height_in(int frame_width, int frame_height) {
  return kStatusBarHeight * ScreenPlace::scale_for(frame_width, frame_height);
}

void StatusBarArt::draw(const StatusValues& v, image::Image& frame, const std::vector<uint32_t>& palette) const {
  const ScreenPlace at = ScreenPlace::in(frame, kStatusBarHeight);  // the bar's rows at the frame's bottom
  auto put = [&](const std::optional<wad::IndexedImage>& pic, int x, int y) {
    if (pic) draw_picture(frame, *pic, x, y, at, palette);
  };
  // Doom's numbers: right-aligned ending at x, at most `digits` of them, 0 drawn as 0.
  auto number = [&](const std::array<std::optional<wad::IndexedImage>, 10>& font, int n, int x, int y, int digits) {
    if (n == kNoAmmoShown || !font[0]) return;
    const int w = font[0]->width;
    const bool negative = n < 0;
    if (negative) n = std::max(n, digits == 2 ? -9 : -99), n = -n;
    if (n == 0) put(font[0], x - w, y);
    for (; n && digits--; n /= 10) put(font[size_t(n % 10)], x -= w, y);
    if (negative) put(minus_, x - 8, y);
  };
  put(bar_, 0, kBarTop);
  put(arms_background_, kArmsBackgroundX, kBarTop);
  number(tall_, v.ready_ammo, kAmmoX, kAmmoY, 3);
  number(tall_, v.health, kHealthX, kHealthY, 3);
  put(percent_, kHealthX, kHealthY);
  number(tall_, v.armor, kArmorX, kArmorY, 3);
  put(percent_, kArmorX, kArmorY);
  for (int i = 0; i < 6; ++i)  // the arms: yellow when owned, grey when not
    put(v.arms[size_t(i)] ? small_[size_t(i + 2)] : grey_[size_t(i + 2)], kArmsX + (i % 3) * kArmsSpaceX,
        kArmsY + (i / 3) * kArmsSpaceY);
  if (v.face >= 0 && size_t(v.face) < faces_.size()) put(faces_[size_t(v.face)], kFaceX, kFaceY);
  for (int i = 0; i < 3; ++i) {  // a skull shows over its card
    const int key = (v.keys >> (i + 3)) & 1 ? i + 3 : (v.keys >> i) & 1 ? i : -1;
    if (key >= 0) put(keys_[size_t(key)], kKeyX, kKeyY[i]);
  }
  for (int i = 0; i < 4; ++i) {
    number(small_, v.ammo[size_t(i)], kAmmoCountX, kAmmoCountY[i], 3);
    number(small_, v.max_ammo[size_t(i)], kMaxAmmoX, kAmmoCountY[i], 3);
  }
}

}  // namespace p3d::play
