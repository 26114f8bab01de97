#include "engine/play/dehacked.h"

#include <array>
#include <cstdio>
#include <utility>

namespace p3d::play {

namespace {

// Doom's texts by their BEX mnemonic (Doom's d_englsh.h): what the menus ask, the
// finale's story and the flats behind it, then the messages the rules say.
constexpr std::pair<const char*, const char*> kMessages[] = {
    {"QUITMSG", "are you sure you want to\nquit this great game?"},
    {"QSAVESPOT", "you haven't picked a quicksave slot yet!\n\npress a key."},
    {"SAVEDEAD", "you can't save if you aren't playing!\n\npress a key."},
    {"LOADNET", "you can't do load while in a net game!\n\npress a key."},
    {"QLOADNET", "you can't quickload during a netgame!\n\npress a key."},
    {"NEWGAME", "you can't start a new game\nwhile in a network game.\n\npress a key."},
    {"NETEND", "you can't end a netgame!\n\npress a key."},
    {"QSPROMPT", "quicksave over your game named\n\n'%s'?\n\npress y or n."},
    {"QLPROMPT", "do you want to quickload the game named\n\n'%s'?\n\npress y or n."},
    {"NIGHTMARE", "are you sure? this skill level\nisn't even remotely fair.\n\npress y or n."},
    {"SWSTRING", "this is the shareware version of doom.\n\nyou need to order the entire trilogy.\n\npress a key."},
    {"MSGOFF", "Messages OFF"},
    {"MSGON", "Messages ON"},
    {"ENDGAME", "are you sure you want to end the game?\n\npress y or n."},
    {"DETAILHI", "High detail"},
    {"DETAILLO", "Low detail"},
    {"GAMMALVL0", "Gamma correction OFF"},
    {"GAMMALVL1", "Gamma correction level 1"},
    {"GAMMALVL2", "Gamma correction level 2"},
    {"GAMMALVL3", "Gamma correction level 3"},
    {"GAMMALVL4", "Gamma correction level 4"},
    {"EMPTYSTRING", "empty slot"},
    {"GGSAVED", "game saved."},
    // The finale's texts after each episode and Doom II's clusters, and their backgrounds.
    {"E1TEXT",
     "Once you beat the big badasses and\n"
     "clean out the moon base you're supposed\n"
     "to win, aren't you? Aren't you? Where's\n"
     "your fat reward and ticket home? What\n"
     "the hell is this? It's not supposed to\n"
     "end this way!\n"
     "\n"
     "It stinks like rotten meat, but looks\n"
     "like the lost Deimos base.  Looks like\n"
     "you're stuck on The Shores of Hell.\n"
     "The only way out is through.\n"
     "\n"
     "To continue the DOOM experience, play\n"
     "The Shores of Hell and its amazing\n"
     "sequel, Inferno!\n"},
    {"E2TEXT",
     "You've done it! The hideous cyber-\n"
     "demon lord that ruled the lost Deimos\n"
     "moon base has been slain and you\n"
     "are triumphant! But ... where are\n"
     "you? You clamber to the edge of the\n"
     "moon and look down to see the awful\n"
     "truth.\n"
     "\n"
     "Deimos floats above Hell itself!\n"
     "You've never heard of anyone escaping\n"
     "from Hell, but you'll make the bastards\n"
     "sorry they ever heard of you! Quickly,\n"
     "you rappel down to  the surface of\n"
     "Hell.\n"
     "\n"
     "Now, it's on to the final chapter of\n"
     "DOOM! -- Inferno."},
    {"E3TEXT",
     "The loathsome spiderdemon that\n"
     "masterminded the invasion of the moon\n"
     "bases and caused so much death has had\n"
     "its ass kicked for all time.\n"
     "\n"
     "A hidden doorway opens and you enter.\n"
     "You've proven too tough for Hell to\n"
     "contain, and now Hell at last plays\n"
     "fair -- for you emerge from the door\n"
     "to see the green fields of Earth!\n"
     "Home at last.\n"
     "\n"
     "You wonder what's been happening on\n"
     "Earth while you were battling evil\n"
     "unleashed. It's good that no Hell-\n"
     "spawn could have come through that\n"
     "door with you ..."},
    {"E4TEXT",
     "the spider mastermind must have sent forth\n"
     "its legions of hellspawn before your\n"
     "final confrontation with that terrible\n"
     "beast from hell.  but you stepped forward\n"
     "and brought forth eternal damnation and\n"
     "suffering upon the horde as a true hero\n"
     "would in the face of something so evil.\n"
     "\n"
     "besides, someone was gonna pay for what\n"
     "happened to daisy, your pet rabbit.\n"
     "\n"
     "but now, you see spread before you more\n"
     "potential pain and gibbitude as a nation\n"
     "of demons run amok among our cities.\n"
     "\n"
     "next stop, hell on earth!"},
    {"C1TEXT",
     "YOU HAVE ENTERED DEEPLY INTO THE INFESTED\n"
     "STARPORT. BUT SOMETHING IS WRONG. THE\n"
     "MONSTERS HAVE BROUGHT THEIR OWN REALITY\n"
     "WITH THEM, AND THE STARPORT'S TECHNOLOGY\n"
     "IS BEING SUBVERTED BY THEIR PRESENCE.\n"
     "\n"
     "AHEAD, YOU SEE AN OUTPOST OF HELL, A\n"
     "FORTIFIED ZONE. IF YOU CAN GET PAST IT,\n"
     "YOU CAN PENETRATE INTO THE HAUNTED HEART\n"
     "OF THE STARBASE AND FIND THE CONTROLLING\n"
     "SWITCH WHICH HOLDS EARTH'S POPULATION\n"
     "HOSTAGE."},
    {"C2TEXT",
     "YOU HAVE WON! YOUR VICTORY HAS ENABLED\n"
     "HUMANKIND TO EVACUATE EARTH AND ESCAPE\n"
     "THE NIGHTMARE.  NOW YOU ARE THE ONLY\n"
     "HUMAN LEFT ON THE FACE OF THE PLANET.\n"
     "CANNIBAL MUTATIONS, CARNIVOROUS ALIENS,\n"
     "AND EVIL SPIRITS ARE YOUR ONLY NEIGHBORS.\n"
     "YOU SIT BACK AND WAIT FOR DEATH, CONTENT\n"
     "THAT YOU HAVE SAVED YOUR SPECIES.\n"
     "\n"
     "BUT THEN, EARTH CONTROL BEAMS DOWN A\n"
     "MESSAGE FROM SPACE: \"SENSORS HAVE LOCATED\n"
     "THE SOURCE OF THE ALIEN INVASION. IF YOU\n"
     "GO THERE, YOU MAY BE ABLE TO BLOCK THEIR\n"
     "ENTRY.  THE ALIEN BASE IS IN THE HEART OF\n"
     "YOUR OWN HOME CITY, NOT FAR FROM THE\n"
     "STARPORT.\" SLOWLY AND PAINFULLY YOU GET\n"
     "UP AND RETURN TO THE FRAY."},
    {"C3TEXT",
     "YOU ARE AT THE CORRUPT HEART OF THE CITY,\n"
     "SURROUNDED BY THE CORPSES OF YOUR ENEMIES.\n"
     "YOU SEE NO WAY TO DESTROY THE CREATURES'\n"
     "ENTRYWAY ON THIS SIDE, SO YOU CLENCH YOUR\n"
     "TEETH AND PLUNGE THROUGH IT.\n"
     "\n"
     "THERE MUST BE A WAY TO CLOSE IT ON THE\n"
     "OTHER SIDE. WHAT DO YOU CARE IF YOU'VE\n"
     "GOT TO GO THROUGH HELL TO GET TO IT?"},
    {"C4TEXT",
     "THE HORRENDOUS VISAGE OF THE BIGGEST\n"
     "DEMON YOU'VE EVER SEEN CRUMBLES BEFORE\n"
     "YOU, AFTER YOU PUMP YOUR ROCKETS INTO\n"
     "HIS EXPOSED BRAIN. THE MONSTER SHRIVELS\n"
     "UP AND DIES, ITS THRASHING LIMBS\n"
     "DEVASTATING UNTOLD MILES OF HELL'S\n"
     "SURFACE.\n"
     "\n"
     "YOU'VE DONE IT. THE INVASION IS OVER.\n"
     "EARTH IS SAVED. HELL IS A WRECK. YOU\n"
     "WONDER WHERE BAD FOLKS WILL GO WHEN THEY\n"
     "DIE, NOW. WIPING THE SWEAT FROM YOUR\n"
     "FOREHEAD YOU BEGIN THE LONG TREK BACK\n"
     "HOME. REBUILDING EARTH OUGHT TO BE A\n"
     "LOT MORE FUN THAN RUINING IT WAS.\n"},
    {"C5TEXT",
     "CONGRATULATIONS, YOU'VE FOUND THE SECRET\n"
     "LEVEL! LOOKS LIKE IT'S BEEN BUILT BY\n"
     "HUMANS, RATHER THAN DEMONS. YOU WONDER\n"
     "WHO THE INMATES OF THIS CORNER OF HELL\n"
     "WILL BE."},
    {"C6TEXT",
     "CONGRATULATIONS, YOU'VE FOUND THE\n"
     "SUPER SECRET LEVEL!  YOU'D BETTER\n"
     "BLAZE THROUGH THIS ONE!\n"},
    {"BGFLATE1", "FLOOR4_8"},
    {"BGFLATE2", "SFLR6_1"},
    {"BGFLATE3", "MFLR8_4"},
    {"BGFLATE4", "MFLR8_3"},
    {"BGFLAT06", "SLIME16"},
    {"BGFLAT11", "RROCK14"},
    {"BGFLAT20", "RROCK07"},
    {"BGFLAT30", "RROCK17"},
    {"BGFLAT15", "RROCK13"},
    {"BGFLAT31", "RROCK19"},
    {"GOTARMOR", "Picked up the armor."},
    {"GOTMEGA", "Picked up the MegaArmor!"},
    {"GOTHTHBONUS", "Picked up a health bonus."},
    {"GOTARMBONUS", "Picked up an armor bonus."},
    {"GOTSTIM", "Picked up a stimpack."},
    {"GOTMEDINEED", "Picked up a medikit that you REALLY need!"},
    {"GOTMEDIKIT", "Picked up a medikit."},
    {"GOTSUPER", "Supercharge!"},
    {"GOTBLUECARD", "Picked up a blue keycard."},
    {"GOTYELWCARD", "Picked up a yellow keycard."},
    {"GOTREDCARD", "Picked up a red keycard."},
    {"GOTBLUESKUL", "Picked up a blue skull key."},
    {"GOTYELWSKUL", "Picked up a yellow skull key."},
    {"GOTREDSKULL", "Picked up a red skull key."},
    {"GOTINVUL", "Invulnerability!"},
    {"GOTBERSERK", "Berserk!"},
    {"GOTINVIS", "Partial Invisibility"},
    {"GOTSUIT", "Radiation Shielding Suit"},
    {"GOTMAP", "Computer Area Map"},
    {"GOTVISOR", "Light Amplification Visor"},
    {"GOTMSPHERE", "MegaSphere!"},
    {"GOTCLIP", "Picked up a clip."},
    {"GOTCLIPBOX", "Picked up a box of bullets."},
    {"GOTROCKET", "Picked up a rocket."},
    {"GOTROCKBOX", "Picked up a box of rockets."},
    {"GOTCELL", "Picked up an energy cell."},
    {"GOTCELLBOX", "Picked up an energy cell pack."},
    {"GOTSHELLS", "Picked up 4 shotgun shells."},
    {"GOTSHELLBOX", "Picked up a box of shotgun shells."},
    {"GOTBACKPACK", "Picked up a backpack full of ammo!"},
    {"GOTBFG9000", "You got the BFG9000!  Oh, yes."},
    {"GOTCHAINGUN", "You got the chaingun!"},
    {"HUSTR_PLRGREEN", "Green: "},
    {"HUSTR_PLRINDIGO", "Indigo: "},
    {"HUSTR_PLRBROWN", "Brown: "},
    {"HUSTR_PLRRED", "Red: "},
    {"GOTCHAINSAW", "A chainsaw!  Find some meat!"},
    {"GOTLAUNCHER", "You got the rocket launcher!"},
    {"GOTPLASMA", "You got the plasma gun!"},
    {"GOTSHOTGUN", "You got the shotgun!"},
    {"GOTSHOTGUN2", "You got the super shotgun!"},
    {"PD_BLUEK", "You need a blue key to open this door"},
    {"PD_REDK", "You need a red key to open this door"},
    {"PD_YELLOWK", "You need a yellow key to open this door"},
    {"PD_BLUEO", "You need a blue key to activate this object"},
    {"PD_REDO", "You need a red key to activate this object"},
    {"PD_YELLOWO", "You need a yellow key to activate this object"},
    {"STSTR_NCON", "No Clipping Mode ON"},
    {"STSTR_NCOFF", "No Clipping Mode OFF"},
    {"STSTR_DQDON", "Degreelessness Mode On"},
    {"STSTR_DQDOFF", "Degreelessness Mode Off"},
    {"STSTR_KFAADDED", "Very Happy Ammo Added"},
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// BEX's escapes: \n a new line (the message line shows the first), \\ a backslash.
std::string unescape(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      const char next = s[++i];
      out += next == 'n' ? '\n' : next;
    } else {
      out += s[i];
    }
  }
  return out;
}

}  // namespace

