// Savegames through the game: a demo replayed headless that saves and loads its game at
// several tics draws the same frames and writes the same stats as the replay that never
// saved, byte for byte; Chocolate Doom's own saves loaded mid-replay go on as Chocolate
// Doom's play after loading them; the Session's save and load keep the game whole when
// a save is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/play/doom_demo.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "game/headless.h"
#include "game/session.h"
#include "tests/support/support.h"

namespace p3d::game {
namespace {

bsp::LevelSource freedoom(const std::string& wad, const std::string& map = "") {
  return bsp::LevelSource{{}, {test::freedoom_path(wad)}, map};
}

// A Doom demo's game: the session on its map and skill, and its tics.
struct DemoGame {
  std::unique_ptr<Session> session;
  play::Demo demo;
};

DemoGame demo_game(const std::string& wad, std::span<const uint8_t> bytes) {
  const play::DoomDemo d = play::decode_doom_demo(bytes, "demo");
  const wad::Stack wads = bsp::read_wads({test::freedoom_path(wad)});
  DemoGame g;
  g.session = std::make_unique<Session>(freedoom(wad, d.map_name(wads.map("MAP01").has_value())), d.skill,
                                        GameFlags{d.fast, d.respawn, d.no_monsters});
  g.demo = play::demo_from_doom(d, g.session->level());
  return g;
}

DemoGame demo_lump(const std::string& wad, int number) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path(wad)});
  return demo_game(wad, wads.find("DEMO" + std::to_string(number))->bytes);
}

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() != ".dsg") out.push_back(e.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

// Saved and loaded at several tics of two demos: every frame (Doom's screen at 320x200,
// with the status bar's face and the messages) and every stats row as the plain replay's.
TEST(SaveGames, ADemoThatSavesAndLoadsDrawsTheSameFramesAsOneThatNeverDid) {
  const auto dir = test::temp_dir("save_exact");
  // (Frames every 40 tics, the first right after a load: tics count from 0.)
  for (const auto& [wad, number, tics] : {std::tuple{"freedoom2.wad", 1, std::vector<size_t>{0, 279, 559, 799, 1119}},
                                          std::tuple{"freedoom1.wad", 3, std::vector<size_t>{39, 439, 719, 999}}}) {
    HeadlessOptions plain{40, dir / "plain", 320, 200};
    plain.raw = true;
    HeadlessOptions saving = plain;
    saving.out_dir = dir / "saving";
    for (size_t t : tics) {
      const auto file = dir / "saving" / ("at" + std::to_string(t) + ".dsg");
      saving.saves.push_back({t, file});
      saving.loads.push_back({t, file});
    }
    std::filesystem::create_directories(saving.out_dir);
    DemoGame a = demo_lump(wad, number), b = demo_lump(wad, number);
    const HeadlessResult ra = replay_headless(*a.session, a.demo, plain);
    const HeadlessResult rb = replay_headless(*b.session, b.demo, saving);
    EXPECT_EQ(ra.tics, rb.tics);
    const auto files = files_in(dir / "plain");
    ASSERT_EQ(files, files_in(dir / "saving"));
    EXPECT_GT(files.size(), 30u);
    size_t same = 0;
    for (const auto& f : files) {
      const bool equal = read_file_bytes(dir / "plain" / f) == read_file_bytes(dir / "saving" / f);
      EXPECT_TRUE(equal) << wad << " DEMO" << number << ": " << f;
      same += equal;
    }
    std::printf("[ exact    ] %s DEMO%d: saved and loaded at %zu tics, %zu of %zu files byte-identical\n", wad, number,
                tics.size(), same, files.size());
    std::filesystem::remove_all(dir / "plain");
    std::filesystem::remove_all(dir / "saving");
  }
  std::filesystem::remove_all(dir);
}

// Chocolate Doom's save loaded in the middle of the replay: the player's exact values
// after each later tic (stats.csv's raw columns) are Chocolate Doom's after loading it.
TEST(SaveGames, ChocolateDoomsSaveLoadedMidReplayGoesOnAsInChocolateDoom) {
  const auto dir = test::temp_dir("save_chocolate");
  const auto golden = test::source_dir() / "tests/golden/saves";
  DemoGame g = demo_game("freedoom2.wad", read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp"));
  HeadlessOptions o{1, dir, 320, 200};
  o.frames = false;
  o.raw = true;
  o.loads.push_back({300, golden / "recorded_freedoom2_map01_300.dsg"});
  replay_headless(*g.session, g.demo, o);
  // stats.csv row t: after t tics (Chocolate Doom's trace line t - 1).
  std::ifstream csv(dir / "stats.csv");
  std::string line;
  std::getline(csv, line);
  std::map<std::string, size_t> column;
  {
    std::istringstream names(line);
    for (std::string name; std::getline(names, name, ',');) column[name] = column.size();
  }
  std::map<int64_t, std::string> ours;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) f.push_back(v);
    const int64_t tic = std::stoll(f[column["tic"]]) - 1;
    ours[tic] = std::to_string(tic);
    for (const char* name : {"x_raw", "y_raw", "z_raw", "angle_raw", "momx_raw", "momy_raw", "health", "random", "viewz_raw"})
      ours[tic] += " " + f[column[name]];
  }
  std::ifstream trace(golden / "recorded_freedoom2_map01_300.trace");
  size_t compared = 0, synced = 0;
  while (std::getline(trace, line)) {
    if (line.empty() || line[0] == '#') continue;
    const int64_t tic = std::stoll(line.substr(0, line.find(' ')));
    if (synced == compared++ && ours[tic] == line) ++synced;
    else if (synced + 1 == compared) ADD_FAILURE() << "parted at tic " << tic << "\n  ours " << ours[tic] << "\n  doom " << line;
  }
  EXPECT_EQ(compared, 667u);
  EXPECT_EQ(synced, compared);
  std::filesystem::remove_all(dir);
}

