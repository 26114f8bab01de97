// Doom's level mechanics on small WADs the tests write, played by the World from the
// map's start: each a sequence of tic commands with what Doom would leave asserted
// (where the player is, what moved and when, what was heard and said). Doors, locks
// and keys, lifts, teleporters, switches, exits, crushers, stairs, secrets, cheats,
// scrolling walls, pickups, hurting floors, lights, the palette's flashes, every
// weapon's damage and spread, and replays with all of them.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>

#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "engine/util/bytes.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::play {
namespace {

using geom::Vec2;
using test::TestMap;
using V = TestMap::Vertex;

// A rectangle's corners, clockwise seen from above (its walls face in).
std::vector<V> rect(int x0, int y0, int x1, int y1) { return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}; }

constexpr TicCmd kWalk{25, 0, 0, 0}, kBack{-25, 0, 0, 0}, kStand{}, kUseCmd{0, 0, 0, kBtUse}, kFire{0, 0, 0, kBtAttack};

// One map played from its start, as MAP01 of a WAD with the test art.
struct Play {
  explicit Play(const TestMap& m, const GameOptions& options = {}) : Play(test::test_stack({{"MAP01", m}}), options) {}
  Play(wad::Stack stack, const GameOptions& options)
      : wads(std::move(stack)),
        level(bsp::build_wad_map(wads, "MAP01", {}, nullptr)),
        world(map_from_wads(wads, "MAP01", level), level, options, Random{}) {}

  // Runs n tics of cmd; on_tic (if any) looks after each.
  void run(int n, TicCmd cmd, const std::function<void()>& on_tic = {}) {
    for (int t = 0; t < n; ++t) {
      world.tick(cmd);
      for (const std::string& m : world.messages()) messages.push_back(m);
      for (const SoundEvent& e : world.sounds()) sounds.push_back({tics, e});
      ++tics;
      if (on_tic) on_tic();
    }
  }
  bool said(const std::string& message) const {
    return std::find(messages.begin(), messages.end(), message) != messages.end();
  }
  int heard(Sound sound) const {
    return int(std::count_if(sounds.begin(), sounds.end(), [&](const auto& s) { return s.second.sound == sound; }));
  }
  Player& player() { return world.player(); }
  Mobj& mo() { return *world.player().mo; }
  Inventory& inv() { return world.player().inv; }
  Vec2 pos() { return {to_double(mo().x), to_double(mo().y)}; }
  double z() { return to_double(mo().z); }
  int sector_here() { return level.sector_at(pos()); }
  const level::SectorState& sector(int s) const { return world.state().sectors[size_t(s)]; }
  uint32_t wall_of(int linedef) const {
    for (uint32_t w = 0; w < level.walls.size(); ++w)
      if (level.walls[w].source == linedef) return w;
    throw std::logic_error("no wall for that linedef");
  }
  std::string texture_name(int texture) const { return texture < 0 ? "-" : level.textures[size_t(texture)].name; }
  std::string front_middle(int linedef) const {
    return texture_name(world.state().texture(wall_of(linedef), 0, level::kMiddlePart));
  }
  // The placed things still in the world (Doom's spawn points), the player's aside.
  std::vector<int32_t> placed_present() {
    std::vector<int32_t> out;
    for (const Mobj* t : world.things())
      if (t != world.player().mo) out.push_back(t->spawn_point.placed);
    return out;
  }
  int32_t placed_of_type(int type) const {
    for (size_t i = 0; i < level.things.size(); ++i)
      if (level.things[i].type == type) return int32_t(i);
    return level::kNone;
  }
  void put_player(Vec2 at, Angle angle) {
    world.place_player(Fixed(std::lround(at.x * kFracUnit)), Fixed(std::lround(at.y * kFracUnit)), angle);
    mo().mom_x = mo().mom_y = mo().mom_z = 0;
  }

  wad::Stack wads;
  level::Level level;
  World world;
  std::vector<std::string> messages;
  std::vector<std::pair<int, SoundEvent>> sounds;  // tic, sound
  int tics = 0;
};

// The LINEDEF number of the line between two points.
int line_index(TestMap& m, V a, V b) { return int(&m.line_at(a, b) - m.lines.data()); }

// ---- doors -------------------------------------------------------------------------

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
  EXPECT_NEAR(play.pos().x, 240, 1) << "the shut door stops the player a radius before it";
  EXPECT_EQ(play.sector(kDoor).ceiling, 0);
  play.run(1, kUseCmd);
  play.run(30, kStand);
  EXPECT_EQ(play.sector(kDoor).ceiling, 62) << "a door opens 2 units a tic, from the tic it is used";
  play.run(100, kWalk);
  EXPECT_GT(play.pos().x, 320) << "walked through into room B";
  EXPECT_EQ(play.sector_here(), kRoomB);
  // It opened to the lowest neighbour ceiling - 4, waits 150 tics, and closes.
  double highest = 0;
  play.run(300, kStand, [&] { highest = std::max(highest, play.sector(kDoor).ceiling); });
  EXPECT_EQ(highest, 124);
  EXPECT_EQ(play.sector(kDoor).ceiling, 0);
  EXPECT_EQ(play.world.map().sectors[kDoor].special_data, nullptr) << "a closed door's thinker is gone";
}