std::string english_text(std::string_view mnemonic) {
  for (const auto& [name, english] : kMessages)
    if (mnemonic == name) return english;
  return std::string(mnemonic);
}

std::map<std::string, std::string> parse_dehacked_texts(std::string_view text) {
  std::map<std::string, std::string> by_mnemonic;
  bool in_strings = false;
  std::string key, value;
  bool continued = false;
  for (size_t pos = 0; pos < text.size();) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    if (continued) {  // a value going on after a trailing backslash
      continued = !line.empty() && line.back() == '\\';
      value += continued ? line.substr(0, line.size() - 1) : line;
      if (!continued) by_mnemonic[key] = unescape(value);
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '[') {
      in_strings = line.substr(0, 9) == "[STRINGS]";
      continue;
    }
    if (!in_strings) continue;
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos) continue;
    key = std::string(trim(line.substr(0, eq)));
    const std::string_view rest = trim(line.substr(eq + 1));
    continued = !rest.empty() && rest.back() == '\\';
    value = std::string(continued ? rest.substr(0, rest.size() - 1) : rest);
    if (!continued) by_mnemonic[key] = unescape(value);
  }
  std::map<std::string, std::string> texts;
  for (const auto& [mnemonic, doom] : kMessages)
    if (const auto it = by_mnemonic.find(mnemonic); it != by_mnemonic.end() && !it->second.empty())
      texts[doom] = it->second;
  return texts;
}

namespace {

// Chocolate Doom loads an IWAD's own DEHACKED (Freedoom's); a PWAD's waits for -dehlump.
std::string_view iwad_dehacked(const wad::Stack& wads) {
  if (wads.empty() || !wads.wads().front().is_iwad()) return {};
  const wad::Lump* lump = wads.wads().front().find("DEHACKED");
  if (!lump) return {};
  return {reinterpret_cast<const char*>(lump->bytes.data()), lump->bytes.size()};
}

}  // namespace

std::map<std::string, std::string> dehacked_texts(const wad::Stack& wads) {
  return parse_dehacked_texts(iwad_dehacked(wads));
}

}  // namespace p3d::play
