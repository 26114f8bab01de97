// Savegames beside Chocolate Doom's: its own saves (tests/golden/saves/*.dsg, made at a
// tic of a demo's playback) load here and the demo's input goes on in sync with
// Chocolate Doom's play after loading them (its trace beside each save), to the last
// tic; our save at the same tic holds the same records, field by field; our saves
// round-trip and, with our extension, go on exactly as the game never saved; and every
// kind of broken save is refused with a located message, never a crash.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/doom_demo.h"
#include "engine/play/savegame.h"
#include "engine/util/bytes.h"
#include "engine/util/file.h"
#include "tests/fuzz/save_map.h"
#include "tests/support/player_trace.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::play {
namespace {

// ---- a demo's game, as the demo sync test plays it

struct Game {
  wad::Stack wads;
  DoomDemo demo;
  std::string map_name;
  std::unique_ptr<level::Level> level;
  GameOptions options;
  std::unique_ptr<DoomNumbers> numbers;
};

std::unique_ptr<Game> open_game(const std::string& wad_file, std::span<const uint8_t> demo_bytes) {
  auto g = std::make_unique<Game>();
  const auto wad = test::freedoom_path(wad_file);
  g->wads = bsp::read_wads({wad});
  g->demo = decode_doom_demo(demo_bytes, "demo");
  g->map_name = g->demo.map_name(g->wads.map("MAP01").has_value());
  g->level = std::make_unique<level::Level>(bsp::open_level(bsp::LevelSource{{}, {wad}, g->map_name}).level);
  g->options = game_options_for(g->wads, g->map_name, g->demo.skill);
  set_demo_game(g->options, g->demo);  // its players, -fast, -respawn, -nomonsters
  g->numbers = std::make_unique<DoomNumbers>(g->wads, *g->level);
  return g;
}

std::unique_ptr<Game> open_demo(const std::string& wad_file, int number) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path(wad_file)});
  const wad::Lump* lump = wads.find("DEMO" + std::to_string(number));
  return open_game(wad_file, lump->bytes);
}

std::unique_ptr<Game> open_recorded() {
  const std::vector<uint8_t> bytes =
      read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp");
  return open_game("freedoom2.wad", bytes);
}

// G_InitNew's world: the map set up anew, the random index cleared.
std::unique_ptr<World> new_world(const Game& g, int skill) {
  GameOptions o = g.options;
  o.skill = skill;
  return std::make_unique<World>(map_from_wads(g.wads, g.map_name, *g.level), *g.level, o, Random{});
}

void play_tic(World& w, const DoomDemo& demo, size_t t) { w.tick_players(players_tic(demo, t)); }

// G_DoLoadGame in the middle of a game.
std::unique_ptr<World> load(const Game& g, const World& before, std::span<const uint8_t> bytes, bool doom_only,
                            LoadedSave* loaded = nullptr) {
  const SaveHeader header = read_save_header(bytes, "save");
  auto w = new_world(g, header.skill);
  carry_over(*w, before, header);
  const LoadedSave l = read_save(*w, bytes, "save", *g.numbers, doom_only);
  if (loaded) *loaded = l;
  return w;
}

// Plays the demo from tic `from` to its end beside the trace's lines of those tics;
// returns how many tics stayed in sync from the first.
size_t in_sync(World& w, const DoomDemo& demo, size_t from, const std::vector<test::PlayerTic>& trace) {
  size_t synced = 0;
  for (size_t t = from; t < demo.tic_count(); ++t) {
    play_tic(w, demo, t);
    const auto line = std::find_if(trace.begin(), trace.end(), [&](const test::PlayerTic& l) { return l.tic == int64_t(t); });
    if (line == trace.end()) break;
    if (!(test::player_tic(w, t) == *line)) {
      std::printf("[ parted   ] at %s\n  doom %s\n", test::describe(test::player_tic(w, t)).c_str(), test::describe(*line).c_str());
      break;
    }
    ++synced;
  }
  return synced;
}

// ---- Chocolate Doom's saves

struct GoldenSave {
  const char* stem;  // tests/golden/saves/<stem>.dsg and .trace
  const char* wad;
  int demo;          // DEMOn, or 0 for the recorded demo
  size_t tic;        // saved after this tic
  bool netgame = false;  // the trace is of every player (tests/support/player_trace.h's NetTrace)
};
constexpr GoldenSave kGoldenSaves[] = {
    {"freedoom1_demo3_600", "freedoom1.wad", 3, 600},
    {"freedoom2_demo3_1200", "freedoom2.wad", 3, 1200},
    {"recorded_freedoom2_map01_300", "freedoom2.wad", 0, 300},
    {"freedm_demo3_1500", "freedm.wad", 3, 1500, true},  // three players, altdeath
};

