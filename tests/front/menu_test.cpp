// Doom's menus as a state machine: the items, keys, sounds, questions and requests
// of m_menu.c, checked against what Doom does.
#include "engine/front/menu.h"

#include <gtest/gtest.h>

#include "engine/front/demo_loop.h"
#include "engine/front/gamma.h"
#include "engine/front/keys.h"

namespace p3d::front {
namespace {

using Sound = play::Sound;
using Kind = MenuRequest::Kind;

struct MenuFixture {
  explicit MenuFixture(GameMode mode = GameMode::kCommercial) : menu(mode, settings, [this] { return slots; }) {}
  MenuSettings settings;
  std::array<std::optional<std::string>, kSaveSlots> slots;
  Menu menu;
  MenuContext context;
  bool press(int key) { return menu.key(key, key > ' ' && key < 0x7f ? key : 0, context); }
};

TEST(Menu, EscapeOpensTheMainMenuWithItsSound) {
  MenuFixture f;
  EXPECT_FALSE(f.press('x')) << "a letter with the menu closed is the game's";
  EXPECT_TRUE(f.press(kKeyEscape));
  EXPECT_TRUE(f.menu.active());
  EXPECT_EQ(f.menu.take_sounds(), std::vector<Sound>{Sound::kSwtchn});
  const Menu::Screen s = f.menu.screen();
  EXPECT_EQ(s.page, Menu::Page::kMain);
  ASSERT_EQ(s.items.size(), 5u) << "Doom II: no Read This!";
  EXPECT_EQ(s.items.back().picture, "M_QUITG");
  EXPECT_EQ(s.y, 72) << "Doom II's main menu sits 8 rows lower";
  EXPECT_TRUE(f.press(kKeyEscape));
  EXPECT_FALSE(f.menu.active());
  EXPECT_EQ(f.menu.take_sounds(), std::vector<Sound>{Sound::kSwtchx});
}

TEST(Menu, UpAndDownWrapAndSkipGaps) {
  MenuFixture f;
  f.menu.open();
  f.press(kKeyUp);
  EXPECT_EQ(f.menu.screen().item_on, 4) << "up from the first wraps to Quit";
  f.press(kKeyDown);
  EXPECT_EQ(f.menu.screen().item_on, 0);
  f.press(kKeyDown);
  f.press(kKeyEnter);  // Options
  ASSERT_EQ(f.menu.screen().page, Menu::Page::kOptions);
  for (int i = 0; i < 4; ++i) f.press(kKeyDown);
  EXPECT_EQ(f.menu.screen().item_on, 5) << "End Game, Messages, Detail, Screen Size, (gap), Mouse";
  f.menu.take_sounds();
  f.press(kKeyDown);
  EXPECT_EQ(f.menu.screen().item_on, 7);
  EXPECT_EQ(f.menu.take_sounds(), (std::vector<Sound>{Sound::kPstop, Sound::kPstop})) << "a sound per step, gaps too";
}

TEST(Menu, NewGameOnDoomIIAsksTheSkillThenStarts) {
  MenuFixture f;
  f.menu.open();
  f.press(kKeyEnter);
  EXPECT_EQ(f.menu.screen().page, Menu::Page::kNewGame);
  EXPECT_EQ(f.menu.screen().item_on, 2) << "Hurt Me Plenty first";
  f.press(kKeyEnter);
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Kind::kNewGame);
  EXPECT_EQ(r[0].episode, 1);
  EXPECT_EQ(r[0].skill, 3);
  EXPECT_FALSE(f.menu.active());
}

TEST(Menu, UltimateDoomAsksTheEpisodeOfFour) {
  MenuFixture f(GameMode::kRetail);
  f.menu.open();
  EXPECT_EQ(f.menu.screen().items.size(), 6u) << "Doom keeps Read This!";
  f.press(kKeyEnter);
  ASSERT_EQ(f.menu.screen().page, Menu::Page::kEpisode);
  EXPECT_EQ(f.menu.screen().items.size(), 4u);
  f.press(kKeyUp);  // the fourth episode
  f.press(kKeyEnter);
  f.press(kKeyUp);  // from Hurt Me Plenty up to Hey, Not Too Rough
  f.press(kKeyEnter);
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].episode, 4);
  EXPECT_EQ(r[0].skill, 2);
  MenuFixture registered(GameMode::kRegistered);
  registered.menu.open();
  registered.press(kKeyEnter);
  EXPECT_EQ(registered.menu.screen().items.size(), 3u) << "three episodes before the Ultimate Doom";
}

