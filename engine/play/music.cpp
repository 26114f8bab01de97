#include "engine/play/music.h"

#include <array>
#include <cctype>
#include <cstdio>

#include "engine/util/error.h"
#include "engine/wad/mus.h"

namespace p3d::play {

namespace {

// sounds.c's S_music names, by music number.
constexpr std::array<std::string_view, size_t(Music::kCount)> kNames = {
    "",       "e1m1",   "e1m2",   "e1m3",   "e1m4",   "e1m5",   "e1m6",   "e1m7",   "e1m8",   "e1m9",
    "e2m1",   "e2m2",   "e2m3",   "e2m4",   "e2m5",   "e2m6",   "e2m7",   "e2m8",   "e2m9",   "e3m1",
    "e3m2",   "e3m3",   "e3m4",   "e3m5",   "e3m6",   "e3m7",   "e3m8",   "e3m9",   "inter",  "intro",
    "bunny",  "victor", "introa", "runnin", "stalks", "countd", "betwee", "doom",   "the_da", "shawn",
    "ddtblu", "in_cit", "dead",   "stlks2", "theda2", "doom2",  "ddtbl2", "runni2", "dead2",  "stlks3",
    "romero", "shawn2", "messag", "count2", "ddtbl3", "ampie",  "theda3", "adrian", "messg2", "romer2",
    "tense",  "shawn3", "openin", "evil",   "ultima", "read_m", "dm2ttl", "dm2int",
};

// Episode 4's maps play tracks of the first three (S_Start's spmus).
constexpr std::array<Music, 9> kEpisode4 = {Music::kE3M4, Music::kE3M2, Music::kE3M3, Music::kE1M5, Music::kE2M7,
                                            Music::kE2M4, Music::kE2M6, Music::kE2M5, Music::kE1M9};

// Doom's arithmetic on music numbers: kNone where it leaves the table.
Music offset(Music base, int n) {
  const int m = int(base) + n;
  return m > int(Music::kNone) && m < int(Music::kCount) ? Music(m) : Music::kNone;
}

}  // namespace

std::string_view music_name(Music music) { return kNames[size_t(music)]; }

std::string music_lump_name(Music music) {
  std::string name = "D_";
  for (char c : music_name(music)) name += char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

Track map_track(int episode, int map) {
  if (map < 1) return {};
  if (episode == 0) return {offset(Music::kRunnin, map - 1)};
  if (episode < 1) return {};
  if (episode < 4) return {offset(Music::kE1M1, (episode - 1) * 9 + map - 1)};
  if (map > int(kEpisode4.size())) return {};
  return {kEpisode4[size_t(map - 1)]};
}

Track map_track(std::string_view map_name) {
  const std::string name(map_name);
  int episode = 0, map = 0;
  char rest = 0;
  if (std::sscanf(name.c_str(), "MAP%d%c", &map, &rest) == 1) return map_track(0, map);
  if (std::sscanf(name.c_str(), "E%dM%d%c", &episode, &map, &rest) == 2 && episode >= 1) return map_track(episode, map);
  return {};
}

Track title_track(bool commercial) { return {commercial ? Music::kDm2ttl : Music::kIntro, false}; }
Track intermission_track(bool commercial) { return {commercial ? Music::kDm2int : Music::kInter}; }
Track finale_track(bool doom2) { return {doom2 ? Music::kReadM : Music::kVictor}; }
Track bunny_track() { return {Music::kBunny, false}; }
Track cast_track() { return {Music::kEvil}; }

Track cheat_track(char first, char second, bool commercial) {
  if (!std::isdigit(static_cast<unsigned char>(first)) || !std::isdigit(static_cast<unsigned char>(second))) return {};
  const int a = first - '0', b = second - '0';
  if (commercial) {  // MAP number: 00 runs off the table's start onto D_INTROA, as Doom's does
    const int n = a * 10 + b;
    return n > 35 ? Track{} : Track{offset(Music::kRunnin, n - 1)};
  }
  const int n = (a - 1) * 9 + (b - 1);  // Ultimate Doom's: episode and map
  return n > 31 ? Track{} : Track{offset(Music::kE1M1, n)};
}

wad::MidiSong read_song(const wad::Stack& wads, Music music, std::vector<std::string>* warnings) {
  const std::string lump_name = music_lump_name(music);
  for (auto wad = wads.wads().rbegin(); wad != wads.wads().rend(); ++wad)
    if (const wad::Lump* lump = wad->find(lump_name)) {
      const std::string what = wad->name() + ": " + lump_name;
      std::vector<std::string> found;
      const wad::MidiSong song = wad::read_midi(wad::music_to_midi(lump->bytes, what, &found), what);
      if (warnings)
        for (const std::string& w : found) warnings->push_back(what + ": " + w);
      return song;
    }
  throw Error(std::string(wads.empty() ? "no WADs" : wads.wads().back().name()) + ": no music lump " + lump_name);
}

}  // namespace p3d::play
