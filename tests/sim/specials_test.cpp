// Doom's level mechanics on small WADs the tests write: each a sequence of tic
// commands replayed from the start, with the end state asserted (where the player
// is, what moved, what was said). Doors, locks and keys, lifts, teleporters,
// switches, exits, crushers, stairs, secrets, and demos with all of them.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "engine/render/renderer.h"
#include "engine/sim/demo.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::sim {
namespace {

using test::TestMap;
using V = TestMap::Vertex;

// A rectangle's corners, clockwise seen from above (its walls face in).
std::vector<V> rect(int x0, int y0, int x1, int y1) { return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}; }

constexpr TicCommand kWalk{25, 0, 0, 0}, kBack{-25, 0, 0, 0}, kStand{0, 0, 0, 0}, kUseCmd{0, 0, 0, kUse};

// One map played from its start.
struct Play {
  explicit Play(const TestMap& m, int skill = level::kDefaultSkill)
      : level(test::compile_test_map(m)), world(level, skill), player(world.spawn()) {}

  // Runs n tics of cmd; on_tic (if any) sees the player after each.
  void run(int n, TicCommand cmd, const std::function<void()>& on_tic = {}) {
    for (int t = 0; t < n; ++t) {
      world.tick(player, cmd);
      for (const Event& e : world.events()) events.push_back(e);
      for (const SoundEvent& e : world.sounds()) sounds.push_back({tics, e});
      ++tics;
      if (on_tic) on_tic();
    }
  }
  bool said(Event::Kind kind, const std::string& message = "") const {
    return std::any_of(events.begin(), events.end(),
                       [&](const Event& e) { return e.kind == kind && (message.empty() || e.message == message); });
  }
  const level::SectorState& sector(int s) const { return world.state().sectors[size_t(s)]; }
  uint32_t wall_of(int linedef) const {
    for (uint32_t w = 0; w < level.walls.size(); ++w)
      if (level.walls[w].source == linedef) return w;
    throw std::logic_error("no wall for that linedef");
  }
  std::string texture_name(int texture) const { return texture < 0 ? "-" : level.textures[size_t(texture)].name; }

  level::Level level;
  World world;
  Player player;
  std::vector<Event> events;
  std::vector<std::pair<int, SoundEvent>> sounds;  // tic, sound
  int tics = 0;
};

// The LINEDEF number of the line between two points.
int line_index(TestMap& m, V a, V b) { return int(&m.line_at(a, b) - m.lines.data()); }

// Room A (0..256), a door sector D (256..288 x 96..160, shut), room B (288..544).
// The line from A into the door has `special`; the player starts in A facing it.
TestMap door_map(int special, V start = {128, 128}) {
  TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 160}, {256, 96}, {256, 0}}, {0, 128});
  m.add_room(rect(256, 96, 288, 160), {0, 0});
  m.add_room({{288, 0}, {288, 96}, {288, 160}, {288, 256}, {544, 256}, {544, 0}}, {0, 128});
  m.line_at({256, 160}, {256, 96}).special = special;
  m.things.push_back({start.x, start.y, 0, 1});
  return m;
}
constexpr int kDoor = 1, kRoomB = 2;

TEST(Doors, UsedDoorOpensWaitsAndCloses) {
  Play play(door_map(1));
  play.run(60, kWalk);
  EXPECT_NEAR(play.player.pos.x, 240, 1) << "the shut door stops the player a radius before it";
  EXPECT_EQ(play.sector(kDoor).ceiling, 0);
  play.run(1, kUseCmd);
  play.run(30, kStand);
  EXPECT_EQ(play.sector(kDoor).ceiling, 62) << "a door opens 2 units a tic";
  play.run(100, kWalk);
  EXPECT_GT(play.player.pos.x, 320) << "walked through into room B";
  EXPECT_EQ(play.world.level().sector_at(play.player.pos), kRoomB);
  // It opened to the lowest neighbour ceiling - 4, waits 150 tics, and closes.
  double highest = 0;
  play.run(300, kStand, [&] { highest = std::max(highest, play.sector(kDoor).ceiling); });
  EXPECT_EQ(highest, 124);
  EXPECT_EQ(play.sector(kDoor).ceiling, 0);
  EXPECT_FALSE(play.world.movers().busy(kDoor)) << "a closed door's mover is done";
}