TEST(Menu, NightmareAsksFirstAndOnlyYesStartsIt) {
  MenuFixture f;
  f.menu.open();
  f.press(kKeyEnter);
  f.press(kKeyDown);
  f.press(kKeyDown);  // Nightmare!
  f.press(kKeyEnter);
  ASSERT_TRUE(f.menu.showing_message());
  EXPECT_NE(f.menu.message()->find("isn't even remotely fair"), std::string::npos);
  EXPECT_TRUE(f.menu.take_requests().empty());
  EXPECT_FALSE(f.press('q')) << "a question takes only y, n, space and escape";
  f.press('n');
  EXPECT_FALSE(f.menu.showing_message());
  EXPECT_FALSE(f.menu.active()) << "Doom closes the menu after any answer";
  EXPECT_TRUE(f.menu.take_requests().empty());
  f.menu.open();
  f.press(kKeyEnter);
  f.press(kKeyEnter);
  f.press('y');
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].skill, 5);
}

TEST(Menu, TheWadRewordsItsQuestions) {
  MenuSettings settings;
  Menu menu(GameMode::kCommercial, settings, {}, [](const std::string& english) {
    return english.find("remotely fair") != std::string::npos ? std::string("This is the highest skill level.") : english;
  });
  MenuContext c;
  menu.open();
  menu.key(kKeyEnter, 0, c);
  menu.key(kKeyUp, 0, c);
  menu.key(kKeyUp, 0, c);
  menu.key(kKeyUp, 0, c);  // from Hurt Me Plenty up to Nightmare!
  menu.key(kKeyEnter, 0, c);
  ASSERT_TRUE(menu.message());
  EXPECT_EQ(*menu.message(), "This is the highest skill level.");
}

TEST(Menu, QuitPicksItsMessageAndSoundByTheTic) {
  for (const uint64_t tic : {0u, 9u, 30u}) {
    MenuFixture f;
    f.context.game_tic = tic;
    f.press(kKeyF10);
    ASSERT_TRUE(f.menu.showing_message());
    const std::string expected = tic % 8 == 1 ? "you want to quit?\nthen, thou hast lost an eighth!"
                                 : tic % 8 == 6 ? "just leave. when you come\nback, i'll be waiting with a bat."
                                                : "are you sure you want to\nquit this great game?";
    EXPECT_EQ(*f.menu.message(), expected + "\n\n(press y to quit to dos.)") << tic;
    f.menu.take_sounds();
    f.press('y');
    const auto r = f.menu.take_requests();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].kind, Kind::kQuit);
    // Doom II's quitsounds2 by (gametic >> 2) & 7: vilact, getpow, boscub, slop, skeswg, kntdth, bspact, sgtatk.
    const Sound sounds[8] = {Sound::kVilact, Sound::kGetpow, Sound::kBoscub, Sound::kSlop,
                             Sound::kSkeswg, Sound::kKntdth, Sound::kBspact, Sound::kSgtatk};
    EXPECT_EQ(f.menu.take_sounds(), std::vector<Sound>{sounds[(tic >> 2) & 7]}) << "and no closing click: Doom has quit";
  }
}

