// The game's SDL-free core: input mapping, the HUD's text, the session's
// interpolation, renderer switching and reloading, and headless replay.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/map/generate.h"
#include "engine/play/doom_demo.h"
#include "engine/play/thing_dump.h"
#include "engine/render/camera_file.h"
#include "engine/wad/art.h"
#include "engine/util/file.h"
#include "game/autopilot.h"
#include "game/front_end.h"
#include "game/headless.h"
#include "game/hud.h"
#include "game/input.h"
#include "game/session.h"
#include "game/sound_mixer.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::game {
namespace {

TEST(Input, DoomKeysMakeDoomCommands) {
  Controls c;
  EXPECT_EQ(make_command(c, 0), play::DemoTic{});
  c.forward = true;
  EXPECT_EQ(make_command(c, 0).cmd.forward, 25);
  c.run = true;
  EXPECT_EQ(make_command(c, 0).cmd.forward, 50);
  c.back = true;  // both cancel
  EXPECT_EQ(make_command(c, 0).cmd.forward, 0);
  c = {};
  c.strafe_right = true;
  EXPECT_EQ(make_command(c, 0).cmd.side, 24);
  c.strafe_left = true;
  EXPECT_EQ(make_command(c, 0).cmd.side, 0);
  c = {};
  c.turn_left = true;
  EXPECT_EQ(make_command(c, 0).cmd.turn, 320) << "slow for the first tics";
  EXPECT_EQ(make_command(c, 6).cmd.turn, 640);
  c.run = true;
  EXPECT_EQ(make_command(c, 6).cmd.turn, 1280);
  c.strafe_modifier = true;  // Alt+Left strafes left instead
  EXPECT_EQ(make_command(c, 6).cmd.turn, 0);
  EXPECT_EQ(make_command(c, 6).cmd.side, -40);
  c = {};
  c.mouse_dx = 10;  // right turns clockwise
  EXPECT_EQ(make_command(c, 0, {24}).cmd.turn, -240);
  c.mouse_dx = 100000;
  EXPECT_EQ(make_command(c, 0, {24}).cmd.turn, -32767) << "clamped, not wrapped";
}

TEST(Hud, LinesNameTheRendererTheWorkAndThePlace) {
  render::RenderStats s;
  s.nodes_visited = 31;
  s.subtrees_culled = 8;
  s.fragments_drawn = 26;
  s.columns_closed = 640;
  s.pixels_written = 256000;
  s.early_exit = true;
  FrameTimes t{512, 1.95, 0.01, 0.52, 1.42};
  const auto lines = hud_lines("Outpost", "bsp", s, t, {64, 96}, 0, 30);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "Outpost  512 fps  1.95 ms (sim 0.01, render 0.52, present 1.42)");
  EXPECT_EQ(lines[1], "bsp: nodes 31  culled 8  fragments 26  columns closed 640  pixels 256000  early exit");
  EXPECT_EQ(lines[2], "x 64.0  y 96.0  z 0.0  angle 30.0");
  render::RenderStats rays;
  rays.rays = 640;
  rays.steps = 6400;
  rays.columns_closed = 640;
  EXPECT_EQ(hud_lines("m", "sphere", rays, t, {64, 96}, 0, 30)[1], "sphere: rays 640  steps/ray 10.0  columns closed 640  pixels 0");
  EXPECT_GE(help_lines().size(), 6u);
}

TEST(Hud, ProgressNamesKeysAndSecrets) {
  EXPECT_EQ(progress_line(0, 0, 0, false), "keys: none");
  EXPECT_EQ(progress_line(1 | 32, 1, 3, true), "keys: blue card, red skull  secrets 1/3  noclip");
}

TEST(Menu, ChoosesWithUpAndDown) {
  Menu m;
  EXPECT_FALSE(m.is_open());
  m.open();
  EXPECT_EQ(m.selected(), Menu::Item::kResume);
  m.up();
  EXPECT_EQ(m.selected(), Menu::Item::kQuit) << "up from the top wraps to the bottom";
  m.down();
  m.down();
  EXPECT_EQ(m.selected(), Menu::Item::kKeys);
  const auto lines = m.lines();
  EXPECT_NE(std::find(lines.begin(), lines.end(), "> Keys"), lines.end());
  m.close();
  m.open();
  EXPECT_EQ(m.selected(), Menu::Item::kResume) << "opens on Resume";
}

TEST(Hud, OffByDefaultAndOneLineAtLowResolutions) {
  Session s(test::source_dir() / "maps/outpost.map");
  EXPECT_FALSE(s.show_hud);
  for (int t = 0; t < 4 * kTicRate; ++t) s.tic(play::TicCmd{});  // the start's message fades
  render::Frame small(320, 200);
  s.render(small, 1);
  const render::Frame bare = small;
  s.show_hud = true;
  s.draw_overlays(small, {}, 1);
  int rows = 0;  // rows the panel changed
  for (int y = 0; y < small.height; ++y) {
    bool changed = false;
    for (int x = 0; x < small.width; ++x) changed |= small.pixels[size_t(y) * small.width + x] != bare.pixels[size_t(y) * small.width + x];
    rows += changed;
  }
  EXPECT_GT(rows, 0);
  EXPECT_LT(rows, small.height / 10) << "a compact heads-up text at 320x200";
}

TEST(Hud, LongLinesWrapAtSpaces) {
  EXPECT_EQ(wrap_lines({"one two three four"}, 9), (std::vector<std::string>{"one two", "three", "four"}));
  EXPECT_EQ(wrap_lines({"abcdefghij"}, 4), (std::vector<std::string>{"abcd", "efgh", "ij"}));
  EXPECT_EQ(wrap_lines({"short", ""}, 40), (std::vector<std::string>{"short", ""}));
}

TEST(Session, InterpolatesBetweenTicsAndSwitchesRenderers) {
  Session s(test::source_dir() / "maps/outpost.map");
  EXPECT_EQ(s.title(), "Outpost");
  s.tic(play::TicCmd{50, 0, 0});
  s.tic(play::TicCmd{50, 0, 0});
  const render::Camera before = s.camera(0), after = s.camera(1), half = s.camera(0.5);
  EXPECT_EQ(after.pos, s.pose().pos);
  EXPECT_NEAR(half.pos.x, (before.pos.x + after.pos.x) / 2, 1e-9);
  EXPECT_LT(before.pos.x, after.pos.x);
  EXPECT_FALSE(s.select_renderer("dda")) << "outpost is not a grid map";
  EXPECT_EQ(s.renderer_name(), "bsp");
  for (const std::string& name : key_renderers()) {
    if (name == "dda") continue;
    EXPECT_TRUE(s.select_renderer(name)) << name;
  }
  render::Frame frame(64, 40);
  s.show_automap = true;
  s.render(frame, 0.5);
  s.draw_overlays(frame, {}, 0.5);  // HUD and automap draw without trouble on a small frame
}

