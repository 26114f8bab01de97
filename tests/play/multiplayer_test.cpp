// Netgames by Doom's rules (engine/play/multiplayer.cpp and the rules it touches), on
// FreeDM's MAP01: four player starts and ten deathmatch starts. Deathmatch starts
// chosen at random, telefrags, frags, co-op respawning that keeps the level, placed
// weapons that stay, altdeath's items coming back, the deathmatch timer.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>

#include "engine/bsp/load.h"
#include "engine/play/chat.h"
#include "engine/play/intermission.h"
#include "engine/play/tally_count.h"
#include "engine/play/world.h"
#include "engine/wad/art.h"
#include "engine/wad/picture.h"
#include "engine/render/translation.h"
#include "engine/util/error.h"
#include "tests/support/support.h"
#include "tests/support/wad_pictures.h"

namespace p3d::play {
namespace {

constexpr int kItemBack = 30 * 35;  // altdeath's 30 seconds

// FreeDM's MAP01 played by `players` players in the mode given.
struct Netgame {
  level::Level level;
  std::unique_ptr<World> world;

  Netgame(int players, Deathmatch mode, int time_limit = 0, const std::function<void(Map&)>& edit = {}) {
    const auto wad = test::freedoom_path("freedm.wad");
    const wad::Stack wads = bsp::read_wads({wad});
    level = bsp::open_level(bsp::LevelSource{{}, {wad}, "MAP01"}).level;
    GameOptions o = game_options_for(wads, "MAP01", 3);
    for (int p = 0; p < kMaxPlayers; ++p) o.in_game[size_t(p)] = p < players;
    o.netgame = players > 1;
    o.deathmatch = mode;
    o.time_limit = time_limit;
    Map map = map_from_wads(wads, "MAP01", level);
    if (edit) edit(map);
    world = std::make_unique<World>(std::move(map), level, o, Random{});
  }
  Player& player(int n) { return world->players_[size_t(n)]; }
  void tick(int tics = 1, int use_by = -1) {
    for (int t = 0; t < tics; ++t) {
      std::array<TicCmd, kMaxPlayers> cmds{};
      if (use_by >= 0) cmds[size_t(use_by)].buttons = kBtUse;
      world->tick_players(cmds);
    }
  }
  // A placed thing of this type, or nullptr.
  Mobj* find(ThingType type) {
    for (const Mobj* m : world->things())
      if (m->type == type) return const_cast<Mobj*>(m);
    return nullptr;
  }
  size_t count(ThingType type) {
    const auto things = world->things();
    return size_t(std::count_if(things.begin(), things.end(), [&](const Mobj* m) { return m->type == type; }));
  }
};

TEST(Multiplayer, DeathmatchPutsEachPlayerOnADifferentDeathmatchStartChosenAtRandom) {
  Netgame g(4, Deathmatch::kDeathmatch);
  const auto& starts = g.world->deathmatch_starts();
  ASSERT_EQ(starts.size(), 10u);
  std::vector<std::pair<Fixed, Fixed>> at;
  for (int n = 0; n < 4; ++n) {
    const Mobj* mo = g.player(n).mo;
    ASSERT_NE(mo, nullptr) << "player " << n + 1;
    const auto spot = std::find_if(starts.begin(), starts.end(), [&](const MapThing& s) {
      return Fixed(s.x) << kFracBits == mo->x && Fixed(s.y) << kFracBits == mo->y;
    });
    ASSERT_NE(spot, starts.end()) << "player " << n + 1 << " stands on no deathmatch start";
    EXPECT_EQ(spot->type, n + 1) << "the start remembers who took it last (Doom's fake player start)";
    EXPECT_EQ(mo->angle, kAngle45 * Angle(spot->angle / 45));
    EXPECT_EQ((mo->flags & kTranslation) >> kTranslationShift, uint32_t(n)) << "the player's colour";
    EXPECT_EQ(g.player(n).cards, 0x3f) << "every key in deathmatch";
    at.push_back({mo->x, mo->y});
  }
  std::sort(at.begin(), at.end());
  EXPECT_EQ(std::unique(at.begin(), at.end()), at.end()) << "no two players on one start";
  // Keys are not spawned in deathmatch; the same map in co-op keeps the player starts.
  Netgame coop(4, Deathmatch::kNone);
  for (int n = 0; n < 4; ++n) {
    EXPECT_EQ(coop.player(n).cards, 0);
    const MapThing& start = coop.world->player_starts_[size_t(n)];
    EXPECT_EQ(coop.player(n).mo->x, Fixed(start.x) << kFracBits);
    EXPECT_EQ(coop.player(n).mo->y, Fixed(start.y) << kFracBits);
  }
}

TEST(Multiplayer, DeathmatchNeedsFourStarts) {
  auto keep_three = [](Map& map) {
    int kept = 0;
    std::erase_if(map.things, [&](const MapThing& t) { return t.type == 11 && ++kept > 3; });
  };
  try {
    Netgame g(2, Deathmatch::kDeathmatch, 0, keep_three);
    FAIL() << "a deathmatch on three starts";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "only 3 deathmatch starts on the map, 4 required");
  }
  EXPECT_NO_THROW(Netgame(2, Deathmatch::kNone, 0, keep_three));  // co-op needs none
}

TEST(Multiplayer, ATelefragKillsWhoeverStandsThereAndCountsAFrag) {
  Netgame g(2, Deathmatch::kDeathmatch);
  Mobj* victim = g.player(0).mo;
  Mobj* killer = g.player(1).mo;
  ASSERT_TRUE(g.world->teleport_move(killer, victim->x, victim->y));
  EXPECT_EQ(killer->x, victim->x);
  EXPECT_LE(g.player(0).inv.health, 0);
  EXPECT_EQ(g.player(0).state, PlayerState::kDead);
  EXPECT_EQ(g.player(1).frags[0], 1);
  EXPECT_EQ(frag_total(g.player(1)), 1);
  EXPECT_EQ(frag_total(g.player(0)), 0);
}

TEST(Multiplayer, FragsCountKillsOfOthersLessDeathsByOnesOwnHandOrTheWorlds) {
  Netgame g(3, Deathmatch::kDeathmatch);
  g.world->damage_mobj(g.player(1).mo, g.player(0).mo, g.player(0).mo, 10000);
  g.world->damage_mobj(g.player(2).mo, g.player(0).mo, g.player(0).mo, 10000);
  EXPECT_EQ(g.player(0).frags, (std::array<int, 4>{0, 1, 1, 0}));
  EXPECT_EQ(frag_total(g.player(0)), 2);
  g.world->damage_mobj(g.player(0).mo, nullptr, nullptr, 10000);  // the floor's slime, say
  EXPECT_EQ(g.player(0).frags[0], 1);
  EXPECT_EQ(frag_total(g.player(0)), 1);
}

TEST(Multiplayer, ADeathmatchPlayerRespawnsAtARandomStartWithAFreshInventoryAndKeepsTheFrags) {
  Netgame g(2, Deathmatch::kDeathmatch);
  g.world->damage_mobj(g.player(0).mo, g.player(1).mo, g.player(1).mo, 10000);
  Mobj* corpse = g.player(0).mo;
  g.tick(1, 0);  // use: reborn asked
  EXPECT_EQ(g.player(0).state, PlayerState::kReborn);
  const size_t fogs = g.count(ThingType::kTfog);
  g.tick();
  const Player& p = g.player(0);
  ASSERT_NE(p.mo, corpse);
  EXPECT_EQ(corpse->player, nullptr) << "the corpse stays, a thing like any other";
  EXPECT_FALSE(corpse->removed);
  EXPECT_EQ(p.state, PlayerState::kLive);
  EXPECT_EQ(p.inv.health, 100);
  EXPECT_EQ(p.inv.ready, Weapon::kPistol);
  EXPECT_EQ(g.player(1).frags[0], 1);
  EXPECT_GT(g.count(ThingType::kTfog), fogs) << "a teleport fog where the player came back";
  const auto& starts = g.world->deathmatch_starts();
  EXPECT_TRUE(std::any_of(starts.begin(), starts.end(), [&](const MapThing& s) {
    return Fixed(s.x) << kFracBits == p.mo->x && Fixed(s.y) << kFracBits == p.mo->y && s.type == 1;
  }));
}

TEST(Multiplayer, ACoopPlayerRespawnsAtItsStartAndTheLevelGoesOn) {
  Netgame g(2, Deathmatch::kNone);
  g.tick(10);
  const int time = g.world->level_time();
  g.world->damage_mobj(g.player(1).mo, nullptr, nullptr, 10000);
  g.tick(1, 1);
  g.tick();
  const MapThing& start = g.world->player_starts_[1];
  EXPECT_EQ(g.player(1).state, PlayerState::kLive);
  EXPECT_EQ(g.player(1).mo->x, Fixed(start.x) << kFracBits);
  EXPECT_EQ(g.player(1).mo->y, Fixed(start.y) << kFracBits);
  EXPECT_EQ(g.world->level_time(), time + 2) << "the level is not started again";
  EXPECT_EQ(g.player(1).frags[1], 1) << "the world's kill counts against the player";
}

TEST(Multiplayer, PlacedWeaponsStayInCoopAndDeathmatchAndGoInAltdeath) {
  for (Deathmatch mode : {Deathmatch::kNone, Deathmatch::kDeathmatch, Deathmatch::kAltdeath}) {
    Netgame g(2, mode);
    Mobj* gun = g.find(ThingType::kShotgun);
    ASSERT_NE(gun, nullptr);
    Player& p = g.player(0);
    g.world->touch_special_thing(gun, p.mo);
    EXPECT_TRUE(p.inv.weapons[size_t(Weapon::kShotgun)]);
    EXPECT_EQ(gun->removed, mode == Deathmatch::kAltdeath) << int(mode);
    // Deathmatch gives five clips of shells, co-op and altdeath two.
    EXPECT_EQ(p.inv.ammo[size_t(AmmoType::kShell)], mode == Deathmatch::kDeathmatch ? 20 : 8) << int(mode);
    g.world->touch_special_thing(gun, p.mo);  // once owned, a staying weapon gives nothing more
    if (mode != Deathmatch::kAltdeath) {
      EXPECT_EQ(p.inv.ammo[size_t(AmmoType::kShell)], mode == Deathmatch::kDeathmatch ? 20 : 8);
    }
  }
}

TEST(Multiplayer, AltdeathItemsComeBackThirtySecondsAfterTheyWereTaken) {
  for (Deathmatch mode : {Deathmatch::kDeathmatch, Deathmatch::kAltdeath}) {
    Netgame g(2, mode);
    Mobj* item = g.find(ThingType::kShotgun);
    ASSERT_NE(item, nullptr);
    const Fixed x = item->x, y = item->y;
    const size_t before = g.count(ThingType::kShotgun);
    g.player(0).inv.weapons[size_t(Weapon::kShotgun)] = false;
    g.world->touch_special_thing(item, g.player(0).mo);
    const size_t taken = g.count(ThingType::kShotgun);
    g.tick(kItemBack);
    EXPECT_EQ(g.count(ThingType::kShotgun), taken) << "not before 30 seconds";
    g.tick();
    if (mode == Deathmatch::kAltdeath) {
      EXPECT_EQ(taken, before - 1);
      EXPECT_EQ(g.count(ThingType::kShotgun), before);
      const auto things = g.world->things();
      EXPECT_TRUE(std::any_of(things.begin(), things.end(), [&](const Mobj* m) {
        return m->type == ThingType::kShotgun && m->x == x && m->y == y;
      }));
      EXPECT_GE(g.count(ThingType::kIfog), 1u) << "with the item fog";
    } else {
      EXPECT_EQ(g.count(ThingType::kShotgun), before) << "deathmatch's weapon never left";
    }
  }
}

TEST(Multiplayer, TheTimerEndsADeathmatchLevel) {
  Netgame g(2, Deathmatch::kDeathmatch, 1);
  EXPECT_EQ(g.world->time_left(), 60 * 35);
  g.tick(60 * 35 - 1);
  EXPECT_EQ(g.world->exit(), ExitKind::kNone);
  g.tick();
  EXPECT_EQ(g.world->exit(), ExitKind::kNormal);
  Netgame coop(2, Deathmatch::kNone, 1);  // Doom's timer is for deathmatch alone
  EXPECT_EQ(coop.world->time_left(), 0);
}

// Tics of Doom's intermission; `press_by` presses fire in the first of them.
std::vector<Sound> count_tally(TallyCount& count, World& world, int tics, int press_by = -1) {
  std::vector<Sound> heard;
  for (int t = 0; t < tics; ++t) {
    std::array<TicCmd, kMaxPlayers> cmds{};
    if (t == 0 && press_by >= 0) cmds[size_t(press_by)].buttons = kBtAttack;
    count.tic(world, cmds);
    for (Sound s : count.take_sounds()) heard.push_back(s);
  }
  return heard;
}

// The intermission after a deathmatch level: Doom's frag table (WI_drawDeathmatchStats),
// counted a frag a tic after a second's pause, then waiting for any player's press.
TEST(Multiplayer, TheDeathmatchIntermissionCountsTheFragTable) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedm.wad")});
  const std::vector<uint32_t> palette = wad::Art(wads).palette();
  const auto art = IntermissionArt::load(wads, 0, 1, 2);
  ASSERT_TRUE(art.has_value());
  Netgame g(4, Deathmatch::kDeathmatch);
  Tally t;
  t.deathmatch = true;
  t.in_game = {true, true, false, true};
  t.me = 1;
  t.frags[0] = {0, 3, 0, 1};
  t.frags[1] = {2, 1, 0, 0};  // one death by its own hand
  t.frags[3] = {0, 0, 0, 0};
  t.frags[2] = {50, 50, 0, 50};  // a player not in the game counts for no one
  TallyCount count(t, true);
  EXPECT_TRUE(count_tally(count, *g.world, 35).empty()) << "a second's pause";
  EXPECT_EQ(count.shown().deathmatch_frags[0][1], 0);
  count_tally(count, *g.world, 1);
  EXPECT_EQ(count.shown().deathmatch_frags[0][1], 1) << "a frag a tic";
  EXPECT_EQ(count.shown().deathmatch_totals[0], 4) << "the totals at once";
  const std::vector<Sound> rest = count_tally(count, *g.world, 2);
  EXPECT_EQ(count.shown().deathmatch_frags[0][1], 3);
  EXPECT_EQ(std::count(rest.begin(), rest.end(), Sound::kBarexp), 0) << "still counting at its last step";
  EXPECT_EQ(count_tally(count, *g.world, 1), std::vector<Sound>{Sound::kBarexp}) << "the tic after: done";
  count_tally(count, *g.world, 35 + 200);
  EXPECT_EQ(count.stage(), TallyCount::Stage::kCounting) << "it waits for a press";
  EXPECT_EQ(count_tally(count, *g.world, 1, 2), std::vector<Sound>{}) << "player 3 is not in this game";
  EXPECT_EQ(count_tally(count, *g.world, 1, 3), std::vector<Sound>{Sound::kSlop}) << "player 4's press: on";
  EXPECT_TRUE(g.player(3).attack_down) << "Doom keeps the button down in the player";
  EXPECT_EQ(count.stage(), TallyCount::Stage::kLeaving) << "Doom II: no episode map";
  count_tally(count, *g.world, 9);
  EXPECT_FALSE(count.over());
  count_tally(count, *g.world, 1);
  EXPECT_TRUE(count.over()) << "ten tics later";
  EXPECT_FALSE(g.player(3).attack_down);

