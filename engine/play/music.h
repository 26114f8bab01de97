// Which music Doom plays when, as Chocolate Doom chooses it: each map's track (Doom's
// S_Start), the title (D_DoAdvanceDemo), the intermission (WI_Ticker), the finale
// (F_StartFinale, the bunny and the cast), the mus cheat (ST_Responder); the lump of
// each (D_ and its name) and that lump read from the WADs into a song. The game's
// music player (game/music_player.h) plays what these choose.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "engine/wad/midi.h"
#include "engine/wad/wad.h"

namespace p3d::play {

// Doom's music numbers (sounds.h's musicenum_t), in its order.
enum class Music : uint8_t {
  kNone,
  kE1M1, kE1M2, kE1M3, kE1M4, kE1M5, kE1M6, kE1M7, kE1M8, kE1M9,
  kE2M1, kE2M2, kE2M3, kE2M4, kE2M5, kE2M6, kE2M7, kE2M8, kE2M9,
  kE3M1, kE3M2, kE3M3, kE3M4, kE3M5, kE3M6, kE3M7, kE3M8, kE3M9,
  kInter, kIntro, kBunny, kVictor, kIntroa,
  kRunnin, kStalks, kCountd, kBetwee, kDoom, kTheDa, kShawn, kDdtblu, kInCit, kDead,
  kStlks2, kTheda2, kDoom2, kDdtbl2, kRunni2, kDead2, kStlks3, kRomero, kShawn2, kMessag,
  kCount2, kDdtbl3, kAmpie, kTheda3, kAdrian, kMessg2, kRomer2, kTense, kShawn3, kOpenin,
  kEvil, kUltima, kReadM, kDm2ttl, kDm2int,
  kCount
};

// A piece of music and whether it starts again at its end (S_ChangeMusic's looping;
// S_StartMusic plays once).
struct Track {
  Music music = Music::kNone;
  bool looping = true;
  bool operator==(const Track&) const = default;
};

// Doom's short name ("e1m1", "runnin", "read_m").
std::string_view music_name(Music music);
// The lump: "D_" and the name in upper case ("D_E1M1", "D_RUNNIN").
std::string music_lump_name(Music music);

// A map's track (S_Start), looping. `episode` 0 for Doom II's MAPxx (commercial
// games): MAP01 plays D_RUNNIN, ..., MAP32 D_ULTIMA, and MAP33..35 run on into the
// table (D_READ_M, D_DM2TTL, D_DM2INT) as Doom's arithmetic does. Doom's ExMy: the
// episodes' nine tracks each, episode 4 (and later) borrowing earlier ones (spmus:
// E4M1 plays D_E3M4, ...). kNone where Doom's table has no entry (it would quit).
Track map_track(int episode, int map);
// The same for a map's name ("E1M1", "MAP01"); kNone for other names.
Track map_track(std::string_view map_name);
// The title screen's music, played once: D_DM2TTL in commercial games, else D_INTRO
// (D_INTROA is the OPL device's, not played here).
Track title_track(bool commercial);
// The intermission's, looping: D_DM2INT or D_INTER.
Track intermission_track(bool commercial);
// The finale's text screen, looping: D_VICTOR for Doom (the three or four episodes),
// D_READ_M for Doom II and Final Doom.
Track finale_track(bool doom2);
// After episode 3's text: the bunny's page, once (D_BUNNY).
Track bunny_track();
// Doom II's cast of characters, looping (D_EVIL).
Track cast_track();
// The mus cheat (idmus followed by two digits): Doom II's map number 01..35 in
// commercial games, else episode and map (11..39 less than E4M1). kNone for what Doom
// answers "IMPOSSIBLE SELECTION".
Track cheat_track(char first, char second, bool commercial);

// The song of a track from the WADs (the last lump of its name): the lump's MIDI, or its MUS
// converted. Throws Error("<wad>: D_NAME: ...") for a lump missing or broken; warnings
// (engine/wad/mus.h) are added to `warnings`.
wad::MidiSong read_song(const wad::Stack& wads, Music music, std::vector<std::string>* warnings = nullptr);

}  // namespace p3d::play