std::filesystem::path golden(const std::string& name) { return test::source_dir() / "tests/golden/saves" / name; }

std::unique_ptr<Game> game_of(const GoldenSave& s) { return s.demo ? open_demo(s.wad, s.demo) : open_recorded(); }

// The demo played to the end of tic `tic`.
std::unique_ptr<World> played_to(const Game& g, size_t tic) {
  auto w = new_world(g, g.demo.skill);
  for (size_t t = 0; t <= tic; ++t) play_tic(*w, g.demo, t);
  return w;
}

TEST(ChocolateSaves, LoadHereAndPlayTheDemosRestInSyncWithChocolateDoomLoadingThem) {
  for (const GoldenSave& s : kGoldenSaves) {
    if (s.netgame) continue;  // the next test's
    const auto g = game_of(s);
    const auto before = played_to(*g, s.tic);
    const std::vector<uint8_t> bytes = read_file_bytes(golden(std::string(s.stem) + ".dsg"));
    const auto w = load(*g, *before, bytes, false);
    const std::vector<test::PlayerTic> trace = test::read_player_trace(golden(std::string(s.stem) + ".trace"));
    ASSERT_FALSE(trace.empty()) << s.stem;
    EXPECT_EQ(trace.front().tic, int64_t(s.tic + 1)) << s.stem << ": the trace starts after the load";
    EXPECT_EQ(trace.back().tic + 1, int64_t(g->demo.tic_count())) << s.stem << ": and goes to the demo's end";
    const size_t synced = in_sync(*w, g->demo, s.tic + 1, trace);
    std::printf("[ sync     ] %s: %zu of %zu tics after the load in sync with Chocolate Doom\n", s.stem, synced, trace.size());
    EXPECT_EQ(synced, trace.size()) << s.stem;
  }
}

// A netgame's save (FreeDM's DEMO3, three players): every player loaded, and every
// player in sync with Chocolate Doom's play after it loaded the same file.
TEST(ChocolateSaves, ANetgamesSaveLoadsEveryPlayerInSyncWithChocolateDoom) {
  for (const GoldenSave& s : kGoldenSaves) {
    if (!s.netgame) continue;
    const auto g = game_of(s);
    const auto before = played_to(*g, s.tic);
    const auto w = load(*g, *before, read_file_bytes(golden(std::string(s.stem) + ".dsg")), false);
    const test::NetTrace trace = test::read_net_trace(golden(std::string(s.stem) + ".trace"));
    ASSERT_EQ(trace.hashes.size(), g->demo.tic_count()) << s.stem << ": the trace goes to the demo's end";
    size_t synced = 0;
    for (size_t t = s.tic + 1; t < g->demo.tic_count(); ++t, ++synced) {
      play_tic(*w, g->demo, t);
      const std::vector<std::string> ours = test::net_lines(*w, t);
      if (test::net_hash(ours) == trace.hashes[t]) continue;
      ADD_FAILURE() << s.stem << " parted at tic " << t << ":\n  ours " << ours.front();
      break;
    }
    std::printf("[ sync     ] %s: %zu of %zu tics after the load in sync with Chocolate Doom, every player\n", s.stem,
                synced, g->demo.tic_count() - s.tic - 1);
  }
}

// Chocolate Doom leaves some fields as its zone memory happened to hold them (the
// floors' flat and special for the kinds that never read them, the cmd's consistency
// check): those are not compared.
DoomSpecial comparable(DoomSpecial s) {
  if (auto* f = std::get_if<DoomFloor>(&s); f && f->type != int(Floor::Type::kLowerAndChange) && f->type != int(Floor::Type::kDonutRaise))
    f->texture = 0, f->new_special = 0;
  return s;
}