  TallyCount hurried(t, true);
  count_tally(hurried, *g.world, 3);
  EXPECT_EQ(count_tally(hurried, *g.world, 1, 0), std::vector<Sound>{Sound::kBarexp}) << "a press in the pause: all at once";
  image::Image frame(320, 200);
  art->draw(t, hurried.shown(), frame, palette);
  auto shows = [&](const std::string& lump, int x, int y) { return test::shows_picture(frame, wads, palette, lump, x, y); };
  auto width = [&](const std::string& lump) { return test::picture_width(wads, lump); };
  EXPECT_TRUE(shows("WIKILRS", 10, 100));
  EXPECT_TRUE(shows("WIVCTMS", 5, 50));
  EXPECT_TRUE(shows("WIMSTT", 269 - width("WIMSTT") / 2, 68 - 33 + 10));
  EXPECT_TRUE(shows("STPB0", 42 - width("STPB0") / 2, 68)) << "player 1's row";
  EXPECT_TRUE(shows("STPB3", 42 + 4 * 40 - width("STPB3") / 2, 68 - 33)) << "player 4's column";
  EXPECT_FALSE(shows("STPB2", 42 - width("STPB2") / 2, 68 + 2 * 33)) << "player 3 is not in the game";
  EXPECT_TRUE(shows("STFST01", 42 - width("STPB1") / 2, 68 + 33)) << "the console player's row: its face";
  const int digit = width("WINUM0");
  EXPECT_TRUE(shows("WINUM3", 42 + 2 * 40 + digit - digit, 68 + 10)) << "player 1 killed player 2 three times";
  EXPECT_TRUE(shows("WINUM4", 269 + digit - digit, 68 + 10)) << "player 1's total";
  EXPECT_EQ(hurried.shown().deathmatch_totals[1], 1) << "two kills less one death by its own hand";
}