TEST(Session, ReloadKeepsThePlayerAndSurvivesABrokenMap) {
  const auto dir = test::temp_dir("reload");
  std::filesystem::create_directory_symlink(test::source_dir() / "maps/textures", dir / "textures");
  std::string text = read_file_text(test::source_dir() / "maps/outpost.map");
  write_file_atomically(dir / "m.map", text);
  Session s(dir / "m.map");
  for (int i = 0; i < 10; ++i) s.tic(play::TicCmd{50, 0, 0});
  const geom::Vec2 where = s.pose().pos;
  const size_t walls = s.level().walls.size();
  write_file_atomically(dir / "m.map", text + "vertex extra1 100 20\nvertex extra2 120 40\nsegment extra1 extra2 texture=metal\n");
  EXPECT_TRUE(s.reload());
  EXPECT_EQ(s.level().walls.size(), walls + 1);
  EXPECT_EQ(s.pose().pos, where);
  write_file_atomically(dir / "m.map", text + "nonsense\n");
  EXPECT_FALSE(s.reload());
  EXPECT_EQ(s.level().walls.size(), walls + 1) << "the old level stays";
  s.tic(play::TicCmd{});
  std::filesystem::remove_all(dir);
}

// The level designer's loop: the map lives in a PWAD over an IWAD; each save reloads it.
TEST(Session, ReloadsAWadMapWhenThePwadChanges) {
  const auto dir = test::temp_dir("reload-wad");
  test::WadWriter iwad(true);
  test::add_test_art(iwad);
  write_file_atomically(dir / "doom.wad", iwad.bytes());
  auto save = [&](int light) {
    test::TestMap m;
    m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {0, 128, "FLOOR", "CEIL", light});
    m.things.push_back({64, 64, 0, 1, 7});
    test::WadWriter pwad;
    m.add_to(pwad, "MAP01");
    write_file_atomically(dir / "mine.wad", pwad.bytes());
  };
  save(100);
  Session s(bsp::LevelSource{{}, {dir / "doom.wad", dir / "mine.wad"}, "MAP01"});
  EXPECT_EQ(s.name(), "mine.wad:MAP01");
  EXPECT_EQ(s.files().size(), 2u);
  EXPECT_EQ(s.level().sectors[0].light, 100);
  save(200);
  EXPECT_TRUE(s.reload());
  EXPECT_EQ(s.level().sectors[0].light, 200);
  write_file_atomically(dir / "mine.wad", std::string("PWAD broken"));
  EXPECT_FALSE(s.reload());
  EXPECT_EQ(s.level().sectors[0].light, 200) << "the old level stays";
  std::filesystem::remove_all(dir);
}

// The summed brightness of a frame (red + green + blue over every pixel).
uint64_t brightness(const render::Frame& frame) {
  uint64_t sum = 0;
  for (uint32_t p : frame.pixels) sum += (p & 0xff) + (p >> 8 & 0xff) + (p >> 16 & 0xff);
  return sum;
}

// --map-reload end to end, without a window: the game's loop (tic, reload check,
// render) runs on a clock of its own while an editor saves the map the ways editors
// do; the frames show the change once the save has settled, and only then.
TEST(Session, MapReloadShowsAnEditorsSaveInTheNextFrames) {
  const auto dir = test::temp_dir("map-reload");
  std::filesystem::create_directory_symlink(test::source_dir() / "maps/textures", dir / "textures");
  const std::string bright = read_file_text(test::source_dir() / "maps/outpost.map");
  const std::string hall = "sector hall     floor=0   ceiling=160 light=176";
  ASSERT_NE(bright.find(hall), std::string::npos);
  std::string dark = bright;
  dark.replace(dark.find(hall), hall.size(), "sector hall     floor=0   ceiling=160 light=40 ");
  const auto map = dir / "m.map";
  write_file_atomically(map, bright);

  Session s(map);
  s.watch_files();
  s.tic(play::TicCmd{0, 0, 0});
  const geom::Vec2 stand = s.pose().pos;
  render::Frame frame(160, 100);
  double now = 0;
  int reloads = 0;
  auto run = [&](double seconds) {  // the loop: one tic, the reload check and a frame, 35 times a second
    for (int i = 0; i < int(seconds * kTicRate); ++i) {
      s.tic(play::TicCmd{});
      now += 1.0 / kTicRate;
      reloads += s.reload_if_saved(now);
      s.render(frame, 1);
    }
    return brightness(frame);
  };
  const uint64_t before = run(1);
  EXPECT_EQ(reloads, 0) << "nothing changed";

  // Written in place, half at first: nothing happens while the file is still growing.
  { std::ofstream(map, std::ios::binary | std::ios::trunc) << dark.substr(0, dark.size() / 2); }
  run(0.2);
  { std::ofstream(map, std::ios::binary | std::ios::trunc) << dark; }
  EXPECT_EQ(reloads, 0) << "a half-written file is not read";
  const uint64_t darker = run(1.5);
  EXPECT_EQ(reloads, 1);
  EXPECT_LT(darker, before * 0.9) << "the hall's new light shows in the frames";
  EXPECT_EQ(s.pose().pos, stand) << "the player stays where they stood";

  // Renamed over, after being briefly missing: one reload, back to the bright hall.
  std::filesystem::rename(map, dir / "m.map~");
  EXPECT_EQ(run(1.5), darker) << "a missing file is waited for, the level kept";
  EXPECT_EQ(reloads, 1);
  write_file_atomically(map, bright);
  EXPECT_EQ(run(1.5), before);
  EXPECT_EQ(reloads, 2);

  // A broken save keeps the old level; the fix after it reloads.
  write_file_atomically(map, bright + "nonsense\n");
  EXPECT_EQ(run(1.5), before);
  EXPECT_EQ(reloads, 2);
  write_file_atomically(map, dark);
  EXPECT_LT(run(1.5), before * 0.9);
  EXPECT_EQ(reloads, 3);
  std::filesystem::remove_all(dir);
}