// The sounds Doom starts: the door's own from the door sector as it opens and as it
// closes, a grunt at a plain wall, a grunt and no door at a lock.
TEST(Doors, SoundWhereAndWhenDoomSoundsThem) {
  using play::Sound;
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(20, kBack);  // out of the door's way
  play.run(280, kStand);
  ASSERT_EQ(play.sounds.size(), 2u);
  EXPECT_EQ(play.sounds[0].second, (SoundEvent{Sound::kDoropn, kDoor}));
  EXPECT_EQ(play.sounds[0].first, 60) << "on the tic it was used";
  EXPECT_EQ(play.sounds[1].second, (SoundEvent{Sound::kDorcls, kDoor}));
  EXPECT_EQ(play.sounds[1].first, 60 + 62 + 150) << "after opening 62 tics and waiting 150";

  Play wall(door_map(0));
  wall.run(60, kWalk);
  wall.run(1, kUseCmd);
  ASSERT_EQ(wall.sounds.size(), 1u);
  EXPECT_EQ(wall.sounds[0].second, SoundEvent{Sound::kNoway}) << "the player's own grunt";

  Play locked(door_map(26, {160, 128}));
  locked.run(20, kWalk);
  locked.run(1, kUseCmd);
  ASSERT_EQ(locked.sounds.size(), 1u);
  EXPECT_EQ(locked.sounds[0].second, SoundEvent{Sound::kOof});
}

TEST(Doors, AClosingDoorGoesBackUpAtThePlayer) {
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  play.run(6, kWalk);  // into the doorway
  ASSERT_GT(play.player.pos.x, 256);
  ASSERT_LT(play.player.pos.x, 288);
  double lowest = 1e9;
  bool reopened = false;
  play.run(400, kStand, [&] {
    const double c = play.sector(kDoor).ceiling;
    if (c < lowest) lowest = c;
    reopened = reopened || (lowest < 124 && c == 124);
  });
  EXPECT_EQ(lowest, play.player.z + kPlayerHeight) << "the door comes down to the player's head, no further";
  EXPECT_TRUE(reopened) << "then goes back up";
}

TEST(Doors, UsingAnOpeningDoorClosesIt) {
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(10, kStand);
  play.run(1, kUseCmd);  // used again while opening: Doom closes it
  play.run(20, kStand);
  EXPECT_EQ(play.sector(kDoor).ceiling, 0);
}

TEST(Doors, UseIsAPressNotAHold) {
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(40, kUseCmd);  // held: one use only, so the door keeps opening
  EXPECT_EQ(play.sector(kDoor).ceiling, 80);
}

TEST(Doors, LockedDoorRefusesThenOpensWithTheKey) {
  TestMap m = door_map(26, {160, 128});  // blue lock
  m.things.push_back({64, 128, 0, 5});   // a blue keycard behind the player
  Play play(m);
  play.run(30, kWalk);
  play.run(1, kUseCmd);
  EXPECT_TRUE(play.said(Event::Kind::kLocked, "You need a blue key to open this door"));
  play.run(30, kStand);
  EXPECT_EQ(play.sector(kDoor).ceiling, 0) << "still shut";
  play.run(40, kBack);  // back over the key
  EXPECT_TRUE(play.said(Event::Kind::kKey, "Picked up a blue keycard."));
  EXPECT_EQ(play.player.keys, kBlueCard);
  EXPECT_EQ(level::find_placed(play.world.state(), 1), level::kNone) << "the key is gone from the level";
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  play.run(80, kWalk);
  EXPECT_EQ(play.world.level().sector_at(play.player.pos), kRoomB);
}