// The sounds Doom starts: the door's own from the door sector as it opens and as it
// closes, a grunt from the player at a plain wall, an "oof" from nowhere at a lock.
TEST(Doors, SoundWhereAndWhenDoomSoundsThem) {
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(20, kBack);  // out of the door's way
  play.run(280, kStand);
  ASSERT_EQ(play.sounds.size(), 2u);
  EXPECT_EQ(play.sounds[0].second.sound, Sound::kDoropn);
  EXPECT_EQ(play.sounds[0].second.origin, kSectorOrigin + kDoor);
  EXPECT_EQ(play.sounds[0].first, 60) << "on the tic it was used";
  EXPECT_EQ(play.sounds[1].second.sound, Sound::kDorcls);
  EXPECT_EQ(play.sounds[1].second.origin, kSectorOrigin + kDoor);
  EXPECT_EQ(play.sounds[1].first, 60 + 62 + 150) << "after opening 62 tics and waiting 150";

  Play wall(door_map(0));
  wall.run(60, kWalk);
  wall.run(1, kUseCmd);
  ASSERT_EQ(wall.sounds.size(), 1u);
  EXPECT_EQ(wall.sounds[0].second.sound, Sound::kNoway);
  EXPECT_EQ(wall.sounds[0].second.origin, wall.mo().id) << "the player's own grunt";

  Play locked(door_map(26, {160, 128}));
  locked.run(20, kWalk);
  locked.run(1, kUseCmd);
  ASSERT_EQ(locked.sounds.size(), 1u);
  EXPECT_EQ(locked.sounds[0].second, (SoundEvent{Sound::kOof, 0, 0, 0})) << "from nowhere, as Doom's";
}

TEST(Doors, AClosingDoorGoesBackUpAtThePlayer) {
  Play play(door_map(1));
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  play.put_player({272, 128}, 0);  // in the doorway
  double lowest = 1e9;
  bool reopened = false;
  play.run(400, kStand, [&] {
    const double c = play.sector(kDoor).ceiling;
    lowest = std::min(lowest, c);
    reopened = reopened || (lowest < 124 && c == 124);
  });
  EXPECT_EQ(lowest, play.z() + 56) << "the door comes down to the player's head, no further";
  EXPECT_TRUE(reopened) << "then goes back up";
  EXPECT_GE(play.heard(Sound::kDoropn), 2) << "opening again sounds again";
  EXPECT_EQ(play.mo().health, 100) << "a door never hurts";
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
  const int32_t key = play.placed_of_type(5);
  ASSERT_NE(key, level::kNone);
  EXPECT_EQ(play.placed_present(), std::vector<int32_t>{key});
  play.run(30, kWalk);
  play.run(1, kUseCmd);
  EXPECT_TRUE(play.said("You need a blue key to open this door"));
  play.run(30, kStand);
  EXPECT_EQ(play.sector(kDoor).ceiling, 0) << "still shut";
  play.run(40, kBack);  // back over the key
  EXPECT_TRUE(play.said("Picked up a blue keycard."));
  EXPECT_EQ(play.player().cards, 1);
  EXPECT_TRUE(play.placed_present().empty()) << "the key is gone from the level";
  play.run(60, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  play.run(80, kWalk);
  EXPECT_EQ(play.sector_here(), kRoomB);
}

TEST(Doors, ASkullOpensTheLockOfItsColour) {
  Play play(door_map(28, {200, 128}));  // red lock
  play.player().cards = 1 << 5;         // the red skull
  play.run(20, kWalk);
  play.run(1, kUseCmd);
  play.run(40, kStand);
  EXPECT_GT(play.sector(kDoor).ceiling, 56);
  EXPECT_TRUE(play.messages.empty());
}

// ---- lifts -------------------------------------------------------------------------

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
  EXPECT_NEAR(play.pos().x, 240, 1) << "the lift's 128-unit side stops the player";
  play.run(1, {25, 0, 0, kBtUse});
  double lowest_on_lift = 1e9, last_z = 0;
  bool rode_up = false;
  play.run(300, kWalk, [&] {
    const bool on_lift = play.sector_here() == 1;
    if (on_lift) lowest_on_lift = std::min(lowest_on_lift, play.z());
    if (on_lift && play.z() > last_z && play.z() == play.sector(1).floor) rode_up = true;
    last_z = play.z();
  });
  EXPECT_EQ(lowest_on_lift, 0) << "the lift came down to the lowest floor around it";
  EXPECT_TRUE(rode_up) << "the player stood on the lift as it rose";
  EXPECT_EQ(play.z(), 128);
  EXPECT_GT(play.pos().x, 336) << "and walked off it into the upper room";
  EXPECT_EQ(play.sector(1).floor, 128);
  // Doom's lift: a start as it goes down, a stop at the bottom, a start up, a stop at the top.
  std::vector<Sound> heard;
  for (const auto& [tic, e] : play.sounds) {
    EXPECT_EQ(e.origin, kSectorOrigin + 1);
    heard.push_back(e.sound);
  }
  EXPECT_EQ(heard, (std::vector<Sound>{Sound::kPstart, Sound::kPstop, Sound::kPstart, Sound::kPstop}));
  // Down 128 at 4 a tic, 105 tics' wait, then up.
  ASSERT_EQ(play.sounds.size(), 4u);
  EXPECT_EQ(play.sounds[1].first - play.sounds[0].first, 32);
  EXPECT_EQ(play.sounds[2].first - play.sounds[1].first, 105);
  EXPECT_EQ(play.world.map().sectors[1].special_data, nullptr) << "a lift that stays up is done";
}

// ---- teleporters -------------------------------------------------------------------

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
  TestMap m = teleport_map({64, 128}, 0);
  Play play(m);
  for (int t = 0; t < 40 && play.mo().x != to_fixed(1128); ++t) play.run(1, kWalk);
  ASSERT_EQ(play.mo().x, to_fixed(1128)) << "teleported";
  EXPECT_EQ(play.mo().y, to_fixed(128));
  EXPECT_EQ(play.mo().angle, kAngle90);
  EXPECT_EQ(play.z(), 32) << "on the destination's floor";
  EXPECT_EQ(play.mo().mom_x, 0);
  EXPECT_EQ(play.mo().mom_y, 0);
  EXPECT_EQ(play.heard(Sound::kTelept), 2) << "fog where it left and where it arrived";
  play.run(18, kWalk);
  EXPECT_EQ(play.pos(), Vec2(1128, 128)) << "frozen for 18 tics, as Doom";
  play.run(10, kWalk);
  EXPECT_GT(play.pos().y, 140) << "then walks on, north";
  EXPECT_EQ(play.world.state().specials[play.wall_of(line_index(m, {128, 256}, {128, 0}))], 97)
      << "WR: the line stays a teleporter";
}