// A PWAD renamed over by an editor: the new map is shown, the player moved to its
// start when the old spot is outside it.
TEST(Session, MapReloadFollowsAPwadRenamedOver) {
  const auto dir = test::temp_dir("map-reload-wad");
  test::WadWriter iwad(true);
  test::add_test_art(iwad);
  write_file_atomically(dir / "doom.wad", iwad.bytes());
  auto save = [&](int size, int light) {
    test::TestMap m;
    m.add_room({{0, 0}, {0, size}, {size, size}, {size, 0}}, {0, 128, "FLOOR", "CEIL", light});
    m.things.push_back({32, 32, 0, 1, 7});
    test::WadWriter pwad;
    m.add_to(pwad, "MAP01");
    write_file_atomically(dir / "mine.wad", pwad.bytes());  // a temporary file renamed over
  };
  save(1024, 100);
  Session s(bsp::LevelSource{{}, {dir / "doom.wad", dir / "mine.wad"}, "MAP01"});
  s.watch_files();
  s.spawn({900, 900}, 0);
  double now = 0;
  auto settle = [&] {
    bool reloaded = false;
    for (int i = 0; i < 50; ++i) reloaded |= s.reload_if_saved(now += 0.1);
    return reloaded;
  };
  EXPECT_FALSE(settle());
  save(1024, 200);
  EXPECT_TRUE(settle());
  EXPECT_EQ(s.level().sectors[0].light, 200);
  EXPECT_EQ(s.pose().pos, geom::Vec2(900, 900));
  save(256, 50);  // the room shrank under the player
  EXPECT_TRUE(settle());
  EXPECT_EQ(s.level().sectors[0].light, 50);
  EXPECT_EQ(s.pose().pos, geom::Vec2(32, 32)) << "moved to the start";
  std::filesystem::remove_all(dir);
}

// The mixer: Doom's panning and distance, resampling, and channels freed when a
// sound ends or goes out of hearing.
TEST(SoundMixer, PlacesResamplesAndFrees) {
  play::SoundClip clip{11025, std::vector<uint8_t>(100, 255)};
  SoundMixer mixer(44100, [&](play::Sound) { return &clip; });
  const play::Listener east = listener_at({0, 0}, 0);
  ASSERT_TRUE(mixer.start(play::Sound::kItemup, 1, std::nullopt, east));  // the player's own: centred
  std::vector<int16_t> out(16);
  mixer.mix(out);
  EXPECT_GT(out[0], 0);
  EXPECT_NEAR(out[0], out[1], out[0] / 50) << "centred: both ears nearly alike (Doom's pan is 126 to 128)";
  for (size_t i = 2; i < out.size(); ++i) EXPECT_EQ(out[i], out[i % 2]) << "four output samples for each 11025 Hz one";

  ASSERT_TRUE(mixer.start(play::Sound::kDoropn, 2, geom::Vec2{0, 600}, east));  // to the left
  std::vector<int16_t> both(2);
  mixer.mix(both);
  EXPECT_GT(both[0] - out[0], both[1] - out[1]) << "the left ear hears the door more";
  EXPECT_FALSE(mixer.start(play::Sound::kDoropn, 3, geom::Vec2{5000, 0}, east)) << "too far to hear";
  EXPECT_EQ(mixer.playing(), 2);
  mixer.update(listener_at({5000, 5000}, 0));  // walked away from the door
  EXPECT_EQ(mixer.playing(), 1);
  std::vector<int16_t> rest(400 * 2);
  mixer.mix(rest);  // the clip's 100 samples end within 400 output samples
  mixer.update(east);
  EXPECT_EQ(mixer.playing(), 0);
  EXPECT_EQ(rest.back(), 0);
}

// Sounds follow their makers (Doom's S_UpdateSounds): a sound from a thing that moves
// to the other side pans with it, and stops when the thing is gone.
TEST(SoundMixer, SoundsFollowTheirMakersAndStopWithThem) {
  play::SoundClip clip{11025, std::vector<uint8_t>(4000, 255)};
  SoundMixer mixer(44100, [&](play::Sound) { return &clip; });
  const play::Listener east = listener_at({0, 0}, 0);
  ASSERT_TRUE(mixer.start(play::Sound::kPosact, 7, geom::Vec2{0, 600}, east));  // on the left
  std::vector<int16_t> left(2);
  mixer.mix(left);
  EXPECT_GT(left[0], left[1]);
  std::optional<geom::Vec2> at = geom::Vec2{0, -600};  // the thing walked round to the right
  mixer.update(east, [&](uint64_t origin) { return origin == 7 ? at : std::nullopt; });
  std::vector<int16_t> right(2);
  mixer.mix(right);
  EXPECT_LT(right[0], right[1]) << "the right ear hears it now";
  at.reset();  // removed
  mixer.update(east, [&](uint64_t origin) { return origin == 7 ? at : std::nullopt; });
  EXPECT_EQ(mixer.playing(), 0);
}

// A session on a WAD level places its sounds: a door's from the middle of the door
// sector, and reads them from the WAD's lumps (a level without WADs is silent).
TEST(Session, SoundsComeFromTheirSectorsAndTheWadsLumps) {
  const auto dir = test::temp_dir("sounds");
  test::WadWriter wad(true);
  test::add_test_art(wad);
  std::vector<uint8_t> lump = {3, 0, 0x11, 0x2b, 100, 0, 0, 0};
  lump.resize(108, 200);
  wad.lump("DSDOROPN", lump);
  test::TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 160}, {256, 96}, {256, 0}}, {0, 128});
  m.add_room({{256, 96}, {256, 160}, {288, 160}, {288, 96}}, {0, 0});
  m.line_at({256, 160}, {256, 96}).special = 1;
  m.things.push_back({230, 128, 0, 1});
  m.add_to(wad, "MAP01");
  write_file_atomically(dir / "doom.wad", wad.bytes());
  const bsp::LevelSource source{{}, {dir / "doom.wad"}, "MAP01"};
  Session deaf(source);
  deaf.tic(play::TicCmd{});  // a new player's use starts held (Doom's G_PlayerReborn): let go first
  deaf.tic(play::TicCmd{0, 0, 0, play::kBtUse});
  EXPECT_EQ(deaf.state().sectors[1].ceiling, 2) << "the door opens";
  EXPECT_TRUE(deaf.take_sounds().empty()) << "but nobody listens";
  Session s(source);
  s.listen();
  s.tic(play::TicCmd{});
  s.tic(play::TicCmd{0, 0, 0, play::kBtUse});
  const std::vector<Session::PlacedSound> sounds = s.take_sounds();
  ASSERT_EQ(sounds.size(), 1u);
  EXPECT_EQ(sounds[0].sound, play::Sound::kDoropn);
  ASSERT_TRUE(sounds[0].at);
  EXPECT_EQ(*sounds[0].at, geom::Vec2(272, 128)) << "the middle of the door sector";
  const play::SoundClip* clip = s.sound_clip(play::Sound::kDoropn);
  ASSERT_NE(clip, nullptr);
  EXPECT_EQ(clip->rate, 11025);
  EXPECT_EQ(s.sound_clip(play::Sound::kPistol), nullptr) << "not in the WAD";
  EXPECT_EQ(Session(test::source_dir() / "maps/outpost.map").sound_clip(play::Sound::kDoropn), nullptr);
  std::filesystem::remove_all(dir);
}

