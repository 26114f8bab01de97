// Doom's text as a WAD's DEHACKED lump rewords it: the BEX [STRINGS] section's
// mnemonics (GOTCHAINGUN = You got the minigun!), which Freedoom's IWADs carry and
// Chocolate Doom loads with them.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "engine/wad/wad.h"

namespace p3d::play {

// The WAD's wording of each of Doom's messages it rewords, keyed by Doom's own English
// text (as the rules say it). Empty when the WADs have no DEHACKED lump; lines that do
// not parse are left out, as Chocolate Doom skips them.
std::map<std::string, std::string> dehacked_texts(const wad::Stack& wads);
// The same from a DEHACKED lump's text.
std::map<std::string, std::string> parse_dehacked_texts(std::string_view text);

// Doom's own English for a BEX mnemonic ("NIGHTMARE", "GOTARMOR"...), the key of
// dehacked_texts' map; the mnemonic itself if Doom has no such text.
std::string english_text(std::string_view mnemonic);

}  // namespace p3d::play