TEST(Doors, ASkullOpensTheLockOfItsColour) {
  TestMap m = door_map(28, {200, 128});  // red lock
  Play play(m);
  play.player.keys = kRedSkull;
  play.run(20, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  EXPECT_GT(play.sector(kDoor).ceiling, 56);
  EXPECT_FALSE(play.said(Event::Kind::kLocked));
}

// Room A (floor 0), a lift L (256..320, floor 128, tag 1), upper room U (floor 128).
// A's line into the lift lowers it when used (62: SR lift).
TestMap lift_map() {
  TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 160}, {256, 96}, {256, 0}}, {0, 256});
  m.add_room(rect(256, 96, 320, 160), {128, 256, "FLOOR", "CEIL", 160, 0, 1});
  m.add_room({{320, 0}, {320, 96}, {320, 160}, {320, 256}, {576, 256}, {576, 0}}, {128, 256});
  TestMap::Line& side = m.line_at({256, 160}, {256, 96});
  side.special = 62;
  side.tag = 1;
  m.things.push_back({128, 128, 0, 1});
  return m;
}

TEST(Lifts, RiddenDownAndUp) {
  Play play(lift_map());
  play.run(50, kWalk);
  EXPECT_NEAR(play.player.pos.x, 240, 1) << "the lift's 128-unit side stops the player";
  play.run(1, {25, 0, 0, kUse});
  double lowest_on_lift = 1e9;
  bool rode_up = false;
  double last_z = 0;
  play.run(300, kWalk, [&] {
    const bool on_lift = play.world.level().sector_at(play.player.pos) == 1;
    if (on_lift) lowest_on_lift = std::min(lowest_on_lift, play.player.z);
    if (on_lift && play.player.z > last_z && play.player.z == play.sector(1).floor) rode_up = true;
    last_z = play.player.z;
  });
  EXPECT_EQ(lowest_on_lift, 0) << "the lift came down to the lowest floor around it";
  EXPECT_TRUE(rode_up) << "the player stood on the lift as it rose";
  EXPECT_EQ(play.player.z, 128);
  EXPECT_GT(play.player.pos.x, 336) << "and walked off it into the upper room";
  EXPECT_EQ(play.sector(1).floor, 128);
  // Doom's lift: a start as it goes down, a stop at the bottom, a start up, a stop at the top.
  std::vector<play::Sound> heard;
  for (const auto& [tic, e] : play.sounds) {
    EXPECT_EQ(e.sector, 1);
    heard.push_back(e.sound);
  }
  EXPECT_EQ(heard, (std::vector<play::Sound>{play::Sound::kPstart, play::Sound::kPstop, play::Sound::kPstart,
                                             play::Sound::kPstop}));
}

// Rooms A1 (0..128) and A2 (128..256) split by a teleporter line facing A1; room C
// far away (tag 2) holds the destination facing north.
TestMap teleport_map(V start, int angle, int special = 97) {
  TestMap m;
  m.add_room(rect(0, 0, 128, 256), {0, 128});
  m.add_room(rect(128, 0, 256, 256), {0, 128});
  TestMap::Line& line = m.line_at({128, 256}, {128, 0});
  line.special = special;
  line.tag = 2;
  m.add_room(rect(1000, 0, 1256, 256), {32, 160, "FLOOR", "CEIL", 160, 0, 2});
  m.things.push_back({start.x, start.y, angle, 1});
  m.things.push_back({1128, 128, 90, 14});
  return m;
}

TEST(Teleporters, CrossingFromTheFrontTakesThePlayerToTheDestination) {
  Play play(teleport_map({64, 128}, 0));
  int arrived = -1;
  play.run(40, kWalk, [&] {
    if (arrived < 0 && play.said(Event::Kind::kTeleport)) arrived = play.tics;
  });
  ASSERT_GE(arrived, 0) << "teleported";
  Play again(teleport_map({64, 128}, 0));
  again.run(arrived, kWalk);
  EXPECT_EQ(again.player.pos, Vec2(1128, 128));
  EXPECT_EQ(again.player.angle, 90);
  EXPECT_EQ(again.player.z, 32) << "on the destination's floor";
  EXPECT_EQ(again.player.momentum, Vec2(0, 0));
  again.run(18, kWalk);
  EXPECT_EQ(again.player.pos, Vec2(1128, 128)) << "frozen for 18 tics, as Doom";
  again.run(10, kWalk);
  EXPECT_GT(again.player.pos.y, 140) << "then walks on, north";
  TestMap m = teleport_map({64, 128}, 0);
  EXPECT_EQ(again.world.state().specials[again.wall_of(line_index(m, {128, 256}, {128, 0}))], 97)
      << "WR: the line stays a teleporter";
}