// A netgame's demo played with every player's input and recorded again: FreeDM's DEMO3
// (three players, altdeath) comes out byte for byte as the WAD holds it.
TEST(Session, ANetgameDemoPlayedAndRecordedIsTheSameDemo) {
  const auto wad = test::freedoom_path("freedm.wad");
  const wad::Stack wads = bsp::read_wads({wad});
  const wad::Lump* lump = wads.find("DEMO3");
  ASSERT_NE(lump, nullptr);
  const std::vector<uint8_t> original(lump->bytes.begin(), lump->bytes.end());
  const play::DoomDemo doom = play::decode_doom_demo(original, "DEMO3");
  ASSERT_EQ(doom.player_count(), 3);
  Session s(bsp::LevelSource{{}, {wad}, doom.map_name(true)}, doom.skill, flags_of(doom));
  s.play_other_players(doom);
  s.start_recording(true);
  for (const play::DemoTic& t : play::demo_from_doom(doom, s.level()).tics) s.tic(t);
  EXPECT_TRUE(s.world().options().netgame);
  EXPECT_EQ(s.world().options().deathmatch, play::Deathmatch::kAltdeath);
  EXPECT_EQ(s.encode_recording("demo3.lmp"), original);
}

// --record x.lmp: a Doom v1.9 demo of the walk, its turns rounded as Doom keeps them
// before they are played, so replaying the Doom demo walks the same path.
TEST(Session, ADoomDemoRecordingReplaysTheSameWalk) {
  const auto dir = test::temp_dir("lmp");
  test::WadWriter wad(true);
  test::add_test_art(wad);
  test::TestMap m;
  m.add_room({{0, 0}, {0, 1024}, {1024, 1024}, {1024, 0}}, {0, 128});
  m.things.push_back({100, 100, 0, 1});
  m.add_to(wad, "MAP07");
  write_file_atomically(dir / "doom.wad", wad.bytes());
  const bsp::LevelSource source{{}, {dir / "doom.wad"}, "MAP07"};
  Session recorder(source);
  recorder.start_recording(true);
  for (int t = 0; t < 120; ++t) recorder.tic(play::TicCmd{50, int8_t(t % 7 - 3), int16_t(300 + 37 * (t % 5)), 0});
  const std::vector<uint8_t> bytes = recorder.encode_recording(dir / "walk.lmp");
  const play::DoomDemo doom = play::decode_doom_demo(bytes, "walk.lmp");
  EXPECT_EQ(doom.map_name(true), "MAP07");
  EXPECT_EQ(doom.tic_count(), 120u);
  Session player(source);
  const play::Demo demo = play::demo_from_doom(doom, player.level());
  for (const play::DemoTic& t : demo.tics) player.tic(t);
  EXPECT_EQ(player.pose().pos, recorder.pose().pos);
  EXPECT_EQ(player.pose().angle, recorder.pose().angle);
  EXPECT_NE(recorder.pose().pos, geom::Vec2(100, 100));
  EXPECT_THROW(Session(test::source_dir() / "maps/outpost.map").encode_recording(dir / "x.lmp"), Error)
      << "a hand-made level is no Doom map";

  // With long tics the turns stay whole, and the v1.91 demo replays them.
  Session fine(source);
  fine.start_recording(true, true);
  for (int t = 0; t < 120; ++t) fine.tic(play::TicCmd{50, 0, int16_t(300 + 37 * (t % 5)), 0});
  const play::DoomDemo long_tics = play::decode_doom_demo(fine.encode_recording(dir / "fine.lmp"), "fine.lmp");
  EXPECT_TRUE(long_tics.long_tics());
  EXPECT_EQ(long_tics.console_tic(1).turn, 337);
  Session fine_player(source);
  for (const play::DemoTic& t : play::demo_from_doom(long_tics, fine_player.level()).tics) fine_player.tic(t);
  EXPECT_EQ(fine_player.pose().pos, fine.pose().pos);
  EXPECT_EQ(fine_player.pose().angle, fine.pose().angle);
  EXPECT_NE(fine.pose().angle, recorder.pose().angle) << "turns a coarse recording rounded";
  std::filesystem::remove_all(dir);
}