// Doom's menu in a netgame: no load, quickload, new game or end (M_LoadGame's LOADNET...).
TEST(Menu, ANetgameCannotBeLoadedOverStartedAgainOrEnded) {
  MenuFixture f;
  f.context.user_game = f.context.in_level = f.context.netgame = true;
  auto says = [&](int key, const std::string& text) {
    f.press(key);
    const bool shown = f.menu.message() && f.menu.message()->rfind(text, 0) == 0;
    f.press(' ');
    if (f.menu.active()) f.press(kKeyEscape);
    return shown;
  };
  EXPECT_TRUE(says(kKeyF3, "you can't do load while in a net game!"));
  EXPECT_TRUE(says(kKeyF9, "you can't quickload during a netgame!"));
  EXPECT_TRUE(says(kKeyF7, "you can't end a netgame!"));
  f.press(kKeyEscape);
  EXPECT_TRUE(says(kKeyEnter, "you can't start a new game")) << "the main menu's first item";
  f.press(kKeyF2);
  EXPECT_EQ(f.menu.screen().page, Menu::Page::kSave) << "saving is allowed: every player's node saves";
}

TEST(Menu, SavingNeedsAGameAndTypesAnUpperCaseDescription) {
  MenuFixture f;
  f.press(kKeyF2);
  EXPECT_TRUE(f.menu.showing_message()) << "you can't save if you aren't playing";
  f.press(' ');
  f.context.user_game = f.context.in_level = true;
  f.slots[1] = "OLD ONE";
  f.press(kKeyF2);
  ASSERT_EQ(f.menu.screen().page, Menu::Page::kSave);
  EXPECT_EQ(f.menu.slot_texts()[0], "empty slot");
  EXPECT_EQ(f.menu.slot_texts()[1], "OLD ONE");
  f.press(kKeyEnter);
  ASSERT_TRUE(f.menu.entering_save_name());
  EXPECT_EQ(f.menu.slot_texts()[0], "") << "an empty slot starts blank";
  for (int k : {int('h'), int('i'), int(kKeySpace), int('{'), int('1'), int(kKeyBackspace), int('2')}) f.press(k);
  EXPECT_EQ(f.menu.slot_texts()[0], "HI 2") << "letters in capitals, '{' is not in Doom's font";
  f.press(kKeyEnter);
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Kind::kSaveGame);
  EXPECT_EQ(r[0].slot, 0);
  EXPECT_EQ(r[0].text, "HI 2");
}

TEST(Menu, EscapeWhileTypingPutsTheOldDescriptionBack) {
  MenuFixture f;
  f.context.user_game = f.context.in_level = true;
  f.slots[0] = "KEEP";
  f.press(kKeyF2);
  f.press(kKeyEnter);
  f.press(kKeyBackspace);
  f.press(kKeyEscape);
  EXPECT_EQ(f.menu.slot_texts()[0], "KEEP");
  EXPECT_FALSE(f.menu.entering_save_name());
  EXPECT_TRUE(f.menu.active());
  EXPECT_TRUE(f.menu.take_requests().empty());
}

TEST(Menu, ADescriptionStopsAtTheSlotsWidth) {
  MenuFixture f;
  f.context.user_game = f.context.in_level = true;
  f.menu.text_width = [](const std::string& s) { return int(s.size()) * 10; };
  f.press(kKeyF2);
  f.press(kKeyEnter);
  for (int i = 0; i < 30; ++i) f.press('w');
  EXPECT_EQ(f.menu.slot_texts()[0].size(), 18u) << "Doom types while the text is narrower than 176 pixels";
}

TEST(Menu, LoadingSkipsEmptySlotsAndQuickloadAsksFirst) {
  MenuFixture f;
  f.slots[2] = "THIRD";
  f.press(kKeyF9);
  EXPECT_TRUE(f.menu.showing_message()) << "no quicksave slot yet";
  f.press(kKeyEscape);
  f.press(kKeyF3);
  ASSERT_EQ(f.menu.screen().page, Menu::Page::kLoad);
  EXPECT_EQ(f.menu.screen().items[0].status, 0);
  EXPECT_EQ(f.menu.screen().items[2].status, 1);
  f.press(kKeyEnter);
  EXPECT_TRUE(f.menu.take_requests().empty()) << "an empty slot does not load";
  f.press('3');  // the slot's hotkey
  f.press(kKeyEnter);
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Kind::kLoadGame);
  EXPECT_EQ(r[0].slot, 2);
}

