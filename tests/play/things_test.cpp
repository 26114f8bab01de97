// Things on their state clocks in a real level (Freedoom's MAP01): every thing
// placed animates through the frames of its idle loop, as Doom's would, and the
// renderers agree with the reference on every frame of it.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "engine/bsp/load.h"
#include "engine/play/info.h"
#include "engine/play/things.h"
#include "engine/render/renderer.h"
#include "engine/sim/sim.h"
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
  for (int tic = 0; tic < 140; ++tic) {
    clocks.tick(state);
    ASSERT_EQ(state.thing_sprites.size(), level.things.size());
    for (uint32_t i = 0; i < level.things.size(); ++i) {
      const level::Thing& t = level.things[i];
      if (t.sprite == level::kNone || !state.things[i]) continue;  // never drawn, or not at this skill
      const level::SpriteFrame& first = level.sprite_frames[size_t(t.sprite)];
      const level::SpriteFrame& now = level.sprite_frames[size_t(state.thing_sprites[i])];
      ASSERT_EQ(now.name.substr(0, 4), first.name.substr(0, 4)) << "thing " << i << ": its reach covers its own sprite";
      ASSERT_EQ(now.hanging, first.hanging);
      ASSERT_EQ(now.drop, first.drop);
      seen[i].insert(now.name);
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
  sim::World a(level), b(level);
  sim::Player pa = a.spawn(), pb = b.spawn();
  Rng rng(5);
  for (int tic = 0; tic < 70; ++tic) {
    a.tick(pa, {});
    b.tick(pb, {});
    ASSERT_EQ(a.state().thing_sprites, b.state().thing_sprites) << "tic " << tic;
    if (tic % 10 != 9) continue;
    const render::Camera c = test::random_camera(level, rng);
    render::Frame bsp(96, 60), reference(96, 60);
    render::make_renderer("bsp", {.threads = 2})->render(level, a.state(), c, bsp);
    render::make_renderer("reference")->render(level, a.state(), c, reference);
    EXPECT_EQ(bsp.pixels, reference.pixels) << "tic " << tic;
  }
}

}  // namespace
}  // namespace p3d::play