// A WAD level at 320x200 is laid out as Doom's screen: the view in the top 168 rows,
// exactly as a 320x168 frame shows it, and the status bar in the 32 below.
TEST(Session, WadLevelsShowDoomsStatusBarBelowAShorterView) {
  Session s(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"});
  for (int t = 0; t < 5; ++t) s.tic(play::TicCmd{});
  render::Frame doom(320, 200), view(320, 168);
  EXPECT_EQ(s.status_bar_rows(doom), 32);
  s.render(doom, 1);
  s.show_status_bar = false;
  s.render(view, 1);
  EXPECT_EQ(s.status_bar_rows(view), 0);
  EXPECT_TRUE(std::equal(view.pixels.begin(), view.pixels.end(), doom.pixels.begin())) << "the view above the bar";
  s.show_status_bar = true;
  render::Frame big(640, 400), tiny(160, 100);
  EXPECT_EQ(s.status_bar_rows(big), 64) << "scaled by 2";
  EXPECT_EQ(s.status_bar_rows(tiny), 0) << "no room for it";
  EXPECT_EQ(Session(test::source_dir() / "maps/outpost.map").status_bar_rows(doom), 0) << "our own levels have none";
}

// A replay's frame 0 is drawn before the first tic: from the eye, where that tic puts
// the player, not from Doom's view_z mark at the floor.
TEST(Session, TheFrameBeforeTheFirstTicSeesFromTheEye) {
  Session s(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"});
  EXPECT_DOUBLE_EQ(s.camera(0).z, s.pose().z + 41);
  EXPECT_DOUBLE_EQ(s.camera(1).z, s.pose().z + 41);
  s.tic(play::TicCmd{});
  EXPECT_DOUBLE_EQ(s.camera(1).z, s.pose().z + 41) << "where the first tic put it";
}

// A pickup flashes the screen gold for a few tics, through the WAD's own palettes:
// every pixel of the frame (view and bar) is a colour of the gold palette.
TEST(Session, APickupFlashesTheScreenGold) {
  Session s(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"});
  std::optional<geom::Vec2> at;
  for (size_t i = 0; i < s.level().things.size() && !at; ++i)
    for (int type : {2014, 2015, 2007, 2008})  // bonuses, a clip, shells: taken at the start
      if (s.level().things[i].type == type && level::find_placed(s.state(), int32_t(i)) != level::kNone)
        at = s.level().things[i].pos;
  ASSERT_TRUE(at);
  EXPECT_EQ(s.flash_palette(), 0);
  s.spawn(*at - geom::Vec2(0, 8), 90);
  s.tic(play::TicCmd{25, 0, 0, 0});  // Doom takes what a move touches
  EXPECT_EQ(s.player().inv.bonus_count, play::kBonusAdd) << "it was picked up";
  ASSERT_EQ(s.flash_palette(), 10) << "Doom's second gold palette";
  render::Frame frame(320, 200);
  s.render(frame, 1);
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  const std::vector<uint32_t> gold = wad::Art(wads).palettes()[10];
  const std::set<uint32_t> colours(gold.begin(), gold.end()), normal(s.level().palette.begin(), s.level().palette.end());
  size_t not_normal = 0, off_view = 0, off_bar = 0;
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    (i < 320 * 168 ? off_view : off_bar) += !colours.count(frame.pixels[i]);
    not_normal += !normal.count(frame.pixels[i]);
  }
  EXPECT_EQ(off_view, 0u) << "every pixel of the view through the gold palette";
  EXPECT_EQ(off_bar, 0u) << "and of the bar";
  EXPECT_GT(not_normal, frame.pixels.size() / 2) << "most of them unlike any normal colour";
  for (int t = 0; t < 12; ++t) s.tic(play::TicCmd{});
  EXPECT_EQ(s.flash_palette(), 0) << "gone after 6 tics";
}

// After an exit the window shows Doom's tally: the level's counts and time over the
// WAD's intermission picture, until the next map is entered.
TEST(Session, TheIntermissionTalliesTheLevel) {
  const auto wad = test::freedoom_path("freedoom2.wad");
  Session s(bsp::LevelSource{{}, {wad}, "MAP01"});
  for (int t = 0; t < 70; ++t) s.tic(play::TicCmd{});
  const play::Tally t = s.tally();
  EXPECT_EQ(t.seconds, 2);
  EXPECT_EQ(t.total_secrets, s.world().total_secrets());
  EXPECT_GT(t.total_items, 0);
  EXPECT_GT(t.total_kills, 0);
  EXPECT_EQ(t.player_kills[size_t(t.me)], 0) << "no monster dies yet";
  ASSERT_TRUE(s.start_intermission());
  EXPECT_TRUE(s.in_intermission());
  render::Frame frame(320, 200);
  s.render(frame, 1);
  const wad::Stack wads = bsp::read_wads({wad});
  const wad::IndexedImage back = wad::decode_picture(wads.find("INTERPIC")->bytes, "INTERPIC");
  const std::vector<uint32_t> palette = wad::Art(wads).palette();
  EXPECT_EQ(frame.at(160, 120), palette[back.indices[back.at(160, 120)]]) << "the picture behind the tally";
  EXPECT_EQ(play::par_seconds(0, 1), 30) << "Doom II's MAP01 par";
  EXPECT_EQ(play::par_seconds(1, 1), 30) << "E1M1's";
  EXPECT_EQ(play::par_seconds(4, 1), 90) << "episode 4 reads Doom II's table one map on, as Chocolate Doom";
  // Doom's WI_Ticker: a press shows the counts at once, the next leaves in ten tics.
  const play::TicCmd fire{0, 0, 0, play::kBtAttack};
  s.tic(fire);
  s.tic(play::TicCmd{});
  s.tic(fire);
  for (int held = 0; held < 9; ++held) s.tic(fire);
  EXPECT_FALSE(s.intermission_over()) << "the held button is no new press";
  s.tic(play::TicCmd{});
  EXPECT_TRUE(s.intermission_over());
  EXPECT_TRUE(s.player().attack_down == false) << "the last tic's buttons stay in the player";
  s.enter_next_map();
  EXPECT_FALSE(s.in_intermission());
  EXPECT_FALSE(Session(test::source_dir() / "maps/outpost.map").start_intermission()) << "our own levels have none";
}

// A WAD in `dir` whose MAP01 is one 256-unit room with a floor of Doom's sector special
// `floor_special` (5: 10% slime, 16: 20% damage), holding `things`.
bsp::LevelSource damaging_room(const std::filesystem::path& dir, int floor_special,
                               const std::vector<test::TestMap::Thing>& things) {
  test::WadWriter wad(true);
  test::add_test_art(wad);
  test::TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {0, 128, "FLOOR", "CEIL", 160, floor_special});
  m.things = things;
  m.add_to(wad, "MAP01");
  write_file_atomically(dir / "doom.wad", wad.bytes());
  return {{}, {dir / "doom.wad"}, "MAP01"};
}

// Death on a slime floor, then use: the level starts again with a fresh player, as
// Doom's single-player reborn.
TEST(Session, UseAfterDeathStartsTheLevelAgain) {
  const auto dir = test::temp_dir("reborn");
  Session s(damaging_room(dir, 5, {{64, 64, 0, 1}}));
  for (int t = 0; t < 32 * 10 + 5; ++t) s.tic(play::TicCmd{25, 0, 0, 0});
  ASSERT_EQ(s.player().state, play::PlayerState::kDead);
  const geom::Vec2 fell = s.pose().pos;
  s.tic(play::TicCmd{25, 0, 0, 0});
  EXPECT_EQ(s.pose().pos, fell) << "the dead do not walk";
  s.tic(play::TicCmd{0, 0, 0, play::kBtUse});
  EXPECT_EQ(s.player().state, play::PlayerState::kReborn);
  const int game_tic = s.world().game_tic();
  s.tic(play::TicCmd{});  // Doom's next G_Ticker starts the level again
  EXPECT_EQ(s.player().state, play::PlayerState::kLive);
  EXPECT_EQ(s.world().level_time(), 1);
  EXPECT_EQ(s.world().game_tic(), game_tic + 1) << "Doom's gametic goes on (a revenant's missile steers by it)";
  EXPECT_EQ(s.player().inv.health, 90) << "a fresh player, hurt at once: the slime bites at level time 0";
  EXPECT_EQ(s.pose().pos, geom::Vec2(64, 64)) << "back at the start";
  std::filesystem::remove_all(dir);
}

// A netgame's dead player pressing use comes back into the level going on, and Doom's
// P_SpawnPlayer starts the console player's message line afresh (HU_Start): the clip's
// message, seconds from fading, is gone.
TEST(Session, ANetgameRespawnClearsTheMessageLine) {
  const auto dir = test::temp_dir("respawn_message");
  GameFlags coop;
  coop.players = {true, true, false, false};
  // The two players' starts, and a clip ahead of player 1.
  Session s(damaging_room(dir, 16, {{64, 64, 0, 1}, {192, 192, 0, 2}, {112, 64, 0, 2007}}), 3, coop);
  int t = 0;
  for (; t < 90; ++t) s.tic(play::TicCmd{});
  for (; t < 100 && s.message().empty(); ++t) s.tic(play::TicCmd{25, 0, 0, 0});
  ASSERT_EQ(s.message(), "Picked up a clip.");
  for (; t < 200 && s.player().state != play::PlayerState::kDead; ++t) s.tic(play::TicCmd{});
  ASSERT_EQ(s.player().state, play::PlayerState::kDead) << "five bites of the floor";
  s.tic(play::TicCmd{0, 0, 0, play::kBtUse});
  ASSERT_EQ(s.player().state, play::PlayerState::kReborn);
  EXPECT_FALSE(s.message().empty()) << "still shown while the player lies dead";
  const int level_time = s.world().level_time();
  s.tic(play::TicCmd{});  // G_Ticker's reborn: back at the start
  EXPECT_EQ(s.player().state, play::PlayerState::kLive);
  EXPECT_EQ(s.world().level_time(), level_time + 1) << "the level goes on";
  EXPECT_EQ(s.message(), "");
  std::filesystem::remove_all(dir);
}

// --dump-things: every thing after every tic of a Freedoom demo, one block a tic, the
// player first, each block's random index and the player's values those of stats.csv.
TEST(Headless, DumpsEveryThingAfterEveryTic) {
  const auto dir = test::temp_dir("thing_dump");
  const auto iwad = test::freedoom_path("freedoom2.wad");
  const play::DoomDemo doom = play::decode_doom_demo(bsp::read_wads({iwad}).find("DEMO3")->bytes, "DEMO3");
  Session s(bsp::LevelSource{{}, {iwad}, doom.map_name(true)}, doom.skill, GameFlags{});
  play::Demo demo = play::demo_from_doom(doom, s.level());
  demo.tics.resize(120);
  HeadlessOptions o{1, dir, 96, 60};
  o.frames = false;
  o.raw = true;
  o.thing_dump = dir / "things.txt";
  ASSERT_EQ(replay_headless(s, demo, o).tics, 120u);

  std::vector<std::vector<std::string>> stats;  // stats.csv's rows, row t after t tics
  {
    std::istringstream csv(read_file_text(dir / "stats.csv"));
    for (std::string line; std::getline(csv, line);) {
      std::vector<std::string> fields;
      std::istringstream in(line);
      for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
      stats.push_back(fields);
    }
  }
  const auto column = [&](const std::string& name) {
    return size_t(std::find(stats[0].begin(), stats[0].end(), name) - stats[0].begin());
  };
  std::istringstream dump(read_file_text(dir / "things.txt"));
  size_t tic = 0, things = 0;
  bool player_next = false;
  for (std::string line; std::getline(dump, line);) {
    std::istringstream in(line);
    std::vector<std::string> f{std::istream_iterator<std::string>(in), {}};
    if (f[0] == "T") {
      ASSERT_EQ(f.size(), 3u) << line;
      ASSERT_EQ(f[1], std::to_string(tic)) << "a block after every tic, in order";
      EXPECT_EQ(f[2], stats[tic + 2][column("random")]) << "tic " << tic;  // +1: the header, +1: after tic+1 tics
      ++tic, player_next = true;
      continue;
    }
    ASSERT_EQ(f[0], "M") << line;
    ASSERT_EQ(f.size(), 19u) << line;
    ++things;
    if (player_next) {
      EXPECT_EQ(f[1], "0") << "the player is the first thing";
      EXPECT_EQ(f[2], stats[tic + 1][column("x_raw")]) << "tic " << tic - 1;
      EXPECT_EQ(f[3], stats[tic + 1][column("y_raw")]) << "tic " << tic - 1;
      player_next = false;
    }
  }
  EXPECT_EQ(tic, 120u);
  EXPECT_GT(things, 120u * 50) << "MAP02's monsters and items, every tic";
  std::filesystem::remove_all(dir);
}

TEST(Headless, ReplayIsByteForByteReproducible) {
  const auto dir = test::temp_dir("headless");
  Session recorder(test::source_dir() / "maps/outpost.map");
  recorder.start_recording();
  Autopilot pilot({{{300, 110}}, {{440, 192}}, {{700, 192}}});
  for (int t = 0; t < 150 && !pilot.done(); ++t) recorder.tic(pilot.next(recorder.pose().pos, recorder.pose().angle));
  const play::Demo demo = play::decode_demo(play::encode_demo(recorder.recording()), "d");
  EXPECT_GT(demo.tics.size(), 60u);
  EXPECT_EQ(recorder.pose().z, 96) << "the autopilot climbed the stairs";

  for (const char* run : {"a", "b"}) {
    Session s(test::source_dir() / "maps/outpost.map");
    const HeadlessResult r = replay_headless(s, demo, {20, dir / run, 96, 60});
    EXPECT_EQ(r.frames, int(demo.tics.size() / 20 + 1 + (demo.tics.size() % 20 != 0))) << "and one at the last tic";
    EXPECT_EQ(r.tics, demo.tics.size());
    EXPECT_EQ(r.exit, play::ExitKind::kNone);
    EXPECT_EQ(s.pose().pos, recorder.pose().pos) << "replay ends where the recording did";
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir / "a"))
    EXPECT_EQ(read_file_bytes(entry.path()), read_file_bytes(dir / "b" / entry.path().filename())) << entry.path();
  const std::string csv = read_file_text(dir / "a/stats.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "frame,tic,x,y,z,angle,health,armor,kills,items,secrets,keys,renderer,nodes_visited,subtrees_culled,"
            "fragments_drawn,columns_closed,pixels_written,masked_pixels,sprites_drawn,sprite_pixels,early_exit,rays,steps,"
            "max_steps,exit");

  Session other(test::source_dir() / "maps/soup.map");
  EXPECT_THROW(replay_headless(other, demo, {20, dir / "c", 96, 60}), Error);
  std::filesystem::remove_all(dir);
}