// The intermission after a co-op level: each player's counts (WI_drawNetgameStats),
// two percent a tic, the frag column only where someone has frags.
TEST(Multiplayer, TheCoopIntermissionCountsEachPlayer) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedm.wad")});
  const std::vector<uint32_t> palette = wad::Art(wads).palette();
  const auto art = IntermissionArt::load(wads, 0, 1, 2);
  ASSERT_TRUE(art.has_value());
  auto width = [&](const std::string& lump) { return test::picture_width(wads, lump); };
  auto height = [&](const std::string& lump) { return wad::decode_picture(wads.find(lump)->bytes, lump).height; };
  auto shows = [&](const image::Image& frame, const std::string& lump, int x, int y) {
    return test::shows_picture(frame, wads, palette, lump, x, y);
  };
  Netgame g(2, Deathmatch::kNone);
  Tally t;
  t.netgame = true;
  t.in_game = {true, true, false, false};
  t.total_kills = 10;
  t.player_kills = {5, 10, 0, 0};  // 50% and 100%
  TallyCount count(t, true);
  EXPECT_EQ(count.shown().kills[0], 0) << "shown from the start";
  EXPECT_EQ(count.shown().kills[2], -1) << "not in the game";
  count_tally(count, *g.world, 35 + 25);
  EXPECT_EQ(count.shown().kills[0], 50);
  EXPECT_EQ(count.shown().kills[1], 50);
  EXPECT_EQ(count_tally(count, *g.world, 25).back(), Sound::kBarexp);
  EXPECT_EQ(count.shown().kills[1], 100) << "counted together, to the end of the longest";
  EXPECT_EQ(count.shown().items[0], 0);
  count_tally(count, *g.world, 1, 1);
  EXPECT_EQ(count.shown().secrets[1], 0) << "a press shows the rest";
  EXPECT_EQ(count_tally(count, *g.world, 1, 1), std::vector<Sound>{}) << "the button still down: no new press";
  count_tally(count, *g.world, 1);
  EXPECT_EQ(count_tally(count, *g.world, 1, 0), std::vector<Sound>{Sound::kSgcock});
  EXPECT_EQ(count.stage(), TallyCount::Stage::kLeaving);

  image::Image frame(320, 200);
  TallyCount done(t, true);
  count_tally(done, *g.world, 1, 1);  // player 1 still holds fire from before: player 2 presses
  art->draw(t, done.shown(), frame, palette);
  const int x = 32 + width("STFST01") / 2 + 32;  // no frags: Doom's table moves right
  const int first_row = 50 + height("WIOSTK");
  EXPECT_TRUE(shows(frame, "WIOSTK", x + 64 - width("WIOSTK"), 50));
  EXPECT_TRUE(shows(frame, "WIOSTS", x + 3 * 64 - width("WIOSTS"), 50));
  EXPECT_FALSE(shows(frame, "WIFRGS", x + 4 * 64 - width("WIFRGS"), 50)) << "nobody has a frag";
  EXPECT_TRUE(shows(frame, "STPB1", x - width("STPB1"), first_row + 33)) << "player 2's row";
  const int percent_x = x + 64 - width("WIPCNT"), digit = width("WINUM0");
  EXPECT_TRUE(shows(frame, "WINUM5", percent_x - 2 * digit, first_row + 10)) << "player 1: 50%";
  EXPECT_TRUE(shows(frame, "WINUM1", percent_x - 3 * digit, first_row + 33 + 10)) << "player 2: 100%";
  t.frags[1][0] = 1;  // a frag: the column shows, the table moves left
  TallyCount with_frags(t, true);
  EXPECT_TRUE(with_frags.shown().show_frags);
  image::Image frags_frame(320, 200);
  art->draw(t, with_frags.shown(), frags_frame, palette);
  EXPECT_TRUE(shows(frags_frame, "WIFRGS", x - 32 + 4 * 64 - width("WIFRGS"), 50));
  t.frags[1][0] = 0;
  EXPECT_TRUE(TallyCount(t, true, true).shown().show_frags) << "Doom's dofrags stays on from the last netgame tally";
}

