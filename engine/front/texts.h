// What Doom's menus say: the BEX mnemonics of its texts (play::english_text gives
// Doom's English, which a WAD's DEHACKED may reword), and the quit messages that have
// none but the first (QUITMSG), from Doom's dstrings.c.
#pragma once

#include <array>
#include <string>

namespace p3d::front {

inline constexpr const char* kEmptySlot = "EMPTYSTRING";
inline constexpr const char* kSharewareOnly = "SWSTRING";
inline constexpr const char* kNightmareQuestion = "NIGHTMARE";
inline constexpr const char* kEndGameQuestion = "ENDGAME";
inline constexpr const char* kMessagesOn = "MSGON";
inline constexpr const char* kMessagesOff = "MSGOFF";
inline constexpr const char* kDetailHigh = "DETAILHI";
inline constexpr const char* kDetailLow = "DETAILLO";
inline constexpr const char* kSaveDead = "SAVEDEAD";
inline constexpr const char* kLoadInNetgame = "LOADNET";
inline constexpr const char* kQuickLoadInNetgame = "QLOADNET";
inline constexpr const char* kNewGameInNetgame = "NEWGAME";
inline constexpr const char* kEndNetgame = "NETEND";
inline constexpr const char* kQuickSavePrompt = "QSPROMPT";
inline constexpr const char* kQuickLoadPrompt = "QLPROMPT";
inline constexpr const char* kQuickSaveSpot = "QSAVESPOT";
inline constexpr const char* kGameSaved = "GGSAVED";
inline constexpr std::array<const char*, 5> kGammaMessages = {"GAMMALVL0", "GAMMALVL1", "GAMMALVL2", "GAMMALVL3",
                                                              "GAMMALVL4"};

// The line under every quit message (no mnemonic: no WAD rewords it).
inline constexpr const char* kQuitDos = "(press y to quit to dos.)";
// Doom's and Doom II's quit messages, picked by gametic; the first of each is QUITMSG.
inline constexpr std::array<const char*, 8> kDoom1QuitMessages = {
    "QUITMSG",
    "please don't leave, there's more\ndemons to toast!",
    "let's beat it -- this is turning\ninto a bloodbath!",
    "i wouldn't leave if i were you.\ndos is much worse.",
    "you're trying to say you like dos\nbetter than me, right?",
    "don't leave yet -- there's a\ndemon around that corner!",
    "ya know, next time you come in here\ni'm gonna toast ya.",
    "go ahead and leave. see if i care.",
};
inline constexpr std::array<const char*, 8> kDoom2QuitMessages = {
    "QUITMSG",
    "you want to quit?\nthen, thou hast lost an eighth!",
    "don't go now, there's a \ndimensional shambler waiting\nat the dos prompt!",
    "get outta here and go back\nto your boring programs.",
    "if i were your boss, i'd \n deathmatch ya in a minute!",
    "look, bud. you leave now\nand you forfeit your body count!",
    "just leave. when you come\nback, i'll be waiting with a bat.",
    "you're lucky i don't smack\nyou for thinking about leaving.",
};

// A prompt with its '%s' replaced by `argument` (Doom's QSPROMPT and QLPROMPT).
inline std::string format_prompt(std::string prompt, const std::string& argument) {
  const size_t at = prompt.find("%s");
  if (at != std::string::npos) prompt.replace(at, 2, argument);
  return prompt;
}

}  // namespace p3d::front