// MAP01: a room whose east wall is an exit switch; MAP02: a plain room. Named `first`
// and `second` (with a MAP01 of the first's kind, so that the WAD is Doom II's).
void two_map_wad(const std::filesystem::path& dir, const char* first = "MAP01", const char* second = "MAP02") {
  test::TestMap one, two;
  one.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {});
  one.line_at({256, 256}, {256, 0}).special = 11;
  one.things.push_back({200, 128, 0, 1});
  one.things.push_back({200, 128, 0, 2001});  // a shotgun where the player stands
  one.things.push_back({200, 128, 0, 2025});  // and a radiation suit
  two.add_room({{1000, 0}, {1000, 512}, {1512, 512}, {1512, 0}}, {});
  two.things.push_back({1100, 100, 90, 1});
  test::WadWriter w(true);
  test::add_test_art(w);
  if (std::string(first) != "MAP01") one.add_to(w, "MAP01");
  one.add_to(w, first);
  two.add_to(w, second);
  write_file_atomically(dir / "two.wad", w.bytes());

}

TEST(Session, AnExitLoadsTheNextMapInDoomsOrder) {
  const auto dir = test::temp_dir("exit");
  two_map_wad(dir);
  Session s(bsp::LevelSource{{}, {dir / "two.wad"}, ""});
  s.give_all_keys(true);
  s.start_recording();
  s.tic(play::TicCmd{25, 0, 0, 0});  // a step: the shotgun and the suit under the player are taken
  for (int t = 0; t < 40; ++t) s.tic(play::TicCmd{});  // the pistol goes down, the shotgun comes up
  EXPECT_EQ(s.player().inv.ready, play::Weapon::kShotgun);
  s.tic(play::TicCmd{0, 0, 0, play::kBtUse});
  EXPECT_EQ(s.exited(), play::ExitKind::kNormal);
  EXPECT_EQ(s.recording().tics.size(), 42u) << "the demo ends at the exit";
  const Session::Pose before = s.pose();
  s.tic(play::TicCmd{50, 0, 0, 0});
  EXPECT_EQ(s.pose().pos, before.pos) << "nothing moves once the level is over";
  EXPECT_FALSE(s.message().empty()) << "the last pickup's message, still showing";
  EXPECT_TRUE(s.enter_next_map());
  EXPECT_EQ(s.message(), "") << "Doom's HU_Start: a map starts with no message (nor says its name)";
  EXPECT_EQ(s.name(), "two.wad:MAP02");
  EXPECT_EQ(s.pose().pos, geom::Vec2(1100, 100));
  EXPECT_EQ(s.player().cards, 63) << "--all-keys holds on every map";
  EXPECT_EQ(s.player().inv.ready, play::Weapon::kShotgun) << "weapons and ammo go on to the next map";
  EXPECT_EQ(s.player().inv.ammo[1], 8);
  EXPECT_EQ(s.player().inv.powers[size_t(play::Power::kIronFeet)], 0) << "powers stay behind";
  EXPECT_EQ(s.exited(), play::ExitKind::kNone);
  std::filesystem::remove_all(dir);
}