TEST(ChocolateSaves, OurSaveOfTheSameTicHoldsChocolateDoomsRecordsFieldByField) {
  for (const GoldenSave& s : kGoldenSaves) {
    const auto g = game_of(s);
    const auto w = played_to(*g, s.tic);
    const DoomSave ours = doom_save_of(*w, DoomNumbers(g->wads, *g->level), "ours");
    const DoomSave doom = parse_doom_save(read_file_bytes(golden(std::string(s.stem) + ".dsg")), s.stem, w->map());
    EXPECT_EQ(ours.header.skill, doom.header.skill);
    EXPECT_EQ(ours.header.episode, doom.header.episode);
    EXPECT_EQ(ours.header.map, doom.header.map);
    EXPECT_EQ(ours.header.level_time, doom.header.level_time);
    EXPECT_EQ(ours.header.in_game, doom.header.in_game) << s.stem;
    for (size_t p = 0; p < kMaxPlayers; ++p) {
      ASSERT_EQ(ours.players[p].has_value(), doom.players[p].has_value()) << s.stem << " player " << p + 1;
      if (!doom.players[p]) continue;
      DoomPlayer player = *doom.players[p];
      player.consistancy = 0;
      EXPECT_EQ(*ours.players[p], player) << s.stem << " player " << p + 1;
    }
    ASSERT_EQ(ours.sectors.size(), doom.sectors.size());
    for (size_t i = 0; i < ours.sectors.size(); ++i) EXPECT_EQ(ours.sectors[i], doom.sectors[i]) << s.stem << " sector " << i;
    for (size_t i = 0; i < ours.lines.size(); ++i) EXPECT_EQ(ours.lines[i], doom.lines[i]) << s.stem << " line " << i;
    ASSERT_EQ(ours.mobjs.size(), doom.mobjs.size()) << s.stem;
    for (size_t i = 0; i < ours.mobjs.size(); ++i) EXPECT_EQ(ours.mobjs[i], doom.mobjs[i]) << s.stem << " thing " << i;
    ASSERT_EQ(ours.specials.size(), doom.specials.size()) << s.stem;
    for (size_t i = 0; i < ours.specials.size(); ++i)
      EXPECT_TRUE(comparable(ours.specials[i]) == comparable(doom.specials[i])) << s.stem << " special " << i;
    std::printf("[ fields   ] %s: %zu sectors, %zu lines, %zu things, %zu specials compared\n", s.stem, ours.sectors.size(),
                ours.lines.size(), ours.mobjs.size(), ours.specials.size());
  }
}

// ---- our saves

TEST(Saves, DoomsPartRoundTripsByteForByte) {
  const auto g = open_demo("freedoom2.wad", 3);
  const auto w = played_to(*g, 900);
  const DoomSave save = doom_save_of(*w, DoomNumbers(g->wads, *g->level), "round trip");
  const std::vector<uint8_t> bytes = encode_doom_save(save);
  const DoomSave back = parse_doom_save(bytes, "round trip", w->map());
  EXPECT_EQ(encode_doom_save(back), bytes);
  EXPECT_EQ(back.end, bytes.size());
  EXPECT_EQ(back.header.description, "round trip");
}

// Saved and loaded at a few tics, with our extension: the game goes on as if it never
// was, to the demo's end; the save of the loaded game is the save it was loaded from.
TEST(Saves, WithOurExtensionALoadedGameGoesOnExactly) {
  for (const auto& [wad, demo, tics] : {std::tuple{"freedoom1.wad", 3, std::vector<size_t>{0, 333, 900}},
                                        std::tuple{"freedoom2.wad", 1, std::vector<size_t>{150, 777, 1300}},
                                        std::tuple{"freedm.wad", 3, std::vector<size_t>{700, 1500, 2200}}}) {  // 3 players
    const auto g = open_demo(wad, demo);
    const DoomNumbers numbers(g->wads, *g->level);
    auto plain = new_world(*g, g->demo.skill);
    auto saved = new_world(*g, g->demo.skill);
    for (size_t t = 0; t < g->demo.tic_count(); ++t) {
      play_tic(*plain, g->demo, t);
      play_tic(*saved, g->demo, t);
      if (std::find(tics.begin(), tics.end(), t) == tics.end()) continue;
      const std::vector<uint8_t> bytes = write_save(*saved, numbers, "exact", {});
      LoadedSave loaded;
      saved = load(*g, *saved, bytes, false, &loaded);
      EXPECT_TRUE(loaded.extended);
      EXPECT_EQ(write_save(*saved, numbers, "exact", {}), bytes) << wad << " DEMO" << demo << " tic " << t;
    }
    EXPECT_EQ(write_save(*saved, numbers, "end", {}), write_save(*plain, numbers, "end", {}))
        << wad << " DEMO" << demo << ": everything equal at the demo's end";
    EXPECT_EQ(test::net_lines(*saved, 0), test::net_lines(*plain, 0)) << wad << " DEMO" << demo;
  }
}

// Our save loaded as Doom would (ignoring our extension) is Chocolate Doom's save loaded.
TEST(Saves, OursLoadedAsDoomEqualsChocolatesLoaded) {
  const GoldenSave& s = kGoldenSaves[1];
  const auto g = game_of(s);
  const auto before = played_to(*g, s.tic);
  const std::vector<uint8_t> ours = write_save(*before, DoomNumbers(g->wads, *g->level), "ours", {});
  const auto from_ours = load(*g, *before, ours, true);
  const auto from_doom = load(*g, *before, read_file_bytes(golden(std::string(s.stem) + ".dsg")), false);
  const DoomNumbers numbers(g->wads, *g->level);
  EXPECT_EQ(write_save(*from_ours, numbers, "x", {}), write_save(*from_doom, numbers, "x", {}));
}