TEST(Teleporters, CrossingFromTheBackDoesNothing) {
  TestMap m = teleport_map({192, 128}, 180, 39);
  Play play(m);
  play.run(40, kWalk);
  EXPECT_FALSE(play.said(Event::Kind::kTeleport));
  EXPECT_LT(play.player.pos.x, 100) << "walked across the line into A1";
  EXPECT_EQ(play.world.state().specials[play.wall_of(line_index(m, {128, 256}, {128, 0}))], 0)
      << "W1: used up even from the back, as Doom";
}

// Room A whose east wall is a switch (SW1TEST) with `special` and `tag`.
TestMap switch_map(int special, int tag = 0) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 100, 0, 1});
  TestMap::Line& l = m.line_at({256, 256}, {256, 0});
  l.special = special;
  l.tag = tag;
  m.sides[size_t(l.front)].middle = "SW1TEST";
  m.things.push_back({200, 128, 0, 1});
  return m;
}

TEST(Switches, ExitSwitchFlipsAndEndsTheLevel) {
  TestMap m = switch_map(11);
  Play play(m);
  const uint32_t wall = play.wall_of(line_index(m, {256, 256}, {256, 0}));
  EXPECT_EQ(play.texture_name(play.world.state().texture(wall, 0, level::kMiddlePart)), "SW1TEST");
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), Exit::kNormal);
  EXPECT_EQ(play.texture_name(play.world.state().texture(wall, 0, level::kMiddlePart)), "SW2TEST");
  EXPECT_EQ(play.world.state().specials[wall], 0) << "S1: used up";
}

TEST(Switches, SecretExitSwitch) {
  Play play(switch_map(51));
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), Exit::kSecret);
}

TEST(Switches, RepeatableSwitchFlipsBackAfterASecond) {
  TestMap m = switch_map(138, 1);  // SR: light to 255, on room A itself (tag 1)
  Play play(m);
  const uint32_t wall = play.wall_of(line_index(m, {256, 256}, {256, 0}));
  play.run(1, kUseCmd);
  EXPECT_EQ(play.sector(0).light, 255);
  EXPECT_EQ(play.texture_name(play.world.state().texture(wall, 0, level::kMiddlePart)), "SW2TEST");
  play.run(33, kStand);
  EXPECT_EQ(play.texture_name(play.world.state().texture(wall, 0, level::kMiddlePart)), "SW2TEST");
  play.run(1, kStand);
  EXPECT_EQ(play.texture_name(play.world.state().texture(wall, 0, level::kMiddlePart)), "SW1TEST") << "35 tics later";
  EXPECT_EQ(play.world.state().specials[wall], 138) << "SR: still a switch";
}

TEST(Switches, OutOfReachOrFromBehindDoesNothing) {
  TestMap m = switch_map(11);
  m.things[0] = {100, 128, 0, 1};  // 156 units away: beyond the 64-unit use range
  Play play(m);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), Exit::kNone);
}

TEST(Exits, WalkingOverAnExitLine) {
  TestMap m = teleport_map({64, 128}, 0, 52);
  Play play(m);
  play.run(30, kWalk);
  EXPECT_EQ(play.world.exit(), Exit::kNormal);
  EXPECT_TRUE(play.said(Event::Kind::kExit));
}