TEST(Teleporters, CrossingFromTheBackDoesNothing) {
  TestMap m = teleport_map({192, 128}, 180, 39);
  Play play(m);
  play.run(40, kWalk);
  EXPECT_EQ(play.heard(Sound::kTelept), 0);
  EXPECT_LT(play.pos().x, 100) << "walked across the line into A1";
  EXPECT_EQ(play.world.state().specials[play.wall_of(line_index(m, {128, 256}, {128, 0}))], 0)
      << "W1: used up even from the back, as Doom";
}

// ---- switches and exits ------------------------------------------------------------

// Room A whose east wall is a switch with `special` and `tag`: SW1BRCOM, since Doom
// knows its switches by name (the test art's SW1TEST is none).
TestMap switch_map(int special, int tag = 0) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 100, 0, 1});
  TestMap::Line& l = m.line_at({256, 256}, {256, 0});
  l.special = special;
  l.tag = tag;
  m.sides[size_t(l.front)].middle = "SW1BRCOM";
  m.things.push_back({200, 128, 0, 1});
  return m;
}

// The map in a WAD whose TEXTURE2 adds Doom's switch pair SW1BRCOM and SW2BRCOM (drawn
// with the test art's wall and sky patches).
wad::Stack with_doom_switch(const TestMap& m) {
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
  m.add_to(w, "MAP01");
  wad::Stack stack;
  stack.add(wad::Wad(w.bytes(), "switches.wad"));
  return stack;
}

// A new player holds use and fire down (Doom's G_PlayerReborn), so that nothing happens
// before they are let go.
TEST(Switches, UseHeldFromTheStartDoesNothingUntilLetGo) {
  Play play(with_doom_switch(switch_map(11)), {});
  play.run(10, kUseCmd);
  EXPECT_EQ(play.world.exit(), ExitKind::kNone);
  play.run(1, kStand);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), ExitKind::kNormal);
}

TEST(Switches, ExitSwitchFlipsAndEndsTheLevel) {
  TestMap m = switch_map(11);
  Play play(with_doom_switch(m), {});
  const int line = line_index(m, {256, 256}, {256, 0});
  EXPECT_EQ(play.front_middle(line), "SW1BRCOM");
  play.run(1, kStand);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), ExitKind::kNormal);
  EXPECT_EQ(play.front_middle(line), "SW2BRCOM");
  EXPECT_EQ(play.world.state().specials[play.wall_of(line)], 0) << "S1: used up";
  ASSERT_EQ(play.sounds.size(), 1u);
  // Doom clears a once-only switch's special before it asks whether the line is an exit
  // switch: its exit sound (DSSWTCHX) never plays.
  EXPECT_EQ(play.sounds[0].second.sound, Sound::kSwtchn);
  EXPECT_EQ(play.sounds[0].second.origin, kSectorOrigin + 0);
}

TEST(Switches, SecretExitSwitch) {
  Play play(with_doom_switch(switch_map(51)), {});
  play.run(1, kStand);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), ExitKind::kSecret);
}

TEST(Switches, RepeatableSwitchFlipsBackAfterASecond) {
  TestMap m = switch_map(138, 1);  // SR: light to 255, on room A itself (tag 1)
  Play play(with_doom_switch(m), {});
  const int line = line_index(m, {256, 256}, {256, 0});
  play.run(1, kStand);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.sector(0).light, 255);
  EXPECT_EQ(play.front_middle(line), "SW2BRCOM");
  play.run(33, kStand);
  EXPECT_EQ(play.front_middle(line), "SW2BRCOM");
  play.run(1, kStand);
  EXPECT_EQ(play.front_middle(line), "SW1BRCOM") << "35 tics later";
  EXPECT_EQ(play.world.state().specials[play.wall_of(line)], 138) << "SR: still a switch";
  EXPECT_EQ(play.heard(Sound::kSwtchn), 2) << "pressed, and back";
}

TEST(Switches, OutOfReachDoesNothing) {
  TestMap m = switch_map(11);
  m.things[0] = {100, 128, 0, 1};  // 156 units away: beyond the 64-unit use range
  Play play(with_doom_switch(m), {});
  play.run(1, kStand);
  play.run(1, kUseCmd);
  EXPECT_EQ(play.world.exit(), ExitKind::kNone);
  EXPECT_EQ(play.front_middle(line_index(m, {256, 256}, {256, 0})), "SW1BRCOM");
}

TEST(Exits, WalkingOverAnExitLine) {
  Play play(teleport_map({64, 128}, 0, 52));
  play.run(30, kWalk);
  EXPECT_EQ(play.world.exit(), ExitKind::kNormal);
  Play secret(teleport_map({64, 128}, 0, 124));
  secret.run(30, kWalk);
  EXPECT_EQ(secret.world.exit(), ExitKind::kSecret);
}

// ---- crushers, stairs, secrets -----------------------------------------------------

