#include "engine/play/intermission.h"

#include <algorithm>
#include <cstdio>


namespace p3d::play {

namespace {

constexpr int kTitleY = 2, kStatsX = 50, kStatsY = 50, kTimeX = 16, kTimeY = kScreenHeight - 32;
constexpr int kNoNumber = 1994;
// Doom's deathmatch table (wi_stuff.c's DM_*, WI_SPACINGY).
constexpr int kMatrixX = 42, kMatrixY = 68, kSpacingX = 40, kSpacingY = 33, kTotalsX = 269;
constexpr int kKillersX = 10, kKillersY = 100, kVictimsX = 5, kVictimsY = 50;
constexpr int kNetStatsY = 50, kNetSpacingX = 64;  // NG_STATSY, NG_SPACINGX

}  // namespace

int par_seconds(int episode, int map) {
  static constexpr int kDoom[3][9] = {{30, 75, 120, 90, 165, 180, 180, 30, 165},
                                      {90, 90, 90, 120, 90, 360, 240, 30, 170},
                                      {90, 45, 90, 150, 90, 90, 165, 30, 135}};
  static constexpr int kDoom2[32] = {30,  90,  120, 120, 90,  150, 120, 120, 270, 90,  210, 150, 150, 150, 210, 150,
                                     420, 150, 210, 150, 240, 150, 180, 150, 150, 300, 330, 420, 300, 180, 120, 30};
  if (episode == 0) return map >= 1 && map <= 32 ? kDoom2[map - 1] : 0;
  if (episode >= 1 && episode <= 3 && map >= 1 && map <= 9) return kDoom[episode - 1][map - 1];
  if (episode == 4 && map >= 0 && map < 32) return kDoom2[map];  // past Doom's table: Doom II's, one map on
  return 0;
}

namespace {

// A level's name picture: Doom II's CWILVxx, Doom's WILVem (both 0-based).
std::string level_name_lump(int episode, int map) {
  char name[32];
  if (episode == 0)
    std::snprintf(name, sizeof name, "CWILV%02d", map - 1);
  else
    std::snprintf(name, sizeof name, "WILV%d%d", episode - 1, map - 1);
  return name;
}

// Where Doom's episode maps show each level (wi_stuff.c's lnodes), episodes 1 to 3.
constexpr int kLevelSpots[3][9][2] = {
    {{185, 164}, {148, 143}, {69, 122}, {209, 102}, {116, 89}, {166, 55}, {71, 56}, {135, 29}, {71, 24}},
    {{254, 25}, {97, 50}, {188, 64}, {128, 78}, {214, 92}, {133, 130}, {208, 136}, {148, 140}, {235, 158}},
    {{156, 168}, {48, 154}, {174, 95}, {265, 75}, {130, 48}, {279, 23}, {198, 48}, {140, 25}, {281, 136}}};

}  // namespace

std::optional<IntermissionArt> IntermissionArt::load(const wad::Stack& wads, int episode, int map, int next_map) {
  IntermissionArt a;
  a.episode_ = episode;
  if (episode == 0 || episode == 4)
    a.background_ = wad::find_picture(wads, "INTERPIC");
  else
    a.background_ = wad::find_picture(wads, "WIMAP" + std::to_string(episode - 1));
  a.level_name_ = wad::find_picture(wads, level_name_lump(episode, map));
  if (next_map > 0) a.next_name_ = wad::find_picture(wads, level_name_lump(episode, next_map));
  a.entering_ = wad::find_picture(wads, "WIENTER");
  a.splat_ = wad::find_picture(wads, "WISPLAT");
  a.you_are_here_ = {wad::find_picture(wads, "WIURH0"), wad::find_picture(wads, "WIURH1")};
  a.finished_ = wad::find_picture(wads, "WIF");
  a.kills_ = wad::find_picture(wads, "WIOSTK");
  a.items_ = wad::find_picture(wads, "WIOSTI");
  a.secret_ = wad::find_picture(wads, "WISCRT2");
  a.time_ = wad::find_picture(wads, "WITIME");
  a.par_label_ = wad::find_picture(wads, "WIPAR");
  a.percent_ = wad::find_picture(wads, "WIPCNT");
  a.colon_ = wad::find_picture(wads, "WICOLON");
  a.minus_ = wad::find_picture(wads, "WIMINUS");
  a.sucks_ = wad::find_picture(wads, "WISUCKS");
  for (int i = 0; i < 10; ++i) a.digits_.push_back(wad::find_picture(wads, "WINUM" + std::to_string(i)));
  a.killers_ = wad::find_picture(wads, "WIKILRS");
  a.victims_ = wad::find_picture(wads, "WIVCTMS");
  a.total_ = wad::find_picture(wads, "WIMSTT");
  a.star_ = wad::find_picture(wads, "STFST01");
  a.dead_star_ = wad::find_picture(wads, "STFDEAD0");
  a.netgame_secret_ = wad::find_picture(wads, "WIOSTS");
  a.netgame_frags_ = wad::find_picture(wads, "WIFRGS");
  for (int i = 0; i < 4; ++i) a.player_faces_[size_t(i)] = wad::find_picture(wads, "STPB" + std::to_string(i));
  if (!a.background_ && !a.digits_[0]) return std::nullopt;
  return a;
}

void IntermissionArt::draw(const Tally& t, const TallyShown& shown, image::Image& frame,
                           const std::vector<uint32_t>& palette) const {
  const ScreenPlace at = ScreenPlace::in(frame);
  std::fill(frame.pixels.begin(), frame.pixels.end(), palette[0]);
  auto put = [&](const Picture& pic, int x, int y) {
    if (pic) draw_picture(frame, *pic, x, y, at, palette);
  };
  auto centred = [&](const Picture& pic, int y) {
    if (pic) put(pic, (kScreenWidth - pic->width) / 2, y);
  };
  const int digit_width = digits_[0] ? digits_[0]->width : 11;
  // Doom's WI_drawNum: right-aligned ending at x, `digits` of them (-1: as many as needed).
  auto number = [&](int x, int y, int n, int digits) {
    if (n == kNoNumber) return x;
    const bool negative = n < 0;
    if (negative) n = -n;
    if (digits < 0) {
      digits = n == 0 ? 1 : 0;
      for (int m = n; m; m /= 10) ++digits;
    }
    while (digits--) {
      x -= digit_width;
      put(digits_[size_t(n % 10)], x, y);
      n /= 10;
    }
    if (negative) put(minus_, x -= 8, y);
    return x;
  };
  auto percentage = [&](int x, int y, int p) {
    if (p < 0) return;
    put(percent_, x, y);
    number(x, y, p, -1);
  };
  auto time = [&](int x, int y, int seconds) {  // Doom's WI_drawTime: minutes and seconds, hours if need be
    if (seconds < 0) return;
    if (seconds > 61 * 59) {
      if (sucks_) put(sucks_, x - sucks_->width, y);
      return;
    }
    for (int div = 1;;) {
      x = number(x, y, (seconds / div) % 60, 2) - (colon_ ? colon_->width : 0);
      div *= 60;
      if (div == 60 || seconds / div) put(colon_, x, y);
      if (!(seconds / div)) break;
    }
  };
  put(background_, 0, 0);
  if (shown.next_location) {  // WI_drawShowNextLoc
    // Doom's episode map (not Doom II's, nor the fourth episode's): a splat on each
    // level taken, the secret level's if it was done, the pointer on the next.
    if (episode_ >= 1 && episode_ <= 3) {
      const auto& spots = kLevelSpots[episode_ - 1];
      // WI_drawOnLnode: the first of the pictures that fits the screen there.
      auto on_level = [&](int index, const Picture* pics, int count) {
        if (index < 0 || index > 8) return;
        const int x = spots[index][0], y = spots[index][1];
        for (int i = 0; i < count; ++i) {
          const Picture& p = pics[i];
          if (!p) continue;
          const int left = x - p->left_offset, top = y - p->top_offset;
          if (left >= 0 && left + p->width < kScreenWidth && top >= 0 && top + p->height < kScreenHeight) {
            put(p, x, y);
            return;
          }
        }
      };
      const int last = t.map == 9 ? t.next_map - 2 : t.map - 1;  // from the secret level: those before the next
      for (int i = 0; i <= last; ++i) on_level(i, &splat_, 1);
      if (t.did_secret) on_level(8, &splat_, 1);
      if (shown.pointer_on) on_level(t.next_map - 1, you_are_here_.data(), 2);
    }
    if (episode_ != 0 || t.next_map != 31) {  // WI_drawEL, not before Doom II's MAP31
      centred(entering_, kTitleY);
      if (next_name_) centred(next_name_, kTitleY + 5 * next_name_->height / 4);
    }
    return;
  }
  int y = kTitleY;  // WI_drawLF
  if (level_name_) {
    centred(level_name_, y);
    y += 5 * level_name_->height / 4;
  }
  centred(finished_, y);
  if (t.deathmatch) {  // WI_drawDeathmatchStats: killers down, victims across, totals on the right
    auto half = [](const Picture& pic) { return pic ? pic->width / 2 : 0; };
    put(total_, kTotalsX - half(total_), kMatrixY - kSpacingY + 10);
    put(killers_, kKillersX, kKillersY);
    put(victims_, kVictimsX, kVictimsY);
    for (int i = 0, x = kMatrixX + kSpacingX, row = kMatrixY; i < 4; ++i, x += kSpacingX, row += kSpacingY) {
      if (!t.in_game[size_t(i)]) continue;
      const Picture& face = player_faces_[size_t(i)];
      put(face, x - half(face), kMatrixY - kSpacingY);
      put(face, kMatrixX - half(face), row);
      if (i == t.me) {  // the console player's own: a dead face across, a live one down
        put(dead_star_, x - half(face), kMatrixY - kSpacingY);
        put(star_, kMatrixX - half(face), row);
      }
    }
    for (int i = 0, row = kMatrixY + 10; i < 4; ++i, row += kSpacingY) {
      if (!t.in_game[size_t(i)]) continue;
      for (int j = 0, x = kMatrixX + kSpacingX; j < 4; ++j, x += kSpacingX)
        if (t.in_game[size_t(j)]) number(x + digit_width, row, shown.deathmatch_frags[size_t(i)][size_t(j)], 2);
      number(kTotalsX + digit_width, row, shown.deathmatch_totals[size_t(i)], 2);
    }
    return;
  }
  if (t.netgame) {  // WI_drawNetgameStats: a row a player, with its colour and the counts
    const int stats_x = 32 + (star_ ? star_->width / 2 : 0) + (shown.show_frags ? 0 : 32);
    auto right = [&](const Picture& pic, int x) { put(pic, x - (pic ? pic->width : 0), kNetStatsY); };
    right(kills_, stats_x + kNetSpacingX);
    right(items_, stats_x + 2 * kNetSpacingX);
    right(netgame_secret_, stats_x + 3 * kNetSpacingX);
    if (shown.show_frags) right(netgame_frags_, stats_x + 4 * kNetSpacingX);
    const int percent_width = percent_ ? percent_->width : 0;
    for (int i = 0, row = kNetStatsY + (kills_ ? kills_->height : 0); i < 4; ++i) {
      if (!t.in_game[size_t(i)]) continue;
      const Picture& face = player_faces_[size_t(i)];
      const int face_x = stats_x - (face ? face->width : 0);
      put(face, face_x, row);
      if (i == t.me) put(star_, face_x, row);
      int x = stats_x + kNetSpacingX;
      percentage(x - percent_width, row + 10, shown.kills[size_t(i)]);
      percentage((x += kNetSpacingX) - percent_width, row + 10, shown.items[size_t(i)]);
      percentage((x += kNetSpacingX) - percent_width, row + 10, shown.secrets[size_t(i)]);
      if (shown.show_frags) number(x + kNetSpacingX, row + 10, shown.frags[size_t(i)], -1);
      row += kSpacingY;
    }
    return;
  }
  const size_t me = size_t(t.me);
  const int line = digits_[0] ? 3 * digits_[0]->height / 2 : 18;  // WI_drawStats
  put(kills_, kStatsX, kStatsY);
  percentage(kScreenWidth - kStatsX, kStatsY, shown.kills[me]);
  put(items_, kStatsX, kStatsY + line);
  percentage(kScreenWidth - kStatsX, kStatsY + line, shown.items[me]);
  put(secret_, kStatsX, kStatsY + 2 * line);
  percentage(kScreenWidth - kStatsX, kStatsY + 2 * line, shown.secrets[me]);
  put(time_, kTimeX, kTimeY);
  time(kScreenWidth / 2 - kTimeX, kTimeY, shown.seconds);
  if (t.show_par) {
    put(par_label_, kScreenWidth / 2 + kTimeX, kTimeY);
    time(kScreenWidth - kTimeX, kTimeY, shown.par);
  }
}

}  // namespace p3d::play