// Room A and a crusher room C (256..512, ceiling 128, tag 3) entered over a W1 crusher line.
TEST(Crushers, StopAtThePlayerThenGoOn) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128});
  m.add_room(rect(256, 0, 512, 256), {0, 128, "FLOOR", "CEIL", 160, 0, 3});
  TestMap::Line& line = m.line_at({256, 256}, {256, 0});
  line.special = 25;
  line.tag = 3;
  m.things.push_back({200, 128, 0, 1});
  Play play(m);
  play.run(20, kWalk);
  ASSERT_EQ(play.world.level().sector_at(play.player.pos), 1);
  play.run(200, kStand);
  EXPECT_EQ(play.sector(1).ceiling, 56) << "down to the player's head, no further";
  EXPECT_EQ(play.player.z, 0);
  play.run(30, kBack);
  ASSERT_EQ(play.world.level().sector_at(play.player.pos), 0);
  double lowest = 1e9;
  play.run(800, kStand, [&] { lowest = std::min(lowest, play.sector(1).ceiling); });
  EXPECT_EQ(lowest, 8) << "then on to floor + 8";
  EXPECT_TRUE(play.world.movers().busy(1)) << "a crusher runs for ever";
}

// Three steps east of room A, all with the STEP flat; a W1 line in A builds them.
TEST(Stairs, EachStepRisesOneStepAboveTheLast) {
  TestMap m;
  m.add_room(rect(0, 0, 128, 256), {0, 256});
  m.add_room(rect(128, 0, 256, 256), {0, 256});
  m.add_room(rect(256, 0, 320, 256), {0, 256, "STEP", "CEIL", 160, 0, 4});
  m.add_room(rect(320, 0, 384, 256), {0, 256, "STEP", "CEIL"});
  m.add_room(rect(384, 0, 448, 256), {0, 256, "STEP", "CEIL"});
  m.add_room(rect(448, 0, 512, 256), {0, 256});  // a different flat: not a step
  TestMap::Line& line = m.line_at({128, 256}, {128, 0});
  line.special = 8;
  line.tag = 4;
  m.things.push_back({64, 128, 0, 1});
  Play play(m);
  play.run(20, kWalk);
  play.run(30, kBack);
  play.run(200, kStand);
  EXPECT_EQ(play.sector(2).floor, 8);
  EXPECT_EQ(play.sector(3).floor, 16);
  EXPECT_EQ(play.sector(4).floor, 24);
  EXPECT_EQ(play.sector(5).floor, 0);
}

TEST(Secrets, StandingInASecretSectorFindsItOnce) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128});
  m.add_room(rect(256, 0, 512, 256), {0, 128, "FLOOR", "CEIL", 160, 9});
  m.things.push_back({200, 128, 0, 1});
  Play play(m);
  EXPECT_EQ(play.world.secrets_total(), 1);
  play.run(40, kWalk);
  play.run(40, kBack);
  play.run(40, kWalk);
  EXPECT_EQ(play.world.secrets_found(), 1);
  EXPECT_EQ(std::count_if(play.events.begin(), play.events.end(), [](const Event& e) { return e.kind == Event::Kind::kSecret; }), 1);
}

TEST(Cheats, NoclipWalksThroughWallsAndBack) {
  Play play(door_map(0));
  play.run(60, kWalk);
  EXPECT_NEAR(play.player.pos.x, 240, 1);
  play.run(1, {0, 0, 0, kNoclip});
  EXPECT_TRUE(play.said(Event::Kind::kCheat, "No Clipping Mode ON"));
  play.run(30, kWalk);
  EXPECT_GT(play.player.pos.x, 300) << "through the shut door";
  play.run(1, {0, 0, 0, kNoclip});
  EXPECT_FALSE(play.player.noclip);
}

