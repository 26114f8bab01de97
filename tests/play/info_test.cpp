// Doom's thing table and the state machine that walks it: the table is whole and
// consistent, agrees with the importer's own table of placed things (written from
// another source), every sprite frame it names is in Freedoom, and things animate
// and pass through zero-tic states as Doom's do.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "engine/bsp/load.h"
#include "engine/play/info.h"
#include "engine/play/state_machine.h"
#include "engine/wad/things.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

constexpr size_t kStateCount = size_t(StateId::kCount);

TEST(Info, EveryReferenceLeadsToAStateTypeOrSoundThatExists) {
  EXPECT_EQ(kStateCount, 967u);  // Doom II's table, which holds Doom's
  EXPECT_EQ(size_t(ThingType::kCount), 137u);
  for (const StateInfo& s : kStates) {
    EXPECT_LT(size_t(s.sprite), size_t(Sprite::kCount));
    EXPECT_LT(size_t(s.next), kStateCount);
    EXPECT_LT(s.frame, 29) << "frames A to \\";
    EXPECT_GE(s.tics, kInfiniteTics);
  }
  for (const ThingInfo& t : kThingTypes) {
    for (StateId s : {t.spawn, t.see, t.pain, t.melee, t.missile, t.death, t.extreme_death, t.raise})
      EXPECT_LT(size_t(s), kStateCount);
    for (Sound s : {t.see_sound, t.attack_sound, t.pain_sound, t.death_sound, t.active_sound})
      EXPECT_LT(size_t(s), size_t(Sound::kCount));
    if (t.spawn == StateId::kNull) {  // only the invisible markers start nowhere
      EXPECT_TRUE(t.flags & kNosector) << t.editor_number;
    }
    EXPECT_GT(t.radius, 0);
  }
  for (const SoundInfo& s : kSounds) EXPECT_LT(size_t(s.link), size_t(Sound::kCount));
  EXPECT_EQ(std::string(kSounds[size_t(Sound::kPistol)].name), "pistol");
  EXPECT_EQ(kSounds[size_t(Sound::kChgun)].link, Sound::kPistol) << "the chaingun plays the pistol's sound";
}

TEST(Info, AgreesWithTheImportersTableOfPlacedThings) {
  int compared = 0;
  for (const wad::ThingInfo& w : wad::thing_table()) {
    const ThingType type = thing_type_for_editor_number(w.type);
    ASSERT_NE(type, ThingType::kCount) << "editor number " << w.type;
    const ThingInfo& t = thing_info(type);
    const StateInfo& spawn = state_info(t.spawn);
    EXPECT_EQ(std::string(kSpriteNames[size_t(spawn.sprite)]), w.sprite) << w.type;
    EXPECT_EQ(spawn.frame, w.frame - 'A') << w.type;
    EXPECT_EQ(spawn.bright, w.bright) << w.type;
    EXPECT_EQ(t.radius, to_fixed(w.radius)) << w.type;
    EXPECT_EQ((t.flags & kSpawnceiling) != 0, w.hanging) << w.type;
    if (w.kind == wad::ThingKind::kMonster) {
      EXPECT_TRUE(t.flags & kShootable) << w.type;
    }
    ++compared;
  }
  EXPECT_GT(compared, 100);
  EXPECT_EQ(thing_type_for_editor_number(3001), ThingType::kTroop);
  EXPECT_EQ(thing_type_for_editor_number(1), ThingType::kPlayer);
  EXPECT_EQ(thing_type_for_editor_number(12345), ThingType::kCount);
}

// Every frame of every state is drawable: Freedoom has a lump for it, either one
// picture for all angles (rotation 0) or one per rotation (some mirrored: A2A8).
TEST(Info, FreedoomHasEverySpriteFrameTheStatesShow) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  std::set<std::string> frames;  // "TROOA": a frame with some picture
  for (const wad::Lump* lump : wads.namespace_lumps({"S", "SS"})) {
    const std::string& name = lump->name;
    if (name.size() >= 6) frames.insert(name.substr(0, 5));
    if (name.size() >= 8) frames.insert(name.substr(0, 4) + name[6]);
  }
  for (size_t i = 1; i < kStateCount; ++i) {
    const StateInfo& s = kStates[i];
    if (s.tics == 0) continue;  // passed through within a tic: never shown
    const std::string frame = std::string(kSpriteNames[size_t(s.sprite)]) + char('A' + s.frame);
    EXPECT_TRUE(frames.count(frame)) << "state " << i << " shows " << frame;
  }
}

TEST(StateMachine, AnImpBreathesEveryTenTicsAndABarrelBubbles) {
  auto ignore = [](StateClock&, Action) {};
  StateClock imp;
  ASSERT_TRUE(enter_state(imp, thing_info(ThingType::kTroop).spawn, ignore));
  std::string shown;
  for (int tic = 0; tic < 40; ++tic) {
    if (tic % 10 == 0) shown += char('A' + imp.info().frame);
    ASSERT_TRUE(advance_state(imp, ignore));
  }
  EXPECT_EQ(shown, "ABAB");
  StateClock barrel;
  enter_state(barrel, thing_info(ThingType::kBarrel).spawn, ignore);
  EXPECT_EQ(barrel.tics, 6);
  for (int tic = 0; tic < 6; ++tic) advance_state(barrel, ignore);
  EXPECT_EQ(barrel.info().frame, 1);
}

TEST(StateMachine, ZeroTicStatesPassAtOnceAndEachActionRuns) {
  // The pistol's firing: kPistol1 (4 tics) leads on to states with actions.
  std::vector<Action> ran;
  auto record = [&](StateClock&, Action a) { ran.push_back(a); };
  StateClock clock;
  // S_LIGHTDONE has 0 tics and an action, then kNull: the thing is removed at once.
  EXPECT_FALSE(enter_state(clock, StateId::kLightdone, record));
  EXPECT_EQ(ran, std::vector<Action>{Action::kLight0});
  EXPECT_EQ(clock.state, StateId::kNull);
  // An action that moves the clock: Doom goes on from the state it entered.
  ran.clear();
  auto jump = [&](StateClock& c, Action a) {
    ran.push_back(a);
    if (ran.size() == 1) c = {StateId::kTrooRun1, 0};  // the first action moves the clock, leaving 0 tics
  };
  ASSERT_TRUE(enter_state(clock, StateId::kTrooStnd, jump));
  EXPECT_EQ(clock.state, StateId::kTrooStnd2) << "on from the state entered, not from the one the action set";
  EXPECT_EQ(ran.size(), 2u);
}

// Things placed in maps never vanish of their own accord, and every one of them
// animates in a loop of positive tics (or stands still); but for Doom's dead lost
// soul (23), which starts in the last frames of a dying soul and is gone after 6 tics.
TEST(StateMachine, PlacedThingsLoopForEver) {
  auto ignore = [](StateClock&, Action) {};
  StateClock soul = spawn_clock(thing_info(thing_type_for_editor_number(23)).spawn);
  for (int tic = 0; tic < 5; ++tic) EXPECT_TRUE(advance_state(soul, ignore));
  EXPECT_FALSE(advance_state(soul, ignore));
  for (size_t t = 0; t < size_t(ThingType::kCount); ++t) {
    const ThingInfo& info = kThingTypes[t];
    if (info.editor_number <= 0 || info.editor_number == 23) continue;
    StateClock clock = spawn_clock(info.spawn);
    for (int tic = 0; tic < 35 * 60; ++tic) ASSERT_TRUE(advance_state(clock, ignore)) << t << " at tic " << tic;
    EXPECT_NE(clock.tics, 0);
  }
}

}  // namespace
}  // namespace p3d::play
