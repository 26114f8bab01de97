#include "engine/util/doom.h"

#include <cctype>
#include <cstdio>

namespace p3d::doom {

std::span<const AnimatedRange> animated_ranges() {
  static constexpr AnimatedRange kRanges[] = {
      {false, "NUKAGE1", "NUKAGE3", 8},  {false, "FWATER1", "FWATER4", 8},  {false, "SWATER1", "SWATER4", 8},
      {false, "LAVA1", "LAVA4", 8},      {false, "BLOOD1", "BLOOD3", 8},    {false, "RROCK05", "RROCK08", 8},
      {false, "SLIME01", "SLIME04", 8},  {false, "SLIME05", "SLIME08", 8},  {false, "SLIME09", "SLIME12", 8},
      {true, "BLODGR1", "BLODGR4", 8},   {true, "SLADRIP1", "SLADRIP3", 8}, {true, "BLODRIP1", "BLODRIP4", 8},
      {true, "FIREWALA", "FIREWALL", 8}, {true, "GSTFONT1", "GSTFONT3", 8}, {true, "FIRELAV3", "FIRELAVA", 8},
      {true, "FIREMAG1", "FIREMAG3", 8}, {true, "FIREBLU1", "FIREBLU2", 8}, {true, "ROCKRED1", "ROCKRED3", 8},
      {true, "BFALL1", "BFALL4", 8},     {true, "SFALL1", "SFALL4", 8},     {true, "WFALL1", "WFALL4", 8},
      {true, "DBRAIN1", "DBRAIN4", 8},
  };
  return kRanges;
}

namespace {

// "E<e>M<m>" or "MAP<nn>" (case-insensitive): the numbers, or false.
bool parse_episode_map(std::string_view name, int& episode, int& map) {
  auto digit = [&](size_t i) { return i < name.size() && std::isdigit(static_cast<unsigned char>(name[i])); };
  auto upper = [&](size_t i) { return char(std::toupper(static_cast<unsigned char>(name[i]))); };
  if (name.size() == 4 && upper(0) == 'E' && digit(1) && upper(2) == 'M' && digit(3)) {
    episode = name[1] - '0', map = name[3] - '0';
    return true;
  }
  if (name.size() == 5 && upper(0) == 'M' && upper(1) == 'A' && upper(2) == 'P' && digit(3) && digit(4)) {
    episode = 0, map = (name[3] - '0') * 10 + (name[4] - '0');
    return true;
  }
  return false;
}

}  // namespace

std::string next_map(std::string_view current, bool secret, const std::function<bool(const std::string&)>& exists) {
  int episode = 0, map = 0;
  if (!parse_episode_map(current, episode, map)) return {};
  char name[16];
  if (episode > 0) {
    constexpr int kAfterSecret[] = {0, 4, 6, 7, 3};  // per episode: where E?M9 returns
    int next;
    if (map == 8) return {};
    if (map == 9)
      next = episode <= 4 ? kAfterSecret[episode] : 0;
    else
      next = secret ? 9 : map + 1;
    if (next == 0) return {};
    std::snprintf(name, sizeof name, "E%dM%d", episode, next);
  } else {
    int next;
    if (map == 30) return {};
    if (secret && map == 15 && exists("MAP31"))
      next = 31;
    else if (secret && map == 31)
      next = 32;
    else if (map == 31 || map == 32)
      next = 16;
    else
      next = map + 1;
    std::snprintf(name, sizeof name, "MAP%02d", next);
  }
  return exists(name) ? name : std::string();
}

std::string map_name(bool commercial, int episode, int map) {
  char name[24];
  if (commercial)
    std::snprintf(name, sizeof name, "MAP%02d", map);
  else
    std::snprintf(name, sizeof name, "E%dM%d", episode, map);
  return name;
}

}  // namespace p3d::doom