// Doom's chat: a line typed by one player goes out a character a tic in its commands,
// and shows on the other nodes when its enter arrives, to everyone or to one player.
TEST(Multiplayer, ChatTravelsACharacterATicAndShowsWhereItIsMeantFor) {
  Chat green, indigo, brown;
  green.start(Chat::kToEveryone);
  EXPECT_TRUE(green.typing());
  for (int c : std::initializer_list<int>{'h', 'i', '!', '~', Chat::kBackspace, 'o', Chat::kEnter}) green.key(c);
  EXPECT_FALSE(green.typing());
  EXPECT_FALSE(green.key('x')) << "not typing";
  const std::array<bool, kMaxPlayers> in_game{true, true, true, false};
  std::optional<Chat::Line> at_indigo, at_brown, at_green;
  for (int t = 0; t < 10; ++t) {
    std::array<TicCmd, kMaxPlayers> cmds{};
    cmds[0].chatchar = green.next_char();
    if (auto m = indigo.receive(cmds, in_game, 1)) at_indigo = m;
    if (auto m = brown.receive(cmds, in_game, 2)) at_brown = m;
    if (auto m = green.receive(cmds, in_game, 0)) at_green = m;
  }
  ASSERT_TRUE(at_indigo && at_brown);
  EXPECT_EQ(at_indigo->player, 0);
  EXPECT_EQ(at_indigo->text, "HIO") << "in upper case; '~' is no Doom letter; the backspace took the '!' back";
  EXPECT_EQ(at_brown->text, "HIO");
  EXPECT_FALSE(at_green) << "not shown back to its writer by the tics";

  Chat red;
  red.start(2);  // to indigo only
  for (int c : std::initializer_list<int>{'y', 'o', Chat::kEnter}) red.key(c);
  std::optional<Chat::Line> to_indigo, to_brown;
  for (int t = 0; t < 5; ++t) {
    std::array<TicCmd, kMaxPlayers> cmds{};
    cmds[3].chatchar = red.next_char();
    const std::array<bool, kMaxPlayers> four{true, true, true, true};
    if (auto m = indigo.receive(cmds, four, 1)) to_indigo = m;
    if (auto m = brown.receive(cmds, four, 2)) to_brown = m;
  }
  ASSERT_TRUE(to_indigo);
  EXPECT_EQ(to_indigo->player, 3);
  EXPECT_EQ(to_indigo->text, "YO");
  EXPECT_FALSE(to_brown) << "meant for indigo";
  Chat quiet;
  quiet.start(Chat::kToEveryone);
  quiet.key('a');
  quiet.key(Chat::kEscape);
  EXPECT_FALSE(quiet.typing());
}

