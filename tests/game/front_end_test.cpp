// Doom's front end on Freedoom: the title loop, the menus driving games, the world
// waiting under them, key scripts, the screens beside Chocolate Doom's, and the
// settings file.
#include "game/front_end.h"

#include <gtest/gtest.h>

#include <set>

#include "engine/front/keys.h"
#include "engine/image/image.h"
#include "engine/play/thing_dump.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "game/key_script.h"
#include "game/settings.h"
#include "tests/support/support.h"

#include <span>

namespace p3d::game {
namespace {

bsp::LevelSource freedoom2() { return {{}, {test::freedoom_path("freedoom2.wad")}, ""}; }

void press(FrontEnd& f, int key) {
  f.key_down(key);
  f.key_up(key);
}

TEST(FrontEnd, TheTitleLoopShowsThePageThenADemoAndAnyKeyOpensTheMenu) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  EXPECT_FALSE(f.session()) << "TITLEPIC first";
  EXPECT_EQ(f.music(), (play::Track{play::Music::kDm2ttl, false})) << "Doom plays the title music once";
  for (int t = 0; t < 11 * 35 + 1; ++t) f.tic();
  ASSERT_TRUE(f.session()) << "DEMO1 after eleven seconds";
  EXPECT_FALSE(f.playing()) << "a demo is watched, not played";
  EXPECT_EQ(f.session()->map_name(), "MAP15") << "freedoom2's DEMO1";
  EXPECT_EQ(f.music(), (play::Track{play::Music::kRunni2, true})) << "MAP15's own track";
  const uint64_t before = f.session()->tics();
  f.tic();
  EXPECT_EQ(f.session()->tics(), before + 1);
  press(f, 'x');
  EXPECT_TRUE(f.menu_active()) << "any key opens the menu over a demo";
  f.tic();
  EXPECT_EQ(f.session()->tics(), before + 2) << "the demo plays on under the menu, as in Doom";
}

TEST(FrontEnd, NewGameFromTheMenuThenTheWorldWaitsUnderIt) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  press(f, front::kKeyEscape);
  press(f, front::kKeyEnter);  // New Game
  press(f, front::kKeyDown);   // Ultra-Violence
  press(f, front::kKeyEnter);
  EXPECT_FALSE(f.playing()) << "Doom starts the game at the next tic (its gameaction)";
  f.tic();
  ASSERT_TRUE(f.playing());
  EXPECT_EQ(f.session()->map_name(), "MAP01");
  EXPECT_EQ(f.session()->skill(), 4);
  EXPECT_EQ(f.session()->screen_blocks, 9) << "Doom's default screen size";
  EXPECT_EQ(f.session()->tics(), 1u) << "and plays the level's first tic in the same";
  f.key_down('w');
  for (int t = 0; t < 9; ++t) f.tic();
  f.key_up('w');
  EXPECT_EQ(f.session()->tics(), 10u);
  const double x = f.session()->pose().pos.x, y = f.session()->pose().pos.y;
  EXPECT_NE(std::make_pair(x, y), std::make_pair(f.session()->level().player_start.x, f.session()->level().player_start.y))
      << "W walked";
  press(f, front::kKeyEscape);
  ASSERT_TRUE(f.waiting());
  for (int t = 0; t < 5; ++t) f.tic();
  EXPECT_EQ(f.session()->tics(), 10u) << "the menu stops the world";
  press(f, front::kKeyEscape);
  press(f, front::kKeyPause);
  f.tic();
  EXPECT_EQ(f.session()->tics(), 10u) << "and so does Pause";
  press(f, front::kKeyPause);
  f.tic();
  EXPECT_EQ(f.session()->tics(), 11u);
}