TEST(Saves, HeaderAndDescription) {
  const auto g = open_recorded();
  const auto w = played_to(*g, 100);
  const std::vector<uint8_t> bytes = write_save(*w, DoomNumbers(g->wads, *g->level), "a very long description that Doom cuts", {});
  const SaveHeader h = read_save_header(bytes, "save");
  EXPECT_EQ(h.description, "a very long description") << "Doom's menu writes 23 characters and a NUL";
  EXPECT_EQ(h.skill, g->demo.skill);
  EXPECT_EQ(h.map, 1);
  EXPECT_EQ(h.level_time, 101);
  EXPECT_EQ(std::string(bytes.begin() + 24, bytes.begin() + 35), "version 109");
  EXPECT_EQ(save_description(bytes), "a very long description");
  EXPECT_EQ(save_description(std::vector<uint8_t>(30, 'x')), std::nullopt);
}

// What Freedoom's demos may not show: a perpetual lift and a crusher stopped in stasis
// (Doom's format drops the lift), fire flickers (not in Doom's format), a switch
// counting down to flip back, strobes, flashes and glows. A corridor east with lines
// that start and stop them, the switch on its east wall.
test::TestMap movers_map() {
  test::TestMap m;
  const int xs[] = {0, 256, 512, 768, 1024, 1536, 1792, 2048};
  for (int i = 0; i < 7; ++i) m.add_room({{xs[i], 0}, {xs[i], 128}, {xs[i + 1], 128}, {xs[i + 1], 0}}, {});
  auto north = [&](int x0, int x1, int y0, test::TestMap::Sector sector) {
    m.add_room({{x0, y0}, {x0, y0 + 128}, {x1, y0 + 128}, {x1, y0}}, sector);
  };
  north(0, 256, 128, {0, 128, "FLOOR", "CEIL", 160, 0, 1});        // the perpetual lift
  north(0, 256, 256, {64, 192, "STEP", "CEIL", 160, 0, 0});         // its top
  north(256, 512, 128, {0, 128, "FLOOR", "CEIL", 160, 0, 2});      // the crusher
  north(256, 512, 256, {0, 128, "FLOOR", "CEIL", 200, 8, 0});      // a glow
  north(512, 768, 128, {0, 128, "NUKAGE1", "CEIL", 192, 17, 0});   // a fire flicker
  north(768, 1024, 128, {0, 128, "FLOOR", "F_SKY1", 192, 1, 0});   // a flash
  north(1024, 1536, 128, {0, 128, "FLOOR", "CEIL", 192, 2, 0});    // a strobe
  north(1792, 2048, 128, {64, 192, "STEP", "CEIL", 160, 0, 3});    // the switch's lift
  // Start the lift (W1 53) and the crusher (W1 6), stop them (W1 54, 57), start them
  // again from stasis (WR 87, 73).
  const std::pair<int, int> crossings[] = {{256, 53}, {512, 6}, {768, 54}, {1024, 57}, {1536, 87}, {1792, 73}};
  for (const auto& [x, special] : crossings) {
    test::TestMap::Line& l = m.line_at({x, 0}, {x, 128});
    l.special = special;
    l.tag = special == 53 || special == 54 || special == 87 ? 1 : 2;
  }
  test::TestMap::Line& sw = m.line_at({2048, 128}, {2048, 0});
  sw.special = 62;  // SR: the lift down, the switch back after a second
  sw.tag = 3;
  m.sides[size_t(sw.front)].middle = "SW1BRCOM";
  m.things.push_back({64, 64, 0, 1});
  return m;
}

// The test art with Doom's switch pair SW1BRCOM and SW2BRCOM in a TEXTURE2 (Doom knows
// its switches by name), numbered after TEXTURE1's.
wad::Stack movers_wad() {
  ByteWriter textures;
  textures.u32(2), textures.u32(12), textures.u32(12 + 32);
  for (const auto& [name, patch] : {std::pair{"SW1BRCOM", 0}, std::pair{"SW2BRCOM", 2}}) {
    textures.raw(std::span(reinterpret_cast<const uint8_t*>(name), 8));
    textures.u32(0), textures.u16(64), textures.u16(72), textures.u32(0), textures.u16(1);  // one patch
    textures.u16(0), textures.u16(0), textures.u16(uint16_t(patch)), textures.u16(1), textures.u16(0);
  }
  test::WadWriter w(true);
  test::add_test_art(w);
  w.lump("TEXTURE2", textures.release());
  movers_map().add_to(w, "MAP01");
  wad::Stack stack;
  stack.add(wad::Wad(w.bytes(), "movers.wad"));
  return stack;
}