// Other players are drawn in their colours: the World shows each player's colour bits,
// and the renderers draw the green ramp through Doom's translation (r_draw.c).
TEST(Multiplayer, OtherPlayersShowInTheirColours) {
  static_assert(render::translate_index(0x70, 1) == 0x60 && render::translate_index(0x7f, 1) == 0x6f);
  static_assert(render::translate_index(0x75, 2) == 0x45 && render::translate_index(0x75, 3) == 0x25);
  static_assert(render::translate_index(0x6f, 3) == 0x6f && render::translate_index(0x80, 1) == 0x80);
  static_assert(render::translate_index(0x75, 0) == 0x75);
  Netgame g(4, Deathmatch::kNone);
  std::set<int> colours;
  for (const level::ShownThing& t : g.world->state().things)
    if (t.flags & level::kShownTranslation) colours.insert((t.flags & level::kShownTranslation) >> level::kShownTranslationShift);
  EXPECT_EQ(colours, (std::set<int>{1, 2, 3})) << "players 2, 3 and 4 (the console player is not shown)";
  // A translated picture differs from its source exactly where the source is green.
  const level::Level& level = g.level;
  for (size_t i = 0; i < level.textures.size(); ++i) {
    const level::Texture& source = level.textures[i];
    if (source.name.rfind("PLAY", 0) != 0 || source.indices.empty()) continue;
    const level::Texture& red = render::translated_texture(level, i, 3);
    ASSERT_EQ(red.indices.size(), source.indices.size());
    size_t green = 0;
    for (size_t k = 0; k < source.indices.size(); ++k) {
      const bool is_green = source.indices[k] >= 0x70 && source.indices[k] <= 0x7f;
      green += is_green;
      EXPECT_EQ(red.indices[k], is_green ? source.indices[k] - 0x50 : source.indices[k]);
    }
    EXPECT_GT(green, 0u) << source.name;
    EXPECT_EQ(&render::translated_texture(level, i, 3), &red) << "made once";
    return;
  }
  FAIL() << "no PLAY sprite in the level";
}