TEST(Menu, QuicksavePicksASlotOnceThenAsks) {
  MenuFixture f;
  f.context.user_game = f.context.in_level = true;
  f.press(kKeyF6);
  ASSERT_EQ(f.menu.screen().page, Menu::Page::kSave) << "the first quicksave opens the save menu";
  f.press(kKeyDown);
  f.press(kKeyEnter);
  f.press('q');
  f.press(kKeyEnter);
  ASSERT_EQ(f.menu.take_requests().size(), 1u);
  f.press(kKeyF6);
  ASSERT_TRUE(f.menu.showing_message());
  EXPECT_EQ(*f.menu.message(), "quicksave over your game named\n\n'Q'?\n\npress y or n.");
  f.press('y');
  const auto r = f.menu.take_requests();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Kind::kSaveGame);
  EXPECT_EQ(r[0].slot, 1);
  f.press(kKeyF9);
  f.press('y');
  const auto l = f.menu.take_requests();
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].kind, Kind::kLoadGame);
  EXPECT_EQ(l[0].slot, 1);
}

TEST(Menu, SlidersAndTogglesChangeTheSettings) {
  MenuFixture f;
  f.menu.open();
  f.press(kKeyDown);
  f.press(kKeyEnter);  // Options
  f.press(kKeyDown);   // Messages
  f.press(kKeyEnter);
  EXPECT_FALSE(f.settings.show_messages);
  auto r = f.menu.take_requests();
  ASSERT_GE(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Kind::kMessage);
  EXPECT_EQ(r[0].text, "Messages OFF");
  f.press(kKeyDown);
  f.press(kKeyDown);  // Screen Size
  f.press(kKeyLeft);
  EXPECT_EQ(f.settings.screen_blocks, 8);
  for (int i = 0; i < 12; ++i) f.press(kKeyRight);
  EXPECT_EQ(f.settings.screen_blocks, 11) << "the slider's end: the view without the status bar";
  f.press(kKeyDown);  // Mouse
  for (int i = 0; i < 12; ++i) f.press(kKeyRight);
  EXPECT_EQ(f.settings.mouse_sensitivity, 9);
  f.press(kKeyDown);
  f.press(kKeyEnter);  // Sound Volume
  for (int i = 0; i < 20; ++i) f.press(kKeyLeft);
  EXPECT_EQ(f.settings.sfx_volume, 0);
  f.press(kKeyDown);
  f.press(kKeyRight);
  EXPECT_EQ(f.settings.music_volume, 9);
  f.menu.take_sounds();
  f.press(kKeyBackspace);
  EXPECT_EQ(f.menu.screen().page, Menu::Page::kOptions) << "backspace goes back a menu";
  EXPECT_EQ(f.menu.take_sounds(), std::vector<Sound>{Sound::kSwtchn});
}

TEST(Menu, FunctionKeysWithTheMenuClosed) {
  MenuFixture f;
  f.press(kKeyF11);
  EXPECT_EQ(f.settings.gamma, 1);
  auto r = f.menu.take_requests();
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r[0].text, "Gamma correction level 1");
  for (int i = 0; i < 4; ++i) f.press(kKeyF11);
  EXPECT_EQ(f.settings.gamma, 0) << "level 4 wraps to off";
  f.press(kKeyMinus);
  EXPECT_EQ(f.settings.screen_blocks, 8);
  f.context.automap = true;
  EXPECT_FALSE(f.press(kKeyMinus)) << "the map zooms with it";
  f.press(kKeyF7);
  EXPECT_FALSE(f.menu.showing_message()) << "no game to end";
  EXPECT_EQ(f.menu.take_sounds().back(), Sound::kOof);
  f.press(kKeyF4);
  EXPECT_EQ(f.menu.screen().page, Menu::Page::kSound);
  f.press(kKeyEscape);
  f.press(kKeyF1);
  EXPECT_TRUE(f.menu.showing_help());
  f.press(kKeyEnter);
  EXPECT_EQ(f.menu.screen().page, Menu::Page::kMain) << "Doom II's one help page leads back to the main menu";
}