TEST(Saves, LiftsAndCrushersInStasisFlickersAndSwitchesGoOnExactly) {
  const wad::Stack wads = movers_wad();
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  const GameOptions options = game_options_for(wads, "MAP01", 3);
  const DoomNumbers numbers(wads, level);
  auto fresh = [&] { return std::make_unique<World>(map_from_wads(wads, "MAP01", level), level, options, Random{}); };
  // Run east, pressing use at the far wall.
  auto input = [](const World& w, int t) {
    return TicCmd{50, 0, 0, uint8_t(w.player().mo->x > 1950 * kFracUnit && t % 2 ? kBtUse : 0)};
  };
  struct Seen {
    bool lift_stopped = false, crusher_stopped = false, flicker = false, button = false;
  };
  auto seen = [](const World& w) {
    Seen s;
    for (const Plat* p : w.active_plats_) s.lift_stopped |= p && !p->active;
    for (const Ceiling* c : w.active_ceilings_) s.crusher_stopped |= c && !c->active;
    for (const World::Button& b : w.buttons_) s.button |= b.timer > 0;
    s.flicker = w.thinker_count() > w.things().size() + 4;
    return s;
  };
  const int tics = 260;
  auto plain = fresh();
  int stasis = -1, button = -1;
  for (int t = 0; t < tics; ++t) {
    plain->tick(input(*plain, t));
    const Seen s = seen(*plain);
    if (stasis < 0 && s.lift_stopped && s.crusher_stopped && s.flicker) stasis = t + 5;
    if (button < 0 && s.button) button = t + 2;
  }
  ASSERT_GT(stasis, 0) << "the lift and the crusher stopped";
  ASSERT_GT(button, stasis) << "then the switch counts";
  const std::vector<int> save_tics = {20, 45, stasis, button};

  auto saved = fresh();
  auto again = fresh();
  for (int t = 0; t < tics; ++t) {
    saved->tick(input(*saved, t));
    if (std::find(save_tics.begin(), save_tics.end(), t) == save_tics.end()) continue;
    const std::vector<uint8_t> bytes = write_save(*saved, numbers, "movers", {});
    if (t == stasis) {
      const DoomSave doom = parse_doom_save(bytes, "movers", saved->map());
      EXPECT_TRUE(std::none_of(doom.specials.begin(), doom.specials.end(), [](const DoomSpecial& sp) {
        return std::holds_alternative<DoomPlat>(sp) && std::get<DoomPlat>(sp).sector == 7;
      })) << "Doom's format drops the lift in stasis (sector 7)";
      EXPECT_TRUE(std::any_of(doom.specials.begin(), doom.specials.end(), [](const DoomSpecial& sp) {
        return std::holds_alternative<DoomCeiling>(sp) && !std::get<DoomCeiling>(sp).thinking;
      })) << "and keeps a crusher in stasis, without its function";
    }
    const SaveHeader header = read_save_header(bytes, "movers");
    if (t == button) {  // as Doom loads it: every texture and flat by Doom's numbers, back to the level's
      auto doom = fresh();
      carry_over(*doom, *saved, header);
      EXPECT_TRUE(read_save(*doom, bytes, "movers", numbers, true).warnings.empty());
      for (size_t i = 0; i < saved->map().sides.size(); ++i) {
        const Side &a = saved->map().sides[i], &b = doom->map().sides[i];
        EXPECT_EQ(std::tuple(a.top, a.middle, a.bottom), std::tuple(b.top, b.middle, b.bottom)) << "side " << i;
      }
      for (size_t i = 0; i < saved->map().sectors.size(); ++i) {
        const Sector &a = saved->map().sectors[i], &b = doom->map().sectors[i];
        EXPECT_EQ(std::pair(a.floor_pic, a.ceiling_pic), std::pair(b.floor_pic, b.ceiling_pic)) << "sector " << i;
      }
      const auto sw_line = std::find_if(saved->map().lines.begin(), saved->map().lines.end(), [](const Line& l) { return l.special == 62; });
      const int sw = sw_line->side[0];
      EXPECT_EQ(level.textures[size_t(doom->map().sides[size_t(sw)].middle)].name, "SW2BRCOM") << "the switch, on";
    }
    auto loaded = fresh();
    carry_over(*loaded, *saved, header);
    read_save(*loaded, bytes, "movers", numbers);
    EXPECT_EQ(write_save(*loaded, numbers, "movers", {}), bytes) << "tic " << t;
    saved = std::move(loaded);
  }
  EXPECT_EQ(write_save(*saved, numbers, "end", {}), write_save(*plain, numbers, "end", {}));
  EXPECT_EQ(saved->state().sectors.size(), plain->state().sectors.size());
  for (size_t i = 0; i < plain->map().sectors.size(); ++i) {
    EXPECT_EQ(saved->map().sectors[i].floor_height, plain->map().sectors[i].floor_height) << "sector " << i;
    EXPECT_EQ(saved->map().sectors[i].ceiling_height, plain->map().sectors[i].ceiling_height) << "sector " << i;
    EXPECT_EQ(saved->map().sectors[i].light, plain->map().sectors[i].light) << "sector " << i;
  }
}

