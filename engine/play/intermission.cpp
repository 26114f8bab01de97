#include "engine/play/intermission.h"

#include <algorithm>
#include <cstdio>

#include "engine/play/dehacked.h"

namespace p3d::play {

namespace {

constexpr int kTitleY = 2, kStatsX = 50, kStatsY = 50, kTimeX = 16, kTimeY = kScreenHeight - 32;
constexpr int kNoNumber = 1994;
// Doom's deathmatch table (wi_stuff.c's DM_*, WI_SPACINGY).
constexpr int kMatrixX = 42, kMatrixY = 68, kSpacingX = 40, kSpacingY = 33, kTotalsX = 269;
constexpr int kKillersX = 10, kKillersY = 100, kVictimsX = 5, kVictimsY = 50;
constexpr int kNetStatsY = 50, kNetSpacingX = 64;  // NG_STATSY, NG_SPACINGX

std::optional<wad::IndexedImage> picture(const wad::Stack& wads, const std::string& name) {
  const wad::Lump* lump = wads.find(name);
  if (!lump) return std::nullopt;
  try {
    return wad::decode_picture(lump->bytes, name);
  } catch (const std::exception&) {
    return std::nullopt;  // a broken piece is left out
  }
}

// Doom's counts as percentages, of at least 1 (Doom's WI_initVariables).
int percent(int n, int total) { return n * 100 / std::max(total, 1); }

}  // namespace

int frag_sum(const Tally& t, int player) {
  int sum = 0;
  for (int j = 0; j < 4; ++j)
    if (t.in_game[size_t(j)] && j != player) sum += t.frags[size_t(player)][size_t(j)];
  sum -= t.frags[size_t(player)][size_t(player)];
  return std::clamp(sum, -99, 99);
}

int par_seconds(int episode, int map) {
  static constexpr int kDoom[3][9] = {{30, 75, 120, 90, 165, 180, 180, 30, 165},
                                      {90, 90, 90, 120, 90, 360, 240, 30, 170},
                                      {90, 45, 90, 150, 90, 90, 165, 30, 135}};
  static constexpr int kDoom2[32] = {30,  90,  120, 120, 90,  150, 120, 120, 270, 90,  210, 150, 150, 150, 210, 150,
                                     420, 150, 210, 150, 240, 150, 180, 150, 150, 300, 330, 420, 300, 180, 120, 30};
  if (episode == 0) return map >= 1 && map <= 32 ? kDoom2[map - 1] : -1;
  if (episode >= 1 && episode <= 3 && map >= 1 && map <= 9) return kDoom[episode - 1][map - 1];
  return -1;
}

std::optional<IntermissionArt> IntermissionArt::load(const wad::Stack& wads, int episode, int map) {
  IntermissionArt a;
  char name[32];
  if (episode == 0 || episode == 4)
    a.background_ = picture(wads, "INTERPIC");
  else
    a.background_ = picture(wads, "WIMAP" + std::to_string(episode - 1));
  if (episode == 0)
    std::snprintf(name, sizeof name, "CWILV%02d", map - 1);
  else
    std::snprintf(name, sizeof name, "WILV%d%d", episode - 1, map - 1);
  a.level_name_ = picture(wads, name);
  a.finished_ = picture(wads, "WIF");
  a.kills_ = picture(wads, "WIOSTK");
  a.items_ = picture(wads, "WIOSTI");
  a.secret_ = picture(wads, "WISCRT2");
  a.time_ = picture(wads, "WITIME");
  a.par_label_ = picture(wads, "WIPAR");
  a.percent_ = picture(wads, "WIPCNT");
  a.colon_ = picture(wads, "WICOLON");
  a.minus_ = picture(wads, "WIMINUS");
  a.sucks_ = picture(wads, "WISUCKS");
  for (int i = 0; i < 10; ++i) a.digits_.push_back(picture(wads, "WINUM" + std::to_string(i)));
  a.killers_ = picture(wads, "WIKILRS");
  a.victims_ = picture(wads, "WIVCTMS");
  a.total_ = picture(wads, "WIMSTT");
  a.star_ = picture(wads, "STFST01");
  a.dead_star_ = picture(wads, "STFDEAD0");
  a.netgame_secret_ = picture(wads, "WIOSTS");
  a.netgame_frags_ = picture(wads, "WIFRGS");
  for (int i = 0; i < 4; ++i) a.player_faces_[size_t(i)] = picture(wads, "STPB" + std::to_string(i));
  if (!a.background_ && !a.digits_[0]) return std::nullopt;
  const auto pars = dehacked_pars(wads);  // the IWAD's own, as Chocolate Doom reads Freedoom's
  const auto par = pars.find({episode, map});
  a.par_ = par != pars.end() ? par->second : par_seconds(episode, map);
  return a;
}

void IntermissionArt::draw(const Tally& t, image::Image& frame, const std::vector<uint32_t>& palette) const {
  const ScreenPlace at = ScreenPlace::in(frame);
  std::fill(frame.pixels.begin(), frame.pixels.end(), palette[0]);
  auto put = [&](const Picture& pic, int x, int y) {
    if (pic) draw_picture(frame, *pic, x, y, at, palette);
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
  int y = kTitleY;
  if (level_name_) {
    put(level_name_, (kScreenWidth - level_name_->width) / 2, y);
    y += 5 * level_name_->height / 4;
  }
  if (finished_) put(finished_, (kScreenWidth - finished_->width) / 2, y);
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
        if (t.in_game[size_t(j)]) number(x + digit_width, row, t.frags[size_t(i)][size_t(j)], 2);
      number(kTotalsX + digit_width, row, frag_sum(t, i), 2);
    }
    return;
  }
  if (t.netgame) {  // WI_drawNetgameStats: a row a player, with its colour and the counts
    bool frags = false;  // Doom's dofrags: shown when anyone's total is not 0
    for (int i = 0; i < 4; ++i) frags |= t.in_game[size_t(i)] && frag_sum(t, i) != 0;
    const int stats_x = 32 + (star_ ? star_->width / 2 : 0) + (frags ? 0 : 32);
    auto right = [&](const Picture& pic, int x) { put(pic, x - (pic ? pic->width : 0), kNetStatsY); };
    right(kills_, stats_x + kNetSpacingX);
    right(items_, stats_x + 2 * kNetSpacingX);
    right(netgame_secret_, stats_x + 3 * kNetSpacingX);
    if (frags) right(netgame_frags_, stats_x + 4 * kNetSpacingX);
    const int percent_width = percent_ ? percent_->width : 0;
    for (int i = 0, row = kNetStatsY + (kills_ ? kills_->height : 0); i < 4; ++i) {
      if (!t.in_game[size_t(i)]) continue;
      const Picture& face = player_faces_[size_t(i)];
      const int face_x = stats_x - (face ? face->width : 0);
      put(face, face_x, row);
      if (i == t.me) put(star_, face_x, row);
      int x = stats_x + kNetSpacingX;
      percentage(x - percent_width, row + 10, percent(t.player_kills[size_t(i)], t.total_kills));
      percentage((x += kNetSpacingX) - percent_width, row + 10, percent(t.player_items[size_t(i)], t.total_items));
      percentage((x += kNetSpacingX) - percent_width, row + 10, percent(t.player_secrets[size_t(i)], t.total_secrets));
      if (frags) number(x + kNetSpacingX, row + 10, frag_sum(t, i), -1);
      row += kSpacingY;
    }
    return;
  }
  const int line = digits_[0] ? 3 * digits_[0]->height / 2 : 18;
  put(kills_, kStatsX, kStatsY);
  percentage(kScreenWidth - kStatsX, kStatsY, percent(t.kills, t.total_kills));
  put(items_, kStatsX, kStatsY + line);
  percentage(kScreenWidth - kStatsX, kStatsY + line, percent(t.items, t.total_items));
  put(secret_, kStatsX, kStatsY + 2 * line);
  percentage(kScreenWidth - kStatsX, kStatsY + 2 * line, percent(t.secrets, t.total_secrets));
  put(time_, kTimeX, kTimeY);
  time(kScreenWidth / 2 - kTimeX, kTimeY, t.seconds);
  if (par_ >= 0) {
    put(par_label_, kScreenWidth / 2 + kTimeX, kTimeY);
    time(kScreenWidth - kTimeX, kTimeY, par_);
  }
}

}  // namespace p3d::play