TEST(FrontEnd, EndGameGoesBackToTheTitleAndQuitWaitsForItsSound) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  f.new_game(1, 1, 3);
  press(f, front::kKeyF7);
  press(f, 'y');
  f.tic();
  EXPECT_FALSE(f.session()) << "back on the title page";
  EXPECT_EQ(f.music().music, play::Music::kDm2ttl);
  press(f, front::kKeyF10);
  press(f, 'y');
  EXPECT_FALSE(f.quit_requested()) << "the quit sound plays first";
  int tics = 0;
  while (!f.quit_requested() && tics < 100) f.tic(), ++tics;
  EXPECT_EQ(tics, 53) << "Doom's 105 VBLs";
}

// Doom II's MAP06: the tally until two presses, then C1TEXT typed over its flat with
// D_READ_M, then at a button MAP07; Doom's E1M8: the text at once (no tally), then the episode's picture.
TEST(FrontEnd, FinalesBetweenClustersAndAfterEpisodes) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  f.new_game(1, 6, 3);
  f.tic();
  f.session()->end_level(false);
  f.tic();
  ASSERT_TRUE(f.session()->in_intermission());
  EXPECT_EQ(f.music().music, play::Music::kDm2int);
  const play::DemoTic use{play::TicCmd{0, 0, 0, play::kBtUse}, 0};
  f.tic(use);  // the counts at once
  f.tic();
  f.tic(use);  // on: Doom's ten tics to the next screen
  for (int t = 0; t < 9; ++t) f.tic();
  EXPECT_TRUE(f.session()->in_intermission());
  f.tic();
  EXPECT_FALSE(f.in_level()) << "the finale's text";
  EXPECT_EQ(f.music(), (play::Track{play::Music::kReadM, true}));
  render::Frame frame(320, 200);
  for (int t = 0; t < 300; ++t) f.tic();
  f.draw(frame, 1, {});
  std::set<uint32_t> colours(frame.pixels.begin(), frame.pixels.end());
  EXPECT_GT(colours.size(), 8u) << "a flat and letters";
  f.tic(play::DemoTic{play::TicCmd{0, 0, 0, play::kBtAttack}, 0});
  ASSERT_TRUE(f.in_level());
  EXPECT_EQ(f.session()->map_name(), "MAP07");
  EXPECT_EQ(f.music().music, play::Music::kShawn) << "MAP07's track";

  FrontEnd doom({{}, {test::freedoom_path("freedoom1.wad")}, ""}, settings, {});
  doom.new_game(1, 8, 3);
  doom.tic();
  doom.session()->end_level(false);
  doom.tic();
  EXPECT_FALSE(doom.in_level());
  EXPECT_FALSE(doom.session()->in_intermission()) << "no tally after an episode's end";
  EXPECT_EQ(doom.music(), (play::Track{play::Music::kVictor, true}));
  for (int t = 0; t < 3000; ++t) doom.tic();
  doom.draw(frame, 1, {});
  EXPECT_FALSE(doom.in_level()) << "the episode ends on its picture, for as long as the player looks";
}