// fuzz_save's seed is a save of its map after a second of play (P3D_WRITE_SEEDS=1
// writes it anew when the format changes).
TEST(Saves, TheFuzzSeedIsASaveOfTheFuzzMap) {
  const wad::Stack wads = fuzz::save_map_wads();
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  World w(map_from_wads(wads, "MAP01", level), level, game_options_for(wads, "MAP01", 3), Random{});
  for (int t = 0; t < 35; ++t) w.tick(TicCmd{25, 0, 128, uint8_t(t == 20 ? kBtAttack : 0)});
  const std::vector<uint8_t> bytes = write_save(w, DoomNumbers(wads, level), "fuzz seed", {});
  const auto seed = test::source_dir() / "tests/fuzz/seeds/room.dsg";
  if (std::getenv("P3D_WRITE_SEEDS")) write_file_atomically(seed, bytes);
  EXPECT_EQ(read_file_bytes(seed), bytes) << "P3D_WRITE_SEEDS=1 writes it anew";
}

// A save of our extension's first version (without the blockmap's header) loads with
// the map's own header, as the same save in today's version does.
TEST(Saves, AFirstVersionExtensionLoadsAsToday) {
  const wad::Stack wads = fuzz::save_map_wads();
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  const DoomNumbers numbers(wads, level);
  auto loaded = [&](const std::filesystem::path& file) {
    World w(map_from_wads(wads, "MAP01", level), level, game_options_for(wads, "MAP01", 3), Random{});
    EXPECT_TRUE(read_save(w, read_file_bytes(file), file.string(), numbers).extended) << file;
    return write_save(w, numbers, "fuzz seed", {});
  };
  const std::vector<uint8_t> today = loaded(test::source_dir() / "tests/fuzz/seeds/room.dsg");
  EXPECT_EQ(loaded(test::source_dir() / "tests/golden/saves/room_extension_v1.dsg"), today);
}

// ---- broken saves: refused with "<what>: byte N: ...", never a crash

