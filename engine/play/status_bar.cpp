#include "engine/play/status_bar.h"

#include <algorithm>
#include <cstdio>

#include "engine/play/angle.h"
#include "engine/play/inventory.h"
#include "engine/play/world.h"

namespace p3d::play {

namespace {

constexpr int kBarTop = kScreenHeight - kStatusBarHeight;
// Doom's faces (st_stuff.c): per pain, 3 straight, turned right and left, ouch, the
// evil grin and the rampage; then the god's and the dead face. Times in tics.
constexpr int kPainFaces = 5, kStraightFaces = 3, kFaceStride = 8;
constexpr int kTurnOffset = kStraightFaces, kOuchOffset = kTurnOffset + 2, kEvilGrinOffset = kOuchOffset + 1,
              kRampageOffset = kEvilGrinOffset + 1;
constexpr int kGodFace = kPainFaces * kFaceStride, kDeadFace = kGodFace + 1;
constexpr int kStraightFaceTics = 35 / 2, kTurnTics = 35, kEvilGrinTics = 2 * 35, kRampageDelay = 2 * 35;
constexpr int kMuchPain = 20;
static_assert(kFaceWeapons == int(Weapon::kCount));

// The face toward the attacker: head-on (the rampage face) within 45 degrees either
// way, else turned right or left, by Doom's comparisons of unsigned angles.
int attacker_offset(Angle to_attacker, Angle facing) {
  Angle off;
  bool right;
  if (to_attacker > facing) {
    off = to_attacker - facing;
    right = off > kAngle180;
  } else {
    off = facing - to_attacker;
    right = off <= kAngle180;
  }
  if (off < kAngle45) return kRampageOffset;
  return right ? kTurnOffset : kTurnOffset + 1;
}

// Doom's places on its 320x200 screen (st_stuff.c).
constexpr int kAmmoX = 44, kAmmoY = 171, kHealthX = 90, kHealthY = 171, kArmorX = 221, kArmorY = 171;
constexpr int kFragsX = 138, kFragsY = 171, kFaceBackX = 143;  // Doom's ST_FRAGSX, ST_FRAGSY, ST_FX
constexpr int kArmsX = 111, kArmsY = 172, kArmsBackgroundX = 104, kArmsSpaceX = 12, kArmsSpaceY = 10;
constexpr int kFaceX = 143, kFaceY = 168, kKeyX = 239;
constexpr int kKeyY[3] = {171, 181, 191};
constexpr int kAmmoCountX = 288, kMaxAmmoX = 314;
constexpr int kAmmoCountY[4] = {173, 179, 191, 185};

}  // namespace

FaceInput face_input(const Player& player) {
  FaceInput in;
  const Inventory& inv = player.inv;
  in.health = inv.health;
  in.bonus_count = inv.bonus_count;
  in.damage_count = inv.damage_count;
  const Mobj* mo = player.mo;
  in.attacked = mo && player.attacker && player.attacker != mo;
  if (in.attacked) {
    in.angle_to_attacker = point_to_angle(mo->x, mo->y, player.attacker->x, player.attacker->y);
    in.angle = mo->angle;
  }
  in.attack_down = player.attack_down;
  std::copy(inv.weapons.begin(), inv.weapons.end(), in.weapons.begin());
  in.god_mode = (player.cheats & kCheatGodMode) != 0;
  in.invulnerability = inv.powers[size_t(Power::kInvulnerability)];
  return in;
}

void Face::start_level(const FaceInput& in) {
  index_ = 0;
  old_health_ = -1;
  old_weapons_ = in.weapons;
}

void Face::tic(Random& random, const FaceInput& in) {
  const int random_number = random.other();  // drawn every tic, whether used or not
  update(random_number, in);
  old_health_ = in.health;
}

int Face::pain_offset(int health) const {
  const int shown = std::min(health, 100);
  return kFaceStride * (((100 - shown) * kPainFaces) / 101);
}

void Face::update(int random_number, const FaceInput& in) {
  // A new face takes over when it matters more than the one shown (higher priority).
  // Doom's test is !health; a player's health never falls below 0.
  if (priority_ < 10 && in.health <= 0) {
    priority_ = 9;
    index_ = kDeadFace;
    count_ = 1;
  }
  if (priority_ < 9 && in.bonus_count) {
    bool new_weapon = false;
    for (size_t i = 0; i < old_weapons_.size(); ++i) {
      if (old_weapons_[i] != in.weapons[i]) {
        new_weapon = true;
        old_weapons_[i] = in.weapons[i];
      }
    }
    if (new_weapon) {
      priority_ = 8;
      count_ = kEvilGrinTics;
      index_ = pain_offset(in.health) + kEvilGrinOffset;
    }
  }
  // The health lost this tic, as Doom (inverted: a gain) or as meant decides "much pain".
  const bool much_pain =
      ouch_ == Ouch::kDoom ? in.health - old_health_ > kMuchPain : old_health_ - in.health > kMuchPain;
  if (priority_ < 8 && in.damage_count && in.attacked) {
    priority_ = 7;
    count_ = kTurnTics;
    if (much_pain) {
      index_ = pain_offset(in.health) + kOuchOffset;
    } else {
      index_ = pain_offset(in.health) + attacker_offset(in.angle_to_attacker, in.angle);
    }
  }
  if (priority_ < 7 && in.damage_count) {  // hurt by the world, or by the player's own blast
    count_ = kTurnTics;
    if (much_pain) {
      priority_ = 7;
      index_ = pain_offset(in.health) + kOuchOffset;
    } else {
      priority_ = 6;
      index_ = pain_offset(in.health) + kRampageOffset;
    }
  }
  if (priority_ < 6) {
    if (!in.attack_down) {
      attack_countdown_ = -1;
    } else if (attack_countdown_ == -1) {
      attack_countdown_ = kRampageDelay;
    } else if (!--attack_countdown_) {
      priority_ = 5;
      index_ = pain_offset(in.health) + kRampageOffset;
      count_ = 1;
      attack_countdown_ = 1;  // held on: the rampage face again next tic
    }
  }
  if (priority_ < 5 && (in.god_mode || in.invulnerability)) {
    priority_ = 4;
    index_ = kGodFace;
    count_ = 1;
  }
  if (!count_) {  // the face shown has had its time: a glance
    index_ = pain_offset(in.health) + random_number % kStraightFaces;
    count_ = kStraightFaceTics;
    priority_ = 0;
  }
  --count_;
}

std::optional<StatusBarArt> StatusBarArt::load(const wad::Stack& wads) {
  StatusBarArt a;
  a.bar_ = wad::find_picture(wads, "STBAR");
  if (!a.bar_) return std::nullopt;
  a.percent_ = wad::find_picture(wads, "STTPRCNT");
  a.minus_ = wad::find_picture(wads, "STTMINUS");
  a.arms_background_ = wad::find_picture(wads, "STARMS");
  for (int i = 0; i < 4; ++i) a.face_backgrounds_[size_t(i)] = wad::find_picture(wads, "STFB" + std::to_string(i));
  for (int i = 0; i < 10; ++i) {
    a.tall_[size_t(i)] = wad::find_picture(wads, "STTNUM" + std::to_string(i));
    a.small_[size_t(i)] = wad::find_picture(wads, "STYSNUM" + std::to_string(i));
    a.grey_[size_t(i)] = wad::find_picture(wads, "STGNUM" + std::to_string(i));
  }
  for (int i = 0; i < 6; ++i) a.keys_[size_t(i)] = wad::find_picture(wads, "STKEYS" + std::to_string(i));
  for (int pain = 0; pain < kPainFaces; ++pain) {
    for (int j = 0; j < kStraightFaces; ++j)
      a.faces_.push_back(wad::find_picture(wads, "STFST" + std::to_string(pain) + std::to_string(j)));
    for (const char* other : {"STFTR", "STFTL"}) a.faces_.push_back(wad::find_picture(wads, other + std::to_string(pain) + "0"));
    for (const char* other : {"STFOUCH", "STFEVL", "STFKILL"}) a.faces_.push_back(wad::find_picture(wads, other + std::to_string(pain)));
  }
  a.faces_.push_back(wad::find_picture(wads, "STFGOD0"));
  a.faces_.push_back(wad::find_picture(wads, "STFDEAD0"));
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
  if (v.face_background >= 0 && v.face_background < 4) put(face_backgrounds_[size_t(v.face_background)], kFaceBackX, kBarTop);
  if (!v.deathmatch) put(arms_background_, kArmsBackgroundX, kBarTop);
  number(tall_, v.ready_ammo, kAmmoX, kAmmoY, 3);
  number(tall_, v.health, kHealthX, kHealthY, 3);
  put(percent_, kHealthX, kHealthY);
  number(tall_, v.armor, kArmorX, kArmorY, 3);
  put(percent_, kArmorX, kArmorY);
  if (v.deathmatch) number(tall_, v.frags, kFragsX, kFragsY, 2);  // Doom's st_fragscount
  for (int i = 0; i < 6 && !v.deathmatch; ++i)  // the arms: yellow when owned, grey when not
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