// Room A and a crusher room C (256..512, ceiling 128, tag 3) entered over a W1 crusher
// line (25: crush and raise). Doom's crusher comes down a unit a tic; at the player's
// head it goes on at an eighth of that, hurting 10 every fourth tic until the player is
// dead, down to the floor + 8, then back up, and again for ever.
TEST(Crushers, HurtEveryFourTicsAndGoOnDown) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128});
  m.add_room(rect(256, 0, 512, 256), {0, 128, "FLOOR", "CEIL", 160, 0, 3});
  TestMap::Line& line = m.line_at({256, 256}, {256, 0});
  line.special = 25;
  line.tag = 3;
  m.things.push_back({200, 128, 0, 1});
  Play play(m);
  play.run(20, kWalk);
  ASSERT_EQ(play.sector_here(), 1);
  double lowest = 1e9, last_ceiling = play.sector(1).ceiling;
  int hurt = 0, slow_tics = 0, last_health = play.mo().health;
  bool back_up = false, down_again = false;
  play.run(700, kStand, [&] {
    const double c = play.sector(1).ceiling;
    lowest = std::min(lowest, c);
    if (last_ceiling - c == 0.125) ++slow_tics;
    back_up = back_up || (lowest == 8 && c == 128);
    down_again = down_again || (back_up && c < 128);
    const int health = play.mo().health;
    if (health != last_health) {
      ++hurt;
      EXPECT_EQ(last_health - health, 10) << "tic " << play.tics;
      EXPECT_EQ((play.world.level_time() - 1) % 4, 0) << "every fourth tic of the level";
      EXPECT_LT(c, play.z() + 56) << "only when the ceiling is in the player's head";
    }
    last_health = health;
    last_ceiling = c;
  });
  EXPECT_EQ(hurt, 10) << "100 health in tens";
  EXPECT_EQ(play.player().state, PlayerState::kDead);
  EXPECT_GT(slow_tics, 300) << "crushing at an eighth of a unit a tic";
  EXPECT_EQ(lowest, 8) << "down to floor + 8";
  EXPECT_TRUE(back_up);
  EXPECT_TRUE(down_again) << "a crusher runs for ever";
  EXPECT_NE(play.world.map().sectors[1].special_data, nullptr);
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
  play.run(40, kStand);
  EXPECT_EQ(play.sector(2).floor, 8) << "a quarter unit a tic: the first step is done";
  EXPECT_LT(play.sector(4).floor, 24) << "the last still rising";
  play.run(100, kStand);
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
  EXPECT_EQ(play.world.total_secrets(), 1);
  play.run(40, kWalk);
  EXPECT_EQ(play.player().secret_count, 1);
  EXPECT_EQ(play.world.map().sectors[1].special, 0) << "the sector is a secret no more";
  play.run(40, kBack);
  play.run(40, kWalk);
  EXPECT_EQ(play.player().secret_count, 1);
}

// ---- cheats and scrolling ----------------------------------------------------------