class BrokenSaves : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    game_ = open_recorded().release();
    before_ = played_to(*game_, 400).release();
    bytes_ = new std::vector<uint8_t>(write_save(*before_, DoomNumbers(game_->wads, *game_->level), "broken", {}));
    doom_ = new DoomSave(parse_doom_save(*bytes_, "save", before_->map()));
  }
  static void TearDownTestSuite() {
    delete doom_;
    delete bytes_;
    delete before_;
    delete game_;
  }
  // The message loading these bytes gives, or "" when they load.
  static std::string message(std::span<const uint8_t> bytes, bool doom_only = false) {
    try {
      load(*game_, *before_, bytes, doom_only);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  static std::vector<uint8_t> with_u32(std::vector<uint8_t> b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
    return b;
  }
  // Our extension's payload changed at `offset` and its checksum made right again.
  static std::vector<uint8_t> with_payload_u32(size_t offset, uint32_t v) {
    std::vector<uint8_t> b = with_u32(*bytes_, doom_->end + 24 + offset, v);
    const uint64_t sum = fnv1a64(std::span(b).subspan(doom_->end + 24));
    for (int i = 0; i < 8; ++i) b[doom_->end + 16 + size_t(i)] = uint8_t(sum >> (8 * i));
    return b;
  }
  static Game* game_;
  static World* before_;
  static std::vector<uint8_t>* bytes_;
  static DoomSave* doom_;
};
Game* BrokenSaves::game_ = nullptr;
World* BrokenSaves::before_ = nullptr;
std::vector<uint8_t>* BrokenSaves::bytes_ = nullptr;
DoomSave* BrokenSaves::doom_ = nullptr;

TEST_F(BrokenSaves, TheUnbrokenSaveLoads) { EXPECT_EQ(message(*bytes_), ""); }

TEST_F(BrokenSaves, TruncatedInEverySection) {
  const DoomSave& d = *doom_;
  const size_t ends[] = {0, 10, 30, 45, 49, d.player_at + 100, d.world_at + 3, d.world_at + d.sectors.size() * 14 + 5,
                         d.thinkers_at, d.mobj_at[0] + 77, d.mobj_at.back() + 153, d.specials_at, d.end - 1,
                         d.end + 5, d.end + 30, d.end + 200, bytes_->size() - 1};
  for (size_t end : ends) {
    const std::string m = message(std::span(*bytes_).first(end));
    EXPECT_NE(m.find("save: byte "), std::string::npos) << "cut at " << end << ": " << m;
    EXPECT_NE(m.find("truncated"), std::string::npos) << "cut at " << end << ": " << m;
  }
}

TEST_F(BrokenSaves, WrongVersionMagicClassStateTypeAndSector) {
  const DoomSave& d = *doom_;
  auto expect = [&](const std::vector<uint8_t>& b, const std::string& part, bool doom_only = false) {
    const std::string m = message(b, doom_only);
    EXPECT_NE(m.find(part), std::string::npos) << "expected \"" << part << "\" in: " << m;
  };
  std::vector<uint8_t> b = *bytes_;
  b[32] = '5';  // "version 105"
  expect(b, "save: byte 24: not a Doom v1.9 savegame");
  b = *bytes_;
  b[40] = 7;
  expect(b, "byte 40: skill 7");
  b = *bytes_;
  b[44] = 2;
  expect(b, "byte 43: players in the game 1 2 0 0");
  b = *bytes_;
  b[43] = 0;
  expect(b, "byte 43: players in the game 0 0 0 0");
  b = *bytes_;
  b[44] = 1;  // a second player whose record is not there: the world's bytes read as one
  expect(b, "the player's state");
  b = *bytes_;
  b[d.mobj_at[2] + 154] = 9;  // the class byte after a thing's record
  expect(b, "unknown thinker class 9");
  expect(with_u32(*bytes_, d.mobj_at[2] + 100, 99999), "byte " + std::to_string(d.mobj_at[2] + 100) + ": a thing's state 99999");
  expect(with_u32(*bytes_, d.mobj_at[2] + 88, 400), "a thing's type 400");
  expect(with_u32(*bytes_, d.mobj_at[2] + 36, uint32_t(-1)), "a thing's sprite -1");
  expect(with_u32(*bytes_, d.player_at + 4, 3), "the player's state 3");
  expect(with_u32(*bytes_, d.player_at + 112, 77), "the weapon in hand 77");
  ASSERT_FALSE(d.specials.empty());
  expect(with_u32(*bytes_, d.special_at[0] + 12 + (d.specials[0].index() == 0 || d.specials[0].index() == 1 ? 4 : d.specials[0].index() == 2 ? 8 : 0), 100000),
         "sector 100000 is out of range");
  b = *bytes_;
  b[d.specials_at] = 42;
  expect(b, "unknown special class 42");
  b = *bytes_;
  b[d.end - 1] = 0x1c;
  expect(b, "Doom's end marker is 0x1d, not 0x1c");
  b = *bytes_;
  b[d.end] = 'X';
  expect(b, "byte " + std::to_string(d.end) + ": bytes after Doom's end marker that are not our extension");
  expect(b, "", true);  // as Doom would: what follows the end marker is not read
  expect(with_u32(*bytes_, d.end + 8, 3), "our extension's version 3");
  b = *bytes_;
  b.back() ^= 1;
  expect(b, "our extension's checksum does not match");
  b = *bytes_;
  b.push_back(0);
  expect(b, "1 bytes after our extension");
  expect(with_payload_u32(0, 12345), "our extension was written on another level");
}

TEST_F(BrokenSaves, CountsThatDoNotFitTheMap) {
  // Where our extension's sector count stands (savegame.cpp's layout): the fingerprint,
  // the game's extras (no message), the World's state (no boss brain spots), the
  // player's attacker and message.
  const size_t sectors_at = 8 + (8 + 4 + 4 + 1 + 20 + 9 + 40) + (2 + 4 + 4 + 1 + 1 + 4 + 12 + 1 + 4 + 4) + 4 + 4 +
                            before_->player().message.size();
  const uint32_t sectors = uint32_t(before_->map().sectors.size());
  ASSERT_EQ(std::memcmp(bytes_->data() + doom_->end + 24 + sectors_at, &sectors, 4), 0);
  std::string m = message(with_payload_u32(sectors_at, sectors + 1));
  EXPECT_NE(m.find(std::to_string(sectors + 1) + " sectors in our extension, " + std::to_string(sectors) + " in the map"),
            std::string::npos)
      << m;
  m = message(with_payload_u32(sectors_at + 4, 0x7fffffff));  // the first sector's floor
  EXPECT_NE(m.find("a sector's floor 2147483647 is out of range (-536870912..536870912)"), std::string::npos) << m;
  m = message(with_payload_u32(sectors_at + 4, 0x12340000));  // a floor that may be
  EXPECT_EQ(m, "");
  // Then each sector (7 numbers, its sound target and mover, its things), the sides (5
  // numbers each), the lines.
  size_t sides_at = sectors_at + 4;
  for (const Sector& sec : before_->map().sectors) {
    sides_at += 4 * 7 + 4 + 4 + 4;
    for (const Mobj* t = sec.thing_list; t; t = t->snext) sides_at += 4;
  }
  const uint32_t sides = uint32_t(before_->map().sides.size()), lines = uint32_t(before_->map().lines.size());
  m = message(with_payload_u32(sides_at, sides - 1));
  EXPECT_NE(m.find(std::to_string(sides - 1) + " sides in our extension, " + std::to_string(sides) + " in the map"), std::string::npos) << m;
  m = message(with_payload_u32(sides_at + 4 + 20 * sides, 70000));
  EXPECT_NE(m.find("70000 lines in our extension, " + std::to_string(lines) + " in the map"), std::string::npos) << m;
  m = message(with_payload_u32(sides_at + 4 + 20 * sides + 4 + 12 * lines, uint32_t(doom_->mobjs.size() + 3)));
  EXPECT_NE(m.find(" things in our extension, " + std::to_string(doom_->mobjs.size()) + " in Doom's part"), std::string::npos) << m;
  m = message(with_payload_u32(sides_at + 4 + 2 * 4, 9999));  // the first side's top texture
  EXPECT_NE(m.find("a texture 9999 is out of range"), std::string::npos) << m;
  // Doom's part for another map: too few sectors and lines for the file.
  std::vector<uint8_t> cut(bytes_->begin(), bytes_->begin() + std::ptrdiff_t(doom_->world_at + 14 * 3));
  m = message(cut);
  EXPECT_NE(m.find("truncated in the sectors"), std::string::npos) << m;
}

// Random damage anywhere (a byte changed, bytes cut or doubled) in a save of the fuzz
// target's small map: a message or a game, never a crash.
TEST(Saves, RandomDamageNeverCrashes) {
  const wad::Stack wads = fuzz::save_map_wads();
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  const GameOptions options = game_options_for(wads, "MAP01", 3);
  const DoomNumbers numbers(wads, level);
  World before(map_from_wads(wads, "MAP01", level), level, options, Random{});
  for (int t = 0; t < 35; ++t) before.tick(TicCmd{25, 0, 128, uint8_t(t == 20 ? kBtAttack : 0)});
  const std::vector<uint8_t> bytes = write_save(before, numbers, "damaged", {});
  Rng rng(20240611);
  std::printf("seed 20240611\n");
  int refused = 0;
  const int runs = 300;
  for (int i = 0; i < runs; ++i) {
    std::vector<uint8_t> b = bytes;
    const size_t at = size_t(rng.below(b.size()));
    switch (i % 3) {
      case 0: b[at] = uint8_t(rng.below(256)); break;
      case 1: b.resize(at); break;
      default: b.insert(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at / 2), b.begin() + std::ptrdiff_t(at)); break;
    }
    // The Doom part alone too: a damaged byte there may still load, as Doom would.
    for (bool doom_only : {false, true}) {
      try {
        World w(map_from_wads(wads, "MAP01", level), level, options, Random{});
        carry_over(w, before, read_save_header(b, "save"));
        read_save(w, b, "save", numbers, doom_only);
        for (int t = 0; t < 20; ++t) w.tick(TicCmd{25, 0, 256, 0});
      } catch (const Error& e) {
        ++refused;
        EXPECT_NE(std::string(e.what()).find("save: byte "), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GT(refused, runs / 2);
}

TEST(Saves, AHandMadeLevelIsRefused) {
  const level::Level level = bsp::load_level(test::source_dir() / "maps/outpost.map");
  GameOptions o;
  o.map = 0;
  World w(map_from_level(level), level, o, Random{});
  EXPECT_NE(why_not_savable(w).find("no WAD map"), std::string::npos);
}

}  // namespace
}  // namespace p3d::play
