#include "engine/util/doom.h"

#include <cctype>
#include <cstdio>

namespace p3d::doom {

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

}  // namespace p3d::doom