TEST(Cheats, NoclipWalksThroughWallsAndBack) {
  Play play(door_map(0));
  play.run(60, kWalk);
  EXPECT_NEAR(play.pos().x, 240, 1);
  play.world.apply_cheats(kToggleNoclip);
  EXPECT_EQ(play.world.messages(), std::vector<std::string>{"No Clipping Mode ON"});
  play.run(30, kWalk);
  EXPECT_GT(play.pos().x, 300) << "through the shut door";
  play.world.apply_cheats(kToggleNoclip);
  EXPECT_EQ(play.world.messages(), std::vector<std::string>{"No Clipping Mode OFF"});
  EXPECT_EQ(play.player().cheats & kCheatNoclip, 0);
  play.run(1, kStand);
  EXPECT_EQ(play.mo().flags & kNoclip, 0u) << "the player's thing clips again";
  play.run(60, kBack);
  EXPECT_GT(play.pos().x, 288 + 15) << "and the shut door stops it on the way back";
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

// ---- pickups, hurting floors and the palette's flashes -----------------------------

// Walking over things picks them up by Doom's rules: a clip and a shotgun are taken
// (ammo, the weapon raised, messages, sounds, a gold flash), a stimpack at full health
// stays.
TEST(Pickups, WalkingOverThingsTakesWhatDoomWouldGive) {
  TestMap m;
  m.add_room(rect(0, 0, 512, 256), {0, 128});
  m.things.push_back({64, 128, 0, 1});
  m.things.push_back({160, 128, 0, 2007});  // a clip
  m.things.push_back({240, 128, 0, 2011});  // a stimpack
  m.things.push_back({320, 128, 0, 2001});  // a shotgun
  Play play(m);
  std::set<int> palettes;
  play.run(60, kWalk, [&] { palettes.insert(flash_palette(play.inv())); });
  ASSERT_GT(play.pos().x, 340);
  play.run(40, kStand);  // the shotgun comes up
  EXPECT_EQ(play.inv().ammo[0], 60);
  EXPECT_EQ(play.inv().ammo[1], 8);
  EXPECT_EQ(play.inv().ready, Weapon::kShotgun);
  EXPECT_EQ(play.inv().health, 100);
  EXPECT_EQ(play.placed_present(), std::vector<int32_t>{play.placed_of_type(2011)})
      << "the clip and the shotgun are gone";
  EXPECT_TRUE(play.said("Picked up a clip."));
  EXPECT_TRUE(play.said("You got the shotgun!"));
  EXPECT_EQ(play.messages.size(), 2u);
  std::vector<SoundEvent> heard;
  for (const auto& [tic, e] : play.sounds) heard.push_back(e);
  EXPECT_EQ(heard, (std::vector<SoundEvent>{{Sound::kItemup, 0, 0, 0}, {Sound::kWpnup, 0, 0, 0}}))
      << "heard from nowhere: the player's own";
  EXPECT_TRUE(palettes.contains(0));
  EXPECT_TRUE(std::any_of(palettes.begin(), palettes.end(), [](int p) { return p >= 9 && p <= 12; })) << "gold";
  EXPECT_FALSE(std::any_of(palettes.begin(), palettes.end(), [](int p) { return p >= 1 && p <= 8; })) << "never red";
  EXPECT_EQ(flash_palette(play.inv()), 0) << "faded";
}

// The palette: red while berserk (fading as the count goes up), green in the radiation
// suit, blinking as it runs out.
TEST(Pickups, BerserkFlashesRedAndTheSuitGreen) {
  TestMap m;
  m.add_room(rect(0, 0, 512, 256), {0, 128});
  m.things.push_back({64, 128, 0, 1});
  m.things.push_back({128, 128, 0, 2023});  // berserk
  m.things.push_back({256, 128, 0, 2025});  // radiation suit
  Play play(m);
  std::vector<int> palettes;
  play.run(60, kWalk, [&] { palettes.push_back(flash_palette(play.inv())); });
  EXPECT_TRUE(play.said("Berserk!"));
  EXPECT_TRUE(play.said("Radiation Shielding Suit"));
  EXPECT_GT(play.inv().powers[size_t(Power::kStrength)], 0);
  EXPECT_EQ(play.inv().ready, Weapon::kFist) << "berserk puts the fist in hand";
  EXPECT_TRUE(std::find(palettes.begin(), palettes.end(), 3) != palettes.end()) << "berserk's red";
  play.run(12 * 64, kStand);
  EXPECT_EQ(play.inv().powers[size_t(Power::kIronFeet)] > 0, true);
  EXPECT_EQ(flash_palette(play.inv()), 13) << "berserk faded; the suit's green";
  play.inv().powers[size_t(Power::kIronFeet)] = 4 * 32;
  std::set<int> blink;
  play.run(64, kStand, [&] { blink.insert(flash_palette(play.inv())); });
  EXPECT_EQ(blink, (std::set<int>{0, 13})) << "the suit blinks as it runs out";
  EXPECT_EQ(play.inv().powers[size_t(Power::kIronFeet)], 2 * 32);
}

// Doom's damaging floors: 5, 10 or 20 every 32 tics of level time while standing on
// them, nothing through the radiation suit (but super slime's chance), armor taking
// its share, the red flash, death at 0 and the level again on use; E1M8's floor ends the
// level at 10% or less, takes god mode away, and never kills (Doom's "hell hack": it
// leaves at least 1).
TEST(Damage, FloorsHurtEveryThirtyTwoTicsAsDoomsDo) {
  auto floor_map = [](int special) {
    TestMap m;
    m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 160, special});
    m.things.push_back({128, 128, 0, 1});
    return m;
  };
  Play nukage(floor_map(7));
  nukage.run(33, kStand);
  EXPECT_GE(flash_palette(nukage.inv()), 1) << "red, fading";
  EXPECT_LE(flash_palette(nukage.inv()), 8);
  nukage.run(31, kStand);
  EXPECT_EQ(nukage.inv().health, 90) << "5 at tics 0 and 32";
  EXPECT_EQ(nukage.mo().health, 90);
  EXPECT_EQ(flash_palette(nukage.inv()), 0) << "faded";
  EXPECT_EQ(nukage.heard(Sound::kPlpain), 2);

  Play suited(floor_map(5));
  suited.inv().powers[size_t(Power::kIronFeet)] = 60 * 35;  // in the radiation suit
  suited.run(64, kStand);
  EXPECT_EQ(suited.inv().health, 100) << "the suit keeps the slime out";

  Play armored(floor_map(16));  // super slime, in green armor
  armored.inv().armor = 100;
  armored.inv().armor_type = 1;
  armored.run(2, kStand);
  EXPECT_EQ(armored.inv().health, 100 - 14) << "20 less a third to the armor";
  EXPECT_EQ(armored.inv().armor, 100 - 6);

  Play dying(floor_map(5));
  dying.run(32 * 9 + 1 + 40, kStand);
  EXPECT_EQ(dying.player().state, PlayerState::kDead);
  EXPECT_EQ(dying.inv().health, 0) << "ten tens";
  EXPECT_EQ(dying.player().view_height, 6 * kFracUnit) << "the view sinks to 6 above the floor";
  dying.run(1, kUseCmd);
  EXPECT_EQ(dying.player().state, PlayerState::kReborn) << "use asks for the level again";

  Play end(floor_map(11));  // E1M8's end, in green armor
  end.inv().armor = 100;
  end.inv().armor_type = 1;
  end.world.apply_cheats(kToggleGod);
  end.run(1, kStand);
  EXPECT_EQ(end.player().cheats & kCheatGodMode, 0) << "no god mode here";
  end.run(32 * 6 - 1, kStand);
  EXPECT_EQ(end.world.exit(), ExitKind::kNone);
  end.run(1, kStand);
  EXPECT_EQ(end.inv().health, 6) << "14 a time (20 less the armor's third) to 16; then 15 at most, less 5";
  EXPECT_EQ(end.world.exit(), ExitKind::kNormal) << "the level ends at 10% or less";

  Play bare(floor_map(11));
  bare.run(32 * 4 + 1, kStand);
  EXPECT_EQ(bare.inv().health, 1) << "20 a time, the last only 19";
  EXPECT_EQ(bare.player().state, PlayerState::kLive);
  EXPECT_EQ(bare.world.exit(), ExitKind::kNormal);
}

TEST(Lights, SectorSpecialsFlickerDeterministically) {
  TestMap m;
  m.add_room(rect(0, 0, 256, 256), {0, 128, "FLOOR", "CEIL", 200, 1});  // flickers
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
  EXPECT_EQ(lights_a[1], 192) << "the glow starts down";
}

// ---- weapons -----------------------------------------------------------------------