// Doom's special 48: the line's front texture scrolls left a unit a tic, and every
// renderer draws it where the reference does.
TEST(Scrolling, SpecialFortyEightScrollsTheFrontTexture) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128}, "SKY1");  // a texture whose columns differ
  m.line_at({256, 256}, {256, 0}).special = 48;
  m.things.push_back({128, 128, 0, 1});
  Play play(m);
  const uint32_t wall = play.wall_of(line_index(m, {256, 256}, {256, 0}));
  const render::Camera c{{128, 128}, 41, 0, 90};
  render::Frame before(64, 40), after(64, 40), reference(64, 40);
  render::make_renderer("bsp")->render(play.level, play.world.state(), c, before);
  play.run(10, kStand);
  EXPECT_EQ(play.world.state().scroll(wall, 0), 10);
  EXPECT_EQ(play.world.state().scroll(wall, 1), 0) << "only the front side";
  EXPECT_EQ(play.world.state().scroll(play.wall_of(line_index(m, {0, 0}, {0, 256})), 0), 0);
  for (const char* name : {"bsp", "painter"}) {
    render::make_renderer(name)->render(play.level, play.world.state(), c, after);
    render::make_renderer("reference")->render(play.level, play.world.state(), c, reference);
    EXPECT_EQ(after.pixels, reference.pixels) << name;
  }
  EXPECT_NE(after.pixels, before.pixels);
}

// Walking over things picks them up by Doom's rules: a clip and a shotgun are taken
// (ammo, the weapon in hand, messages, sounds), a stimpack at full health stays.
TEST(Pickups, WalkingOverThingsTakesWhatDoomWouldGive) {
  TestMap m;
  m.add_room(rect(0, 0, 512, 256), {0, 128});
  m.things.push_back({64, 128, 0, 1});
  m.things.push_back({160, 128, 0, 2007});  // a clip
  m.things.push_back({240, 128, 0, 2011});  // a stimpack
  m.things.push_back({320, 128, 0, 2001});  // a shotgun
  Play play(m);
  play.run(60, kWalk);
  ASSERT_GT(play.player.pos.x, 340);
  const play::Inventory& inv = play.player.inventory;
  EXPECT_EQ(inv.ammo[0], 60);
  EXPECT_EQ(inv.ammo[1], 8);
  EXPECT_EQ(inv.ready, play::Weapon::kShotgun);
  EXPECT_EQ(inv.health, 100);
  std::vector<int32_t> present;
  for (const level::ShownThing& t : play.world.state().things) present.push_back(t.placed);
  EXPECT_EQ(present, (std::vector<int32_t>{0, 2})) << "the clip and the shotgun are gone, the stimpack stays";
  EXPECT_TRUE(play.said(Event::Kind::kPickup, "Picked up a clip."));
  EXPECT_TRUE(play.said(Event::Kind::kPickup, "You got the shotgun!"));
  std::vector<play::Sound> heard;
  for (const auto& [tic, e] : play.sounds) heard.push_back(e.sound);
  EXPECT_EQ(heard, (std::vector<play::Sound>{play::Sound::kItemup, play::Sound::kWpnup}));
}

// Doom's damaging floors: 5% or 10% or 20% every 32 tics of level time while standing on
// them, nothing through the radiation suit (but super slime's 2% chance a tic), armor
// taking its share, the red flash, death at 0 and the level again on use.
TEST(Damage, FloorsHurtEveryThirtyTwoTicsAsDoomsDo) {
  auto floor_map = [](int special) {
    TestMap m;
    m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 160, special});
    m.things.push_back({128, 128, 0, 1});
    return m;
  };
  Play nukage(floor_map(7));
  nukage.run(33, kStand);
  EXPECT_GT(play::flash_palette(nukage.player.inventory), 0) << "red, fading";
  nukage.run(31, kStand);
  EXPECT_EQ(nukage.player.inventory.health, 90) << "5% at tics 0 and 32";
  EXPECT_EQ(play::flash_palette(nukage.player.inventory), 0) << "faded";
  int pains = 0;
  for (const auto& [tic, e] : nukage.sounds) pains += e.sound == play::Sound::kPlpain;
  EXPECT_EQ(pains, 2);

  Play suited(floor_map(5));
  suited.player.inventory.powers[size_t(play::Power::kIronFeet)] = 60 * 35;  // in the radiation suit
  suited.run(64, kStand);
  EXPECT_EQ(suited.player.inventory.health, 100) << "the suit keeps the slime out";

  Play armored(floor_map(16));  // super slime, in green armor
  armored.player.inventory.armor = 100;
  armored.player.inventory.armor_type = 1;
  armored.run(2, kStand);
  EXPECT_EQ(armored.player.inventory.health, 100 - 14) << "20 less a third to the armor";
  EXPECT_EQ(armored.player.inventory.armor, 100 - 6);

  Play dying(floor_map(5));
  dying.run(32 * 10, kStand);
  EXPECT_TRUE(dying.player.dead);
  EXPECT_EQ(dying.player.inventory.health, 0);
  EXPECT_LT(dying.player.view_offset, -30) << "the view sinks";
  EXPECT_FALSE(dying.world.reborn());
  dying.run(1, kUseCmd);
  EXPECT_TRUE(dying.world.reborn()) << "use asks for the level again";

  Play end(floor_map(11));  // E1M8's end
  end.run(32 * 6, kStand);
  EXPECT_GT(end.player.inventory.health, 0) << "never to death";
  EXPECT_EQ(end.world.exit(), Exit::kNormal) << "the level ends at 10%";
}