TEST(FrontEnd, MenuSoundsAndMusicAreLoggedByAKeyScript) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  const auto steps = parse_key_script("3 key escape\n8 key enter\n9 key enter\n12 end\n", "s");
  const std::filesystem::path out = test::temp_dir("front_end_log");
  const ScriptResult r = run_key_script(f, steps, out, 320, 200);
  EXPECT_EQ(r.tics, 12u);
  EXPECT_NE(r.log.find("4 sound SWTCHN"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("9 sound PISTOL"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("1 music D_DM2TTL once"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("10 music D_RUNNIN loop"), std::string::npos) << r.log << " (MAP01's, from the tic it starts)";
}

// The menu's slots: a save written through the menu loads from the title back to the
// same place; a broken or foreign slot is refused with a message and the game goes on.
TEST(FrontEnd, SlotsSaveAndLoadAndABrokenSaveLeavesTheGame) {
  Settings settings;
  FrontEndOptions options;
  options.save_dir = test::temp_dir("front_end_slots");
  FrontEnd f(freedoom2(), settings, options);
  f.new_game(1, 1, 3);
  f.key_down('w');
  for (int t = 0; t < 20; ++t) f.tic();
  f.key_up('w');
  for (int t = 0; t < 20; ++t) f.tic();
  press(f, front::kKeyF2);
  press(f, front::kKeyEnter);
  for (char c : std::string("here")) press(f, c);
  press(f, front::kKeyEnter);
  f.tic();  // the game saved goes on a tic: so shall the one loaded (Doom loads, then plays the tic)
  const Session::Pose saved = f.session()->pose();
  ASSERT_TRUE(std::filesystem::exists(f.slot_path(0)));
  const std::vector<uint8_t> good = read_file_bytes(f.slot_path(0));
  EXPECT_EQ(std::string(good.begin(), good.begin() + 4), "HERE") << "Doom's description opens the file";
  press(f, front::kKeyF7);
  press(f, 'y');
  f.tic();
  ASSERT_FALSE(f.session()) << "back on the title";
  press(f, front::kKeyF3);
  press(f, front::kKeyEnter);
  f.tic();
  ASSERT_TRUE(f.playing());
  EXPECT_EQ(f.session()->pose().pos, saved.pos);
  EXPECT_EQ(f.session()->pose().angle, saved.angle);

  // A save cut short, and one of Doom (freedoom1) in a Doom II game: refused, the game goes on.
  write_file_atomically(f.slot_path(1), std::span(good.data(), good.size() / 2));
  const std::vector<uint8_t> doom1 = [] {
    Settings s;
    FrontEndOptions o;
    o.save_dir = test::temp_dir("front_end_slots_doom1");
    FrontEnd d({{}, {test::freedoom_path("freedoom1.wad")}, ""}, s, o);
    d.new_game(1, 1, 3);
    d.tic();
    EXPECT_TRUE(d.save_slot(0, "E1M1"));
    return read_file_bytes(d.slot_path(0));
  }();
  write_file_atomically(f.slot_path(2), doom1);
  for (int slot : {1, 2}) {
    const uint64_t tics = f.session()->tics();
    const Session::Pose before = f.session()->pose();
    EXPECT_FALSE(f.load_slot(slot)) << slot;
    ASSERT_TRUE(f.playing());
    EXPECT_EQ(f.session()->map_name(), "MAP01");
    EXPECT_EQ(f.session()->pose().pos, before.pos);
    f.tic();
    EXPECT_EQ(f.session()->tics(), tics + 1) << "the game goes on";
  }
}

TEST(KeyScript, BadStepsNameTheirLine) {
  auto message = [](const std::string& text) {
    try {
      parse_key_script(text, "s.txt");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("1 key escape\nx key enter\n"), "s.txt:2: 'x' is not a tic number");
  EXPECT_EQ(message("5 key escape\n3 key enter\n"), "s.txt:2: tic 3 comes before the last step's");
  EXPECT_EQ(message("1 key nokey\n"), "s.txt:1: unknown key 'nokey'");
  EXPECT_EQ(message("1 jump\n"), "s.txt:1: unknown step 'jump' (key, hold, release, type, shot or end)");
  EXPECT_EQ(message("1 shot ../x.png\n"), "s.txt:1: a shot needs a plain file name (no directory)");
  EXPECT_EQ(message("# only a comment\n\n"), "no error");
}

// Our screens beside Chocolate Doom's own screenshots (320x200, taken by
// tools/peer_menus.sh): Doom's menus from the WAD's pictures, its font, its smaller
// view in a border with the status bar.
double equal_share(const image::Image& a, const image::Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.pixels.size() != b.pixels.size()) return 0;
  size_t equal = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) equal += a.pixels[i] == b.pixels[i];
  return double(equal) / double(a.pixels.size());
}

TEST(FrontEnd, ScreensAreChocolateDoomsPixels) {
  Settings settings;
  FrontEnd f(freedoom2(), settings, {});
  // Chocolate's skull was lit (M_SKULL1) in these shots; ours is drawn at both phases.
  const auto steps = parse_key_script(
      "14 key escape\n20 shot main_a.png\n28 shot main_b.png\n30 key enter\n36 shot skill_a.png\n44 shot skill_b.png\n"
      "46 key enter\n140 shot game_a.png\n146 shot game_b.png\n152 shot game_c.png\n155 key escape\n156 key down\n"
      "157 key enter\n160 shot options_a.png\n168 shot options_b.png\n170 end\n",
      "screens");
  const std::filesystem::path out = test::temp_dir("front_end_screens");
  run_key_script(f, steps, out, 320, 200);
  const std::filesystem::path golden = test::source_dir() / "tests/golden/chocolate_menus";
  auto best = [&](const std::string& screen, std::initializer_list<const char*> ours) {
    const image::Image theirs = image::load_png(golden / ("freedoom2_" + screen + ".png"));
    double share = 0;
    for (const char* o : ours) share = std::max(share, equal_share(image::load_png(out / o), theirs));
    return share;
  };
  EXPECT_GE(best("main", {"main_a.png", "main_b.png"}), 0.9999) << "the title and the main menu";
  EXPECT_GE(best("skill", {"skill_a.png", "skill_b.png"}), 0.9999);
  // The face glances every half second: one of three tics shows Chocolate's glance.
  EXPECT_GE(best("game", {"game_a.png", "game_b.png", "game_c.png"}), 0.99)
      << "the view at screen size 9 in its border, the status bar";
  EXPECT_GE(best("options", {"options_a.png", "options_b.png"}), 0.99);
}

TEST(Settings, SurviveARestartAndTheirTextRoundTrips) {
  Settings s;
  s.menu.mouse_sensitivity = 7;
  s.menu.show_messages = false;
  s.menu.screen_blocks = 11;
  s.menu.sfx_volume = 3;
  s.menu.music_volume = 15;
  s.menu.gamma = 2;
  s.menu.low_detail = true;
  s.window_width = 1280, s.window_height = 800;
  s.fullscreen = true;
  s.renderer = "painter";
  s.last_wad = "/usr/share/games/doom/freedoom1.wad";
  s.keys[size_t(Action::kUse)] = {'f', front::kKeyEnter};
  const std::filesystem::path path = test::temp_dir("settings_round_trip") / "deeper" / "settings.cfg";
  std::string why;
  ASSERT_TRUE(save_settings(s, path, why)) << why;
  std::vector<std::string> warnings;
  const Settings back = load_settings(path, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(format_settings(back), format_settings(s));
  EXPECT_EQ(back.keys[size_t(Action::kUse)], (std::vector<int>{'f', front::kKeyEnter}));
  EXPECT_EQ(back.menu.gamma, 2);
}

TEST(Settings, ADamagedFileGivesWarningsAndDefaultsNeverACrash) {
  std::vector<std::string> warnings;
  const Settings s = parse_settings(
      "mouse_sensitivity = 12\nscreen_blocks=10\nnonsense\ncolour = blue\nkey_fire = nokey\nwindow = 0x0\n"
      "sfx_volume = 4\xff\n",
      "cfg", warnings);
  EXPECT_EQ(s.menu.mouse_sensitivity, 5) << "out of range: the default";
  EXPECT_EQ(s.menu.screen_blocks, 10);
  EXPECT_EQ(s.keys[size_t(Action::kFire)], default_key_bindings()[size_t(Action::kFire)]);
  EXPECT_EQ(s.menu.sfx_volume, 8);
  ASSERT_EQ(warnings.size(), 6u);
  EXPECT_EQ(warnings[0], "cfg:1: bad value '12' for mouse_sensitivity, the default kept");
  EXPECT_EQ(warnings[1], "cfg:3: not 'name = value', skipped");
  EXPECT_EQ(warnings[2], "cfg:4: unknown setting 'colour', skipped");
  // An unreadable file (here a directory) and a missing one: the defaults.
  std::vector<std::string> more;
  const std::filesystem::path dir = test::temp_dir("settings_is_a_directory");
  std::filesystem::create_directories(dir);
  EXPECT_EQ(format_settings(load_settings(dir, more)), format_settings(Settings{}));
  EXPECT_EQ(more.size(), 1u);
  EXPECT_EQ(format_settings(load_settings(dir / "missing.cfg", more)), format_settings(Settings{}));
  EXPECT_EQ(more.size(), 1u) << "a missing file is no warning: the first run";
}

TEST(Settings, AFailedSaveLeavesTheOldFile) {
  const std::filesystem::path dir = test::temp_dir("settings_readonly");
  std::filesystem::create_directories(dir);
  Settings s;
  std::string why;
  ASSERT_TRUE(save_settings(s, dir / "settings.cfg", why));
  const std::string before = read_file_text(dir / "settings.cfg");
  EXPECT_FALSE(save_settings(s, dir / "settings.cfg" / "below_a_file.cfg", why));
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(read_file_text(dir / "settings.cfg"), before);
}

// A netgame's chat from the keys: T starts a line, the letters go out one a tic in our
// commands (Doom's HU_dequeueChatChar) and move no one meanwhile; the other node shows
// the line after our name (as the WAD words it) when its enter arrives.
TEST(FrontEnd, ChatFromTheKeysGoesOutInTheCommands) {
  Settings settings;
  GameFlags two;
  two.players = {true, true, false, false};
  FrontEnd f(std::make_unique<Session>(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"}, 3, two),
             settings, {});
  ASSERT_TRUE(f.netgame());
  for (int key : std::initializer_list<int>{'t', 'h', 'w', 'i', front::kKeyEnter}) f.key_down(key), f.key_up(key);
  EXPECT_EQ(f.session()->message(), "HWI") << "our own line, shown at once";
  std::vector<uint8_t> sent;
  for (int t = 0; t < 6; ++t) {
    const play::TicCmd cmd = f.command();
    EXPECT_EQ(cmd.forward, 0) << "'w' was the chat's";
    sent.push_back(cmd.chatchar);
  }
  EXPECT_EQ(sent, (std::vector<uint8_t>{play::Chat::kToEveryone, 'H', 'W', 'I', play::Chat::kEnter, 0}));

  GameFlags other = two;
  other.console_player = 1;
  Session s(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"}, 3, other);
  for (uint8_t c : sent) {
    std::array<play::TicCmd, play::kMaxPlayers> cmds{};
    cmds[0].chatchar = c;
    s.queue_other_players(cmds);
    s.tic(play::TicCmd{});
  }
  EXPECT_EQ(s.message(), "g:HWI") << "Freedoom's DEHACKED names green g:, as Chocolate Doom shows it";
}

// A netgame's pause and save go out in our command as Doom's special buttons: every
// node pauses at the tic that carries one, and saves (ours with our description, the
// other's as "NET GAME") before the next.
TEST(FrontEnd, ANetgamesPauseAndSaveTravelInTheCommands) {
  const auto dir = test::temp_dir("netgame-save");
  Settings settings;
  GameFlags two;
  two.players = {true, true, false, false};
  const bsp::LevelSource map01{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"};
  FrontEndOptions ours_options, theirs_options;
  ours_options.save_dir = dir / "ours";
  theirs_options.save_dir = dir / "theirs";
  GameFlags other = two;
  other.console_player = 1;
  FrontEnd ours(std::make_unique<Session>(map01, 3, two), settings, ours_options);
  FrontEnd theirs(std::make_unique<Session>(map01, 3, other), settings, theirs_options);
  // One tic of both nodes: each one's command, the other's queued beside it.
  auto tic = [&] {
    const play::TicCmd a = ours.command(), b = theirs.command();
    ours.session()->queue_other_players({a, b, {}, {}});
    theirs.session()->queue_other_players({a, b, {}, {}});
    ours.tic({a, 0});
    theirs.tic({b, 0});
  };
  tic();
  ours.key_down(front::kKeyPause);
  tic();
  EXPECT_TRUE(ours.paused() && theirs.paused()) << "both, at the tic our command says so";
  EXPECT_FALSE(ours.waiting()) << "the lockstep goes on";
  const int level_time = theirs.session()->world().level_time();
  tic();
  EXPECT_EQ(theirs.session()->world().level_time(), level_time) << "the worlds wait";
  theirs.key_down(front::kKeyPause);
  tic();
  EXPECT_FALSE(ours.paused() || theirs.paused()) << "either player's pause ends it";

  ours.key_down(front::kKeyF2);
  ours.key_down(front::kKeyEnter);  // slot 0
  for (int key : std::initializer_list<int>{'u', 's', front::kKeyEnter}) ours.key_down(key);
  EXPECT_FALSE(std::filesystem::exists(ours.slot_path(0))) << "not before the command runs";
  tic();
  tic();  // saved before this one, as Doom's ga_savegame
  ASSERT_TRUE(std::filesystem::exists(ours.slot_path(0)));
  ASSERT_TRUE(std::filesystem::exists(theirs.slot_path(0)));
  EXPECT_EQ(Session::save_description(read_file_bytes(ours.slot_path(0))), "US");
  EXPECT_EQ(Session::save_description(read_file_bytes(theirs.slot_path(0))), "NET GAME");
  EXPECT_EQ(read_file_bytes(ours.slot_path(0)).size(), read_file_bytes(theirs.slot_path(0)).size());
}

// Two nodes of a netgame cross a level change in lockstep: the tally takes every
// player's command, the other player's press hurries both tallies on, both enter the
// next map at the same tic, and their worlds stay the same thing for thing.
TEST(FrontEnd, TwoNodesLeaveTheTallyAtTheSameTicAndPlayOnAlike) {
  Settings settings;
  GameFlags two;
  two.players = {true, true, false, false};
  two.deathmatch = 1;
  GameFlags other = two;
  other.console_player = 1;
  const bsp::LevelSource map01{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"};
  FrontEnd a(std::make_unique<Session>(map01, 3, two), settings, {});
  FrontEnd b(std::make_unique<Session>(map01, 3, other), settings, {});
  std::vector<play::TicCmd> moves;  // player 1 runs and turns; player 2 presses fire now and then
  auto tic = [&](int t) {
    const play::TicCmd first{50, 0, int16_t(t % 40 < 20 ? 300 : -300), 0};
    const play::TicCmd second{0, 0, 0, uint8_t(t % 30 == 29 ? play::kBtAttack : 0)};
    a.session()->queue_other_players({first, second, {}, {}});
    b.session()->queue_other_players({first, second, {}, {}});
    a.tic({first, 0});
    b.tic({second, 0});
  };
  for (int t = 0; t < 40; ++t) tic(t);
  a.session()->end_level(false);  // the same exit on both nodes, as a timer's would be
  b.session()->end_level(false);
  int t = 40, tally_tics = 0;
  for (; t < 400 && (a.session()->in_intermission() || a.session()->map_name() == "MAP01"); ++t, ++tally_tics) {
    tic(t);
    EXPECT_EQ(a.session()->in_intermission(), b.session()->in_intermission()) << t;
  }
  ASSERT_EQ(a.session()->map_name(), "MAP02") << "the presses of player 2 ended both tallies";
  EXPECT_EQ(b.session()->map_name(), "MAP02");
  EXPECT_GT(tally_tics, 40) << "a second's pause, a count, another press, ten tics";
  for (int end = t + 100; t < end; ++t) tic(t);
  EXPECT_EQ(play::dump_things(a.session()->world(), 0), play::dump_things(b.session()->world(), 0));
  EXPECT_GT(a.session()->world().level_time(), 90);
}

}  // namespace
}  // namespace p3d::game