// A long room; the player at (272, 256) facing east; with `keen`, Commander Keen (a
// thing that bleeds and never moves) hangs from the 96-unit ceiling 48 units ahead.
TestMap range_map(bool keen) {
  TestMap m;
  m.add_room(rect(0, 0, 1024, 512), {0, 96, "FLOOR", "CEIL", 200});
  m.things.push_back({272, 256, 0, 1});
  if (keen) m.things.push_back({320, 256, 0, 72});
  return m;
}

// Every weapon, full ammo, god mode; `weapon` raised with the weapon keys' command.
void take_up(Play& play, int slot, Weapon weapon) {
  play.world.apply_cheats(kGiveAll | kToggleGod);
  if (weapon == Weapon::kShotgun) play.inv().weapons[size_t(Weapon::kSuperShotgun)] = false;
  if (weapon == Weapon::kFist) play.inv().weapons[size_t(Weapon::kChainsaw)] = false;
  play.run(1, {0, 0, 0, uint8_t(kBtChange | (slot << kBtWeaponShift))});
  for (int t = 0; t < 100 && (play.inv().ready != weapon || play.inv().pending != Weapon::kCount); ++t)
    play.run(1, kStand);
  play.run(20, kStand);  // raised
  EXPECT_EQ(play.inv().ready, weapon);
}

Mobj* thing_of_type(World& world, ThingType type) {
  for (const Mobj* mo : world.things())
    if (mo->type == type) return const_cast<Mobj*>(mo);
  return nullptr;
}

// What one tic of fire did to a target.
struct Hit {
  int damage = 0;                     // health lost
  int blood = 0, sprays = 0;          // blood spawned (a bullet or blow each), BFG sprays landed
  std::vector<const Mobj*> exploded;  // missiles that burst this tic
};

// Holds fire for `tics` tics at the target (kept still and alive), while the weapon in
// hand is one of `weapons`; the tics that did something.
std::vector<Hit> fire_at(Play& play, Mobj& target, int tics, std::set<Weapon> weapons) {
  std::set<uint32_t> seen, flying;
  for (const Mobj* mo : play.world.things()) seen.insert(mo->id);
  std::vector<Hit> hits;
  for (int t = 0; t < tics && weapons.contains(play.inv().ready); ++t) {
    target.health = 1000000;
    play.run(1, kFire);
    target.mom_x = target.mom_y = target.mom_z = 0;
    Hit h;
    h.damage = 1000000 - target.health;
    for (const Mobj* mo : play.world.things()) {
      const bool fresh = seen.insert(mo->id).second;
      if (fresh && mo->type == ThingType::kBlood) ++h.blood;
      if (fresh && mo->type == ThingType::kExtrabfg) ++h.sprays;
      if (mo->flags & kMissile) {
        flying.insert(mo->id);
      } else if (flying.erase(mo->id)) {
        h.exploded.push_back(mo);
      }
    }
    if (h.damage || h.blood || h.sprays || !h.exploded.empty()) hits.push_back(h);
  }
  return hits;
}

TEST(Weapons, BulletsAndBlowsDoDoomsDamage) {
  struct Case {
    const char* name;
    int slot;
    Weapon weapon;
    bool berserk;
    int pellets;            // a hit each, every shot at this range
    std::set<int> per_hit;  // Doom's damage of one
  };
  const std::set<int> bullet{5, 10, 15};
  std::set<int> blow, berserk_blow;
  for (int d = 1; d <= 10; ++d) blow.insert(2 * d), berserk_blow.insert(20 * d);
  for (const Case& c : {Case{"pistol", 1, Weapon::kPistol, false, 1, bullet},
                        Case{"chaingun", 3, Weapon::kChaingun, false, 1, bullet},
                        Case{"shotgun", 2, Weapon::kShotgun, false, 7, bullet},
                        Case{"super shotgun", 2, Weapon::kSuperShotgun, false, 20, bullet},
                        Case{"fist", 0, Weapon::kFist, false, 1, blow},
                        Case{"berserk fist", 0, Weapon::kFist, true, 1, berserk_blow},
                        Case{"chainsaw", 0, Weapon::kChainsaw, false, 1, blow}}) {
    Play play(range_map(true));
    take_up(play, c.slot, c.weapon);
    if (c.berserk) play.inv().powers[size_t(Power::kStrength)] = 1;
    Mobj* keen = thing_of_type(play.world, ThingType::kKeen);
    ASSERT_NE(keen, nullptr);
    const std::vector<Hit> hits = fire_at(play, *keen, 350, {c.weapon});
    std::set<int> singles, totals;
    int shots = 0;
    for (const Hit& h : hits) {
      totals.insert(h.damage);
      EXPECT_EQ(h.blood, c.pellets) << c.name << ": every pellet hits at 48 units, and bleeds";
      EXPECT_GE(h.damage, *c.per_hit.begin() * h.blood) << c.name;
      EXPECT_LE(h.damage, *c.per_hit.rbegin() * h.blood) << c.name;
      EXPECT_EQ(h.damage % *c.per_hit.begin(), 0) << c.name << ": " << h.damage;
      if (h.blood == 1) {
        EXPECT_TRUE(c.per_hit.contains(h.damage)) << c.name << ": " << h.damage;
        singles.insert(h.damage);
      }
      ++shots;
    }
    EXPECT_GT(shots, c.pellets > 1 ? 5 : 15) << c.name;
    if (c.pellets == 1) {
      EXPECT_GE(singles.size(), std::min<size_t>(c.per_hit.size(), 5)) << c.name << ": Doom's range, not one value";
    }
    std::printf("[ weapon   ] %s: %d shots, %zu different damages (%d to %d)\n", c.name, shots, totals.size(),
                *totals.begin(), *totals.rbegin());
  }
}