TEST(Menu, ReadThisShowsDoomsTwoPagesOrUltimatesOne) {
  MenuFixture registered(GameMode::kRegistered);
  registered.menu.open();
  for (int i = 0; i < 4; ++i) registered.press(kKeyDown);
  registered.press(kKeyEnter);
  EXPECT_EQ(registered.menu.screen().page, Menu::Page::kReadThis1);
  registered.press(kKeyEnter);
  EXPECT_EQ(registered.menu.screen().page, Menu::Page::kReadThis2);
  MenuFixture ultimate(GameMode::kRetail);
  ultimate.menu.open();
  ultimate.press('r');  // Read This!'s hotkey
  ultimate.press(kKeyEnter);
  EXPECT_EQ(ultimate.menu.screen().page, Menu::Page::kReadThis2) << "the Ultimate Doom's one page";
}

TEST(Menu, TheSkullBlinksEveryEightTics) {
  MenuFixture f;
  std::vector<int> skulls;
  for (int t = 0; t < 30; ++t) {
    skulls.push_back(f.menu.screen().skull);
    f.menu.tic();
  }
  // Doom's M_Init counts 10 tics first, then 8.
  EXPECT_EQ(skulls[9], 0);
  EXPECT_EQ(skulls[10], 1);
  EXPECT_EQ(skulls[17], 1);
  EXPECT_EQ(skulls[18], 0);
}

TEST(DemoLoop, DoomIIShowsTheTitleAndThreeDemos) {
  DemoLoop loop(GameMode::kCommercial);
  std::vector<std::string> steps;
  for (int i = 0; i < 7; ++i) steps.push_back(loop.advance().lump);
  EXPECT_EQ(steps, (std::vector<std::string>{"TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "TITLEPIC", "DEMO3", "TITLEPIC"}));
  loop.restart();
  const DemoStep title = loop.advance();
  EXPECT_EQ(title.tics, 11 * 35);
  EXPECT_EQ(title.music, (play::Track{play::Music::kDm2ttl, false}));
}

TEST(DemoLoop, UltimateDoomAddsTheFourthDemo) {
  DemoLoop loop(GameMode::kRetail);
  std::vector<std::string> steps;
  for (int i = 0; i < 8; ++i) steps.push_back(loop.advance().lump);
  EXPECT_EQ(steps, (std::vector<std::string>{"TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "CREDIT", "DEMO3", "DEMO4", "TITLEPIC"}));
  DemoLoop registered(GameMode::kRegistered);
  for (int i = 0; i < 4; ++i) registered.advance();
  EXPECT_EQ(registered.advance().lump, "HELP2");
  registered.restart();
  EXPECT_EQ(registered.advance().tics, 170);
}

TEST(Keys, NamesRoundTrip) {
  for (int key : {int(kKeyEscape), int(kKeyF1), int(kKeyF10), int(kKeyF11), int(kKeyF12), int('a'), int('7'), int(','),
                  int(kKeyUp), int(kKeyRShift), int(kKeyPause), int(kKeySpace), 200})
    EXPECT_EQ(key_from_name(key_name(key)), key) << key_name(key);
  EXPECT_EQ(key_from_name("F3"), kKeyF3);
  EXPECT_FALSE(key_from_name("nokey"));
  EXPECT_FALSE(key_from_name(""));
}

TEST(Gamma, LevelsBrightenDarkColoursAndKeepWhite) {
  EXPECT_EQ(gamma_channel(0, 0), 1) << "Doom's level 0 table starts at 1";
  EXPECT_GT(gamma_channel(4, 32), gamma_channel(1, 32));
  EXPECT_EQ(gamma_channel(4, 255), 255);
  std::vector<uint32_t> pixels = {0xFF102030u};
  apply_gamma(0, pixels);
  EXPECT_EQ(pixels[0], 0xFF102030u) << "level 0 shows the frame as it is";
  apply_gamma(2, pixels);
  EXPECT_EQ(pixels[0] >> 24, 0xFFu);
  EXPECT_GT(pixels[0] & 0xFF, 0x30u);
}

}  // namespace
}  // namespace p3d::front