TEST(Lights, SectorSpecialsFlickerDeterministically) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 200, 1});    // flickers
  m.add_room(rect(256, 0, 512, 256), {0, 128, "FLOOR", "CEIL", 80});
  m.add_room(rect(512, 0, 768, 256), {0, 128, "FLOOR", "CEIL", 200, 8});  // glows
  m.things.push_back({128, 128, 0, 1});
  Play a(m), b(m);
  std::vector<int> lights_a, lights_b;
  a.run(300, kStand, [&] { lights_a.push_back(a.sector(0).light), lights_a.push_back(a.sector(2).light); });
  b.run(300, kStand, [&] { lights_b.push_back(b.sector(0).light), lights_b.push_back(b.sector(2).light); });
  EXPECT_EQ(lights_a, lights_b);
  std::set<int> flicker, glow;
  for (size_t i = 0; i < lights_a.size(); i += 2) flicker.insert(lights_a[i]), glow.insert(lights_a[i + 1]);
  EXPECT_EQ(flicker, (std::set<int>{80, 200})) << "between its own light and its darkest neighbour's";
  EXPECT_EQ(*glow.begin(), 88) << "glows in steps of 8 between its darkest neighbour and its own light";
  EXPECT_EQ(*glow.rbegin(), 192);
  EXPECT_EQ(glow.size(), 14u);
}

// Random walks that press use, on the door and lift maps: replaying the recorded
// commands gives the same player and the same level state at every tic.
TEST(Demos, ReplayIsExactWithDoorsAndLifts) {
  for (const TestMap& m : {door_map(1), lift_map()}) {
    const level::Level level = test::compile_test_map(m);
    Rng rng(5);
    std::vector<TicCommand> tics;
    for (int t = 0; t < 1500; ++t)
      tics.push_back({int8_t(rng.below(3) == 0 ? -25 : 50), 0, int16_t(int(rng.below(801)) - 400),
                      uint8_t(rng.below(8) == 0 ? kUse : 0)});
    const Demo demo = decode_demo(encode_demo({fingerprint(level), level.player_start, level.player_angle, 3, 0, tics}), "d");
    std::vector<std::pair<Player, std::vector<double>>> first;
    for (int pass = 0; pass < 2; ++pass) {
      World world(level, demo.skill);
      Player p = world.spawn_at(demo.start, demo.angle);
      int moved = 0;
      for (size_t t = 0; t < demo.tics.size(); ++t) {
        world.tick(p, demo.tics[t]);
        std::vector<double> heights;
        for (const level::SectorState& s : world.state().sectors) heights.push_back(s.floor), heights.push_back(s.ceiling);
        if (pass == 0) {
          first.push_back({p, heights});
          continue;
        }
        moved += heights != first[0].second;
        ASSERT_EQ(p.pos, first[t].first.pos) << "tic " << t;
        ASSERT_EQ(p.z, first[t].first.z) << "tic " << t;
        ASSERT_EQ(heights, first[t].second) << "tic " << t;
      }
      if (pass == 1) {
        EXPECT_GT(moved, 0) << "something moved during the walk";
      }
    }
  }
}

}  // namespace
}  // namespace p3d::sim