// Rockets (20 to 160 a hit, and a blast of 128 less the distance), plasma (5 to 40),
// the BFG's ball (100 to 800) and its spray 16 tics later (15 to 120 a tracer). When
// the BFG's cells run short Doom changes to the plasma gun, which uses up the rest (and
// then to the super shotgun, where the test stops).
TEST(Weapons, MissilesDoDoomsDamage) {
  for (const Weapon weapon : {Weapon::kMissile, Weapon::kPlasma, Weapon::kBfg}) {
    Play play(range_map(true));
    take_up(play, weapon == Weapon::kMissile ? 4 : weapon == Weapon::kPlasma ? 5 : 6, weapon);
    play.put_player({32, 256}, 0);  // out of the blasts' reach
    Mobj* keen = thing_of_type(play.world, ThingType::kKeen);
    ASSERT_NE(keen, nullptr);
    // Out of cells, the BFG gives way to the plasma gun; out of those to the super shotgun.
    const std::vector<Hit> hits = fire_at(play, *keen, 600, {weapon, Weapon::kPlasma});
    std::map<ThingType, int> burst;
    int sprays = 0;
    for (const Hit& h : hits) {
      const ThingType type = h.exploded.empty() ? ThingType::kCount : h.exploded[0]->type;
      for (const Mobj* mo : h.exploded) ASSERT_EQ(mo->type, type) << "one kind of missile at a time";
      burst[type] += int(h.exploded.size());
      if (type == ThingType::kRocket) {
        ASSERT_EQ(h.exploded.size(), 1u);
        // The blast: 128 less the distance beyond Keen's radius (P_RadiusAttack).
        const Mobj& at = *h.exploded[0];
        const Fixed dist = std::max(std::abs(keen->x - at.x), std::abs(keen->y - at.y));
        const int blast = 128 - std::max(0, (dist - keen->radius) >> kFracBits);
        const int hit = h.damage - blast;
        EXPECT_TRUE(hit % 20 == 0 && hit >= 20 && hit <= 160) << "rocket: " << h.damage << " with a blast of " << blast;
      } else if (type == ThingType::kPlasma) {
        const int n = int(h.exploded.size());
        EXPECT_EQ(h.damage % 5, 0);
        EXPECT_GE(h.damage, 5 * n);
        EXPECT_LE(h.damage, 40 * n) << "plasma";
      } else if (type == ThingType::kBfg) {
        EXPECT_EQ(h.exploded.size(), 1u);
        EXPECT_EQ(h.damage % 100, 0);
        EXPECT_GE(h.damage, 100);
        EXPECT_LE(h.damage, 800) << "BFG ball";
      } else {  // the spray
        EXPECT_GE(h.sprays, 1);
        EXPECT_GE(h.damage, 15 * h.sprays);
        EXPECT_LE(h.damage, 120 * h.sprays) << "BFG spray";
        ++sprays;
      }
    }
    if (weapon == Weapon::kMissile) {
      EXPECT_GT(burst[ThingType::kRocket], 10);
      EXPECT_EQ(burst.size(), 1u);
    } else if (weapon == Weapon::kPlasma) {
      EXPECT_GT(burst[ThingType::kPlasma], 100);
      EXPECT_EQ(burst.size(), 1u);
    } else {
      EXPECT_EQ(burst[ThingType::kBfg], 7) << "300 cells, 40 a shot";
      EXPECT_EQ(sprays, 7) << "each ball's spray hits too";
      EXPECT_EQ(burst[ThingType::kPlasma], 20) << "the 20 cells left, by the plasma gun";
    }
  }
}

// Bullets at a far wall: where the puffs land. The first shot of the pistol and the
// chaingun goes where the player looks; then each bullet turns by P_SubRandom() << 18
// (up to 255 << 18 of a binary angle, 5.6 degrees either way; the super shotgun's
// << 19), a triangular spread about the aim.
TEST(Weapons, BulletsSpreadAsDoomsDo) {
  struct Case {
    const char* name;
    int slot;
    Weapon weapon;
    int per_shot, shift;
    bool first_accurate;
  };
  for (const Case& c : {Case{"pistol", 1, Weapon::kPistol, 1, 18, true},
                        Case{"chaingun", 3, Weapon::kChaingun, 1, 18, true},
                        Case{"shotgun", 2, Weapon::kShotgun, 7, 18, false},
                        Case{"super shotgun", 2, Weapon::kSuperShotgun, 20, 19, false}}) {
    Play play(range_map(false));
    take_up(play, c.slot, c.weapon);
    play.put_player({64, 256}, 0);  // 960 units from the east wall
    std::set<uint32_t> seen;
    for (const Mobj* mo : play.world.things()) seen.insert(mo->id);
    std::vector<double> spread;  // each puff's turn from the aim, in units of 1 << shift
    int shots = 0;
    for (int t = 0; t < 700; ++t) {
      play.run(1, kFire);
      std::vector<double> puffs;
      for (const Mobj* mo : play.world.things()) {
        if (!seen.insert(mo->id).second || mo->type != ThingType::kPuff) continue;
        EXPECT_NEAR(to_double(mo->x), 1024 - 4, 0.5) << c.name << ": on the wall, 4 units out";
        const double turn = std::atan2(to_double(mo->y) - 256, to_double(mo->x) - 64) / (2 * M_PI) * 4294967296.0;
        puffs.push_back(turn / double(1 << c.shift));
      }
      if (puffs.empty()) continue;
      EXPECT_EQ(puffs.size(), size_t(c.per_shot)) << c.name;
      if (shots == 0 && c.first_accurate) {
        EXPECT_LT(std::abs(puffs[0]), 4) << c.name << ": the first shot goes where the player looks";
      } else {
        spread.insert(spread.end(), puffs.begin(), puffs.end());
      }
      ++shots;
    }
    ASSERT_GT(spread.size(), 40u) << c.name;
    const double mean = std::accumulate(spread.begin(), spread.end(), 0.0) / double(spread.size());
    double sq = 0, widest = 0;
    for (double s : spread) sq += (s - mean) * (s - mean), widest = std::max(widest, std::abs(s));
    const double deviation = std::sqrt(sq / double(spread.size()));
    std::printf("[ spread   ] %s: %d shots, %zu puffs, mean %.1f, deviation %.1f, widest %.1f (units of 1 << %d)\n",
                c.name, shots, spread.size(), mean, deviation, widest, c.shift);
    EXPECT_LE(widest, 255 + 4) << c.name << ": never beyond P_SubRandom's reach";
    EXPECT_GT(widest, 100) << c.name << ": the spread is used";
    EXPECT_LT(std::abs(mean), 35) << c.name << ": about the aim";
    EXPECT_GT(deviation, 65) << c.name << ": the difference of two random bytes spreads about 104";
    EXPECT_LT(deviation, 145) << c.name;
  }
}