// The number of "T" blocks in a thing dump: the tics played in a level.
size_t dumped_tics(const std::filesystem::path& dump) {
  std::istringstream in(read_file_text(dump));
  size_t blocks = 0;
  for (std::string line; std::getline(in, line);) blocks += line.rfind("T ", 0) == 0;
  return blocks;
}

// A Doom demo that exits goes on as Chocolate Doom replays it: through the tally, which
// the demo's presses hurry on, into the next map with the health carried over. The
// headless replay and the front end watching the demo (its screens melting between,
// the demo waiting for them) play the same game to the same end.
TEST(Headless, ADoomDemoGoesOnThroughTheTallyIntoTheNextMap) {
  const auto dir = test::temp_dir("across_levels");
  const auto iwad = test::freedoom_path("freedoom2.wad");
  // The walk to MAP01's exit (tests/golden/doom_demos: Chocolate plays it in sync), then
  // the tally's presses, a fresh one every fourth tic, then MAP02 walked into.
  const play::DoomDemo walk = play::decode_doom_demo(
      read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp"), "walk");
  const bsp::LevelSource map01{{}, {iwad}, "MAP01"};
  auto session = [&] { return std::make_unique<Session>(map01, walk.skill, flags_of(walk)); };
  std::unique_ptr<Session> headless = session();
  play::Demo demo = play::demo_from_doom(walk, headless->level());
  const size_t walked = demo.tics.size();
  for (int t = 0; t < 10; ++t) demo.tics.push_back({});
  for (int t = 0; t < 200; ++t) demo.tics.push_back({play::TicCmd{0, 0, 0, uint8_t(t % 4 == 0 ? play::kBtUse : 0)}, 0});
  for (int t = 0; t < 140; ++t) demo.tics.push_back({play::TicCmd{25, 0, int16_t(t < 70 ? 512 : 0), 0}, 0});

  HeadlessOptions o{35, dir / "frames", 96, 60};
  o.frames = false;
  o.thing_dump = dir / "things.txt";
  const HeadlessResult r = replay_headless(*headless, demo, o);
  EXPECT_EQ(r.tics, demo.tics.size()) << "the demo is played to its end";
  EXPECT_EQ(r.maps, (std::vector<std::string>{"MAP01", "MAP02"}));
  EXPECT_EQ(r.exit, play::ExitKind::kNone);
  EXPECT_EQ(headless->map_name(), "MAP02");
  const size_t tally = demo.tics.size() - dumped_tics(o.thing_dump);
  EXPECT_GT(tally, 10u + 4) << "the tally waits for a fresh press, then ten tics";
  EXPECT_LT(tally, 60u) << "two presses end Doom II's tally";
  EXPECT_EQ(dumped_tics(o.thing_dump), walked + demo.tics.size() - walked - tally);
  EXPECT_GT(headless->world().level_time(), 100) << "MAP02 is played";

  Settings settings;
  FrontEndOptions watch;
  watch.watching = watch.plays_demo = true;
  FrontEnd front(session(), settings, watch);
  render::Frame screen(64, 40);  // drawn after every tic, as the window does: a change of screen melts
  size_t melting = 0;
  for (const play::DemoTic& t : demo.tics) {
    for (; front.melting(); ++melting) front.tic(), front.draw(screen, 1.0, {});
    ASSERT_TRUE(front.in_game());
    front.tic(t);
    front.draw(screen, 1.0, {});
  }
  EXPECT_GT(melting, 0u) << "the tally and MAP02 melted in";
  EXPECT_EQ(front.session()->map_name(), "MAP02");
  EXPECT_EQ(front.session()->world().level_time(), headless->world().level_time());
  EXPECT_EQ(play::dump_things(front.session()->world(), 0), play::dump_things(headless->world(), 0));
  EXPECT_EQ(front.session()->player().inv.health, headless->player().inv.health);
  std::filesystem::remove_all(dir);
}

// Doom II's text between clusters (after MAP06) holds the demo for 50 tics, then gives
// way at a press to MAP07; a press before then does nothing.
TEST(Headless, TheTextBetweenDoomIIsClustersGivesWayAtAPressAfter50Tics) {
  const auto dir = test::temp_dir("finale_demo");
  two_map_wad(dir, "MAP06", "MAP07");
  Session s(bsp::LevelSource{{}, {dir / "two.wad"}, "MAP06"});
  play::Demo demo;
  demo.level_fingerprint = play::fingerprint(s.level());
  demo.tics.push_back({play::TicCmd{25, 0, 0, 0}, 0});
  for (int t = 0; t < 40; ++t) demo.tics.push_back({});
  demo.tics.push_back({play::TicCmd{0, 0, 0, play::kBtUse}, 0});  // tic 41: the exit
  for (int t = 0; t < 60; ++t) demo.tics.push_back({play::TicCmd{0, 0, 0, play::kBtUse}, 0});
  for (int t = 0; t < 20; ++t) demo.tics.push_back({play::TicCmd{25, 0, 0, 0}, 0});
  HeadlessOptions o{10, dir / "frames", 64, 40};
  o.thing_dump = dir / "things.txt";
  const HeadlessResult r = replay_headless(s, demo, o);
  EXPECT_EQ(r.maps, (std::vector<std::string>{"MAP06", "MAP07"}));
  EXPECT_EQ(r.tics, demo.tics.size());
  // Tics 42 to 92 count the text's 51 tics; 93 is the press that ends it; 94 on: MAP07.
  EXPECT_EQ(dumped_tics(o.thing_dump), 42u + (demo.tics.size() - 94));
  EXPECT_GT(s.pose().pos.y, 100) << "MAP07's start, walked north from";
  const image::Image level = image::load_png(dir / "frames/frame00004.png");
  const image::Image text = image::load_png(dir / "frames/frame00006.png");  // tic 60: the text's 18th tic
  EXPECT_GT(image::compare(level, text).fraction(level), 0.5) << "the text's screen, not the level's view";
  EXPECT_EQ(image::compare(text, image::load_png(dir / "frames/frame00009.png")).differing_pixels, 0u)
      << "MAP06's text over the flat (the test WAD has no font to type it in)";
  EXPECT_GT(image::compare(text, image::load_png(dir / "frames/frame00010.png")).fraction(text), 0.5) << "MAP07";
  std::filesystem::remove_all(dir);
}

TEST(Session, TheLastMapStartsAgain) {
  Session s(test::source_dir() / "maps/outpost.map");
  EXPECT_FALSE(s.enter_next_map()) << "a hand-made level has no next map";
  EXPECT_EQ(s.pose().pos, s.level().player_start);
}

// The walk through freedoom2 MAP01 recorded as a Doom demo gives the bytes that Chocolate
// Doom was seen to play in sync (tests/golden/doom_demos, checked in DemoSync).
TEST(Session, RecordsTheDoomDemoChocolateDoomPlaysInSync) {
  Session s(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"});
  s.start_recording(true);
  Autopilot pilot(route_from_cameras(render::read_camera_list(test::source_dir() / "maps/freedoom2_map01.route")));
  while (!pilot.done() && s.exited() == play::ExitKind::kNone) s.tic(pilot.next(s.pose().pos, s.pose().angle));
  const auto dir = test::temp_dir("record_lmp");
  const auto lmp = dir / "walk.lmp";
  EXPECT_EQ(s.encode_recording(lmp),
            read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp"));
  std::filesystem::remove_all(dir);
}

TEST(Autopilot, UseWaypointsOpenDoors) {
  const auto dir = test::temp_dir("route");
  test::TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 160}, {256, 96}, {256, 0}}, {0, 128});
  m.add_room({{256, 96}, {256, 160}, {288, 160}, {288, 96}}, {0, 0});
  m.add_room({{288, 0}, {288, 96}, {288, 160}, {288, 256}, {544, 256}, {544, 0}}, {0, 128});
  m.line_at({256, 160}, {256, 96}).special = 1;
  m.things.push_back({64, 200, 0, 1});
  test::WadWriter w(true);
  test::add_test_art(w);
  m.add_to(w, "MAP01");
  write_file_atomically(dir / "door.wad", w.bytes());
  Session s(bsp::LevelSource{{}, {dir / "door.wad"}, ""});
  Autopilot pilot(route_from_cameras(render::parse_camera_list("use 220 128 0\nthrough 400 128 0\n", "route")));
  for (int t = 0; t < 600 && !pilot.done(); ++t) s.tic(pilot.next(s.pose().pos, s.pose().angle));
  EXPECT_TRUE(pilot.done());
  EXPECT_GT(s.pose().pos.x, 380) << "through the door the route opened";
  std::filesystem::remove_all(dir);
}

