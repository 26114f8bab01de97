// Things on their state clocks in a real level (Freedoom's MAP01): every thing
// placed animates through the frames of its idle loop, as Doom's would, and the
// renderers agree with the reference on every frame of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "engine/bsp/load.h"
#include "engine/play/info.h"
#include "engine/play/things.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

const level::Level& map01() {
  static const level::Level level =
      bsp::open_level(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"}).level;
  return level;
}

TEST(ThingClocks, PlacedThingsShowTheirIdleLoopsFrames) {
  const level::Level& level = map01();
  level::State state = level::start_state(level);
  Random random;
  ThingClocks clocks(level, state, random);
  ASSERT_GT(clocks.size(), 50u);
  // Doom draws one number for each thing spawned and one for each timed first state.
  EXPECT_GE(random.play_index(), clocks.size() % 256);

  std::map<uint32_t, std::set<std::string>> seen;  // thing -> frames shown over 4 seconds
  const size_t shown = state.things.size();
  for (int tic = 0; tic < 140; ++tic) {
    clocks.tick(state);
    ASSERT_EQ(state.things.size(), shown) << "nothing comes or goes";
    for (const level::ShownThing& entry : state.things) {
      ASSERT_NE(entry.placed, level::kNone);
      const level::Thing& t = level.things[size_t(entry.placed)];
      if (t.sprite == level::kNone) continue;  // never drawn
      const level::SpriteFrame& first = level.sprite_frames[size_t(t.sprite)];
      const level::SpriteFrame& now = level.sprite_frames[size_t(entry.frame)];
      ASSERT_EQ(now.hanging, first.hanging);
      ASSERT_EQ(now.drop, first.drop);
      seen[uint32_t(entry.placed)].insert(now.name);
    }
  }
  int animated = 0, checked = 0;
  for (const auto& [i, frames] : seen) {
    const ThingType type = thing_type_for_editor_number(level.things[i].type);
    ASSERT_NE(type, ThingType::kCount);
    // The frames the thing's loop shows (its states of positive tics from the first on).
    std::set<std::string> loop;
    std::set<StateId> visited;
    for (StateId s = thing_info(type).spawn; s != StateId::kNull && visited.insert(s).second; s = state_info(s).next)
      if (state_info(s).tics != 0)
        loop.insert(std::string(kSpriteNames[size_t(state_info(s).sprite)]) + char('A' + state_info(s).frame));
    EXPECT_EQ(frames, loop) << "thing " << i << " (type " << level.things[i].type << ") over 140 tics";
    animated += frames.size() > 1;
    ++checked;
  }
  EXPECT_GT(animated, 20) << "monsters breathe, lamps flicker, pickups blink";
}

TEST(ThingClocks, RenderersAgreeOnAnimatedThingsAndReplaysRepeat) {
  const level::Level& level = map01();
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  World a(map_from_wads(wads, "MAP01", level), level, GameOptions{}, Random{});
  World b(map_from_wads(wads, "MAP01", level), level, GameOptions{}, Random{});
  Rng rng(5);
  for (int tic = 0; tic < 70; ++tic) {
    a.tick({});
    b.tick({});
    ASSERT_EQ(a.state().things.size(), b.state().things.size()) << "tic " << tic;
    for (size_t k = 0; k < a.state().things.size(); ++k)
      ASSERT_EQ(a.state().things[k].frame, b.state().things[k].frame) << "tic " << tic << " thing " << k;
    if (tic % 10 != 9) continue;
    const render::Camera c = test::random_camera(level, rng);
    render::Frame bsp(96, 60), reference(96, 60);
    render::make_renderer("bsp", {.threads = 2})->render(level, a.state(), c, bsp);
    render::make_renderer("reference")->render(level, a.state(), c, reference);
    EXPECT_EQ(bsp.pixels, reference.pixels) << "tic " << tic;
  }
}

// What the importer must embed for the world to come: a zombieman's every state
// (its death among them) and the clip it drops; on every map, puffs and blood.
TEST(ThingFrames, ReachableFramesFollowStatesAndWhatTheySpawn) {
  auto has = [](const std::vector<wad::FrameName>& frames, const std::string& sprite, char frame) {
    return std::any_of(frames.begin(), frames.end(),
                       [&](const wad::FrameName& f) { return f.sprite == sprite && f.frame == frame; });
  };
  const std::vector<wad::FrameName> zombieman = reachable_frames(3004);
  for (char f = 'A'; f <= 'U'; ++f) EXPECT_TRUE(has(zombieman, "POSS", f)) << "POSS" << f;  // stand, walk, attack, pain, deaths
  EXPECT_TRUE(has(zombieman, "CLIP", 'A')) << "the clip it drops";
  EXPECT_TRUE(has(zombieman, "BLUD", 'A')) << "it bleeds";
  EXPECT_TRUE(has(zombieman, "PUFF", 'A')) << "its bullets hit walls";
  EXPECT_EQ(zombieman.front().sprite, "POSS") << "its own frames first";
  std::set<std::string> distinct;
  for (const wad::FrameName& f : zombieman) distinct.insert(f.sprite + f.frame + (f.bright ? "*" : ""));
  EXPECT_EQ(distinct.size(), zombieman.size()) << "each frame once";

  const std::vector<wad::FrameName> imp = reachable_frames(3001);
  EXPECT_TRUE(has(imp, "BAL1", 'C')) << "its fireball's explosion";
  const std::vector<wad::FrameName> spitter = reachable_frames(89);  // the boss's cube shooter
  for (const char* monster : {"TROO", "SARG", "PAIN", "HEAD", "VILE", "SKEL", "BOS2", "FATT", "BSPI", "BOSS", "FIRE", "SKUL"})
    EXPECT_TRUE(has(spitter, monster, 'A')) << monster << ": what its cubes may make, and what those make";
  EXPECT_TRUE(has(reachable_frames(88), "MISL", 'B')) << "the brain explodes in rockets";
  EXPECT_TRUE(reachable_frames(9999).empty());

  const std::vector<wad::FrameName> always = always_frames();
  for (const char* sprite : {"PUFF", "BLUD", "PLAY", "TFOG", "IFOG", "MISL", "PLSS", "PLSE", "BFS1", "BFE1", "BFE2"})
    EXPECT_TRUE(has(always, sprite, 'A')) << sprite;
  EXPECT_FALSE(has(always, "POSS", 'A'));
}

// A WAD map carries every frame its things may show: a zombieman's death on MAP01.
TEST(ThingFrames, TheImporterEmbedsThem) {
  const level::Level& level = map01();
  auto has = [&](const std::string& name) {
    return std::any_of(level.sprite_frames.begin(), level.sprite_frames.end(),
                       [&](const level::SpriteFrame& f) { return f.name == name; });
  };
  for (const char* name : {"POSSH", "POSSL", "POSSU", "CLIPA", "PUFFA", "BLUDC", "PLAYN", "TFOGJ", "MISLB", "BFE2D"})
    EXPECT_TRUE(has(name)) << name;
}

}  // namespace
}  // namespace p3d::play