// ---- demos -------------------------------------------------------------------------

// Random walks that press use, on the door and lift maps: replaying the recorded
// commands gives the same player and the same sectors at every tic.
// Doom's boss maps: when the last of the bosses dies, the map's tagged sectors move
// (A_BossDeath): MAP07's mancubi lower the tag-666 floors, its arachnotrons raise the
// tag-667 ones; E1M8's barons lower tag 666. Killed here by the player, one by one.
std::map<int, Fixed> floors_tagged(const World& w, int tag) {
  std::map<int, Fixed> out;
  for (const Sector& s : w.map().sectors)
    if (s.tag == tag) out[s.index] = s.floor_height;
  return out;
}

void kill_all(World& w, ThingType type) {
  for (const Mobj* m : w.things())
    if (m->type == type && m->health > 0) w.damage_mobj(const_cast<Mobj*>(m), nullptr, w.player().mo, 10000);
}

TEST(Bosses, TheLastBossOfTheMapMovesItsTaggedSectors) {
  struct Case {
    const char* wad;
    const char* map;
    ThingType boss;
    int tag;
    bool down;
  };
  for (const Case& c : {Case{"freedoom2.wad", "MAP07", ThingType::kFatso, 666, true},
                        Case{"freedoom2.wad", "MAP07", ThingType::kBaby, 667, false},
                        Case{"freedoom1.wad", "E1M8", ThingType::kBruiser, 666, true}}) {
    const wad::Stack wads = bsp::read_wads({test::freedoom_path(c.wad)});
    const level::Level level = bsp::build_wad_map(wads, c.map, {}, nullptr);
    World w(map_from_wads(wads, c.map, level), level, game_options_for(wads, c.map, 3), Random{});
    w.apply_cheats(kToggleGod);
    const std::map<int, Fixed> before = floors_tagged(w, c.tag);
    ASSERT_FALSE(before.empty()) << c.map << " has sectors tagged " << c.tag;
    const auto bosses = [&] {
      const std::vector<const Mobj*> things = w.things();
      return std::count_if(things.begin(), things.end(), [&](const Mobj* m) { return m->type == c.boss; });
    };
    ASSERT_GT(bosses(), 0) << c.map;
    for (int t = 0; t < 10; ++t) w.tick({});
    EXPECT_EQ(floors_tagged(w, c.tag), before) << c.map << ": nothing moves while a boss lives";
    kill_all(w, c.boss);
    for (int t = 0; t < 35 * 10; ++t) w.tick({});
    const std::map<int, Fixed> after = floors_tagged(w, c.tag);
    int moved = 0;
    for (const auto& [sector, height] : before)
      moved += c.down ? after.at(sector) < height : after.at(sector) > height;
    EXPECT_GT(moved, 0) << c.map << ": the tag-" << c.tag << " floors " << (c.down ? "lower" : "rise");
  }
}

TEST(Demos, ReplayIsExactWithDoorsAndLifts) {
  for (const TestMap& m : {door_map(1), lift_map()}) {
    Rng rng(5);
    Demo recorded;
    recorded.level_fingerprint = fingerprint(test::compile_test_map(m));
    for (int t = 0; t < 1500; ++t)
      recorded.tics.push_back({{int8_t(rng.below(3) == 0 ? -25 : 50), 0, int16_t(int(rng.below(801)) - 400),
                                uint8_t(rng.below(8) == 0 ? kBtUse : 0)},
                               0});
    const Demo demo = decode_demo(encode_demo(recorded), "d");
    struct Tic {
      Fixed x, y, z;
      std::vector<double> heights;
    };
    std::vector<Tic> first;
    for (int pass = 0; pass < 2; ++pass) {
      Play play(m);
      int moved = 0;
      for (size_t t = 0; t < demo.tics.size(); ++t) {
        play.run(1, demo.tics[t].cmd);
        Tic now{play.mo().x, play.mo().y, play.mo().z, {}};
        for (const level::SectorState& s : play.world.state().sectors)
          now.heights.push_back(s.floor), now.heights.push_back(s.ceiling);
        if (pass == 0) {
          first.push_back(now);
          continue;
        }
        moved += now.heights != first[0].heights;
        ASSERT_EQ(now.x, first[t].x) << "tic " << t;
        ASSERT_EQ(now.y, first[t].y) << "tic " << t;
        ASSERT_EQ(now.z, first[t].z) << "tic " << t;
        ASSERT_EQ(now.heights, first[t].heights) << "tic " << t;
      }
      if (pass == 1) {
        EXPECT_GT(moved, 0) << "something moved during the walk";
      }
    }
  }
}

}  // namespace
}  // namespace p3d::play