TEST(Input, TypedCheatsBecomeDemoCheats) {
  Cheats cheats;
  for (char c : std::string("xxidcli")) EXPECT_EQ(cheats.type(c), 0);
  EXPECT_EQ(cheats.type('p'), play::kToggleNoclip);
  for (char c : std::string("idspispop")) EXPECT_EQ(cheats.type(c), 0);
  EXPECT_EQ(cheats.type('d'), play::kToggleNoclip);
  for (char c : std::string("iddq")) EXPECT_EQ(cheats.type(c), 0);
  EXPECT_EQ(cheats.type('d'), play::kToggleGod);
  for (char c : std::string("idkf")) EXPECT_EQ(cheats.type(c), 0);
  EXPECT_EQ(cheats.type('a'), play::kGiveAll);
  Controls c;
  c.cheats = play::kToggleNoclip;
  EXPECT_EQ(make_command(c, 0).cheats, play::kToggleNoclip);
}

TEST(Input, AttackAndWeaponKeysAreDoomsButtons) {
  Controls c;
  c.attack = true;
  c.weapon = 3;  // Doom's key 3: the shotgun (weapon 2)
  const play::TicCmd cmd = make_command(c, 0).cmd;
  EXPECT_EQ(cmd.buttons, play::kBtAttack | play::kBtChange | 2 << play::kBtWeaponShift);
}

}  // namespace
}  // namespace p3d::game