TEST(SaveGames, TheSessionSavesAndLoadsWholeOrNotAtAll) {
  const auto golden = test::source_dir() / "tests/golden/saves";
  const std::vector<uint8_t> map02 = read_file_bytes(golden / "freedoom2_demo3_1200.dsg");
  EXPECT_EQ(Session::save_description(map02), "CHOCOLATE");
  EXPECT_EQ(Session::save_description(read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp")),
            std::nullopt);

  Session s(freedoom("freedoom2.wad", "MAP01"), 4);
  for (int t = 0; t < 30; ++t) s.tic(play::TicCmd{25, 0, 0, 0});
  const Session::Pose before = s.pose();
  const uint64_t tics = s.tics();
  // Refused, the game kept: broken bytes, a Doom save of a map freedoom2 lacks.
  std::vector<uint8_t> broken = map02;
  broken.resize(broken.size() / 2);
  EXPECT_THROW(s.load_game(broken, "half.dsg"), Error);
  try {
    s.load_game(read_file_bytes(golden / "freedoom1_demo3_600.dsg"), "e3m3.dsg");
    ADD_FAILURE() << "a Doom save of E3M3 loaded on Doom II";
  } catch (const Error& e) {
    std::printf("[ refused  ] %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("e3m3.dsg: byte "), std::string::npos) << e.what();
  }
  EXPECT_EQ(s.name(), "freedoom2.wad:MAP01");
  EXPECT_EQ(s.pose().pos, before.pos);
  EXPECT_EQ(s.tics(), tics);
  EXPECT_EQ(s.skill(), 4);

  // Loaded: the save's map and skill.
  s.load_game(map02, "map02.dsg");
  EXPECT_EQ(s.name(), "freedoom2.wad:MAP02");
  EXPECT_EQ(s.skill(), 3);
  EXPECT_EQ(s.world().level_time(), 1201);
  EXPECT_EQ(s.tics(), 1201u) << "Doom's save keeps no tic count of ours: the level's time";
  s.tic(play::TicCmd{});
  // Saved again and loaded again with our extension: the same game.
  const std::vector<uint8_t> ours = s.save_game("again");
  EXPECT_EQ(Session::save_description(ours), "again");
  s.tic(play::TicCmd{50, 0, 0, 0});
  s.load_game(ours, "ours.dsg");
  EXPECT_EQ(s.save_game("again"), ours);

  // A hand-made level has no Doom numbers to save.
  Session outpost(test::source_dir() / "maps/outpost.map");
  try {
    outpost.save_game("x");
    ADD_FAILURE() << "saved a .map level";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not a hand-made level"), std::string::npos) << e.what();
  }
  EXPECT_THROW(outpost.load_game(ours, "ours.dsg"), Error);
}

}  // namespace
}  // namespace p3d::game