// A player who leaves a netgame (Doom's PlayerQuitGame): out of the game, its body left
// standing where it was, its commands no longer played, the others told.
TEST(Multiplayer, APlayerWhoLeavesStaysStandingAndIsToldOf) {
  Netgame g(3, Deathmatch::kNone);
  Mobj* body = g.player(2).mo;
  ASSERT_NE(body, nullptr);
  g.world->player_left(2);
  EXPECT_FALSE(g.world->in_game(2));
  EXPECT_TRUE(g.world->in_game(1));
  EXPECT_EQ(g.player(0).message, "Player 3 left the game");
  const Fixed x = body->x, y = body->y;
  std::array<TicCmd, kMaxPlayers> cmds{};
  cmds[2] = {50, 0, 0, 0};  // no longer read
  cmds[1] = {50, 0, 0, 0};
  const Fixed x1 = g.player(1).mo->x, y1 = g.player(1).mo->y;
  for (int t = 0; t < 10; ++t) g.world->tick_players(cmds);
  EXPECT_EQ(body->x, x);
  EXPECT_EQ(body->y, y);
  EXPECT_TRUE(g.player(1).mo->x != x1 || g.player(1).mo->y != y1) << "the others play on";
  const auto things = g.world->things();
  EXPECT_NE(std::find(things.begin(), things.end(), body), things.end()) << "its body stays";
}

}  // namespace
}  // namespace p3d::play
