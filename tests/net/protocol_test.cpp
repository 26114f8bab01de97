// Chocolate Doom's protocol, byte by byte (the layouts of net_structrw.c), and the
// client's side of a game against a server played here by the test.
#include <gtest/gtest.h>

#include "engine/net/client.h"
#include "engine/net/server.h"
#include "engine/net/protocol.h"

namespace p3d::net {
namespace {

std::vector<uint8_t> bytes_of(PacketWriter w) { return std::move(w.bytes()); }

TEST(NetProtocol, RecordsReadBackAsWritten) {
  GameSettings s;
  s.extratics = 2, s.deathmatch = 2, s.episode = 1, s.map = 7, s.skill = 4, s.fast_monsters = true;
  s.time_limit = 20, s.load_game = -1, s.num_players = 3, s.console_player = 2, s.player_classes = {0, 1, 2};
  PacketWriter w(PacketType::kGameStart);
  w.settings(s);
  const std::vector<uint8_t> b = bytes_of(std::move(w));
  EXPECT_EQ(b.size(), 2u + 12 + 4 + 4 + 3) << "type, twelve bytes, the time limit, four bytes, a class per player";
  EXPECT_EQ((std::vector<uint8_t>{b[0], b[1]}), (std::vector<uint8_t>{0, 5})) << "big-endian type";
  PacketReader r(b);
  ASSERT_EQ(r.u16(), 5u);
  const auto back = r.settings();
  ASSERT_TRUE(back);
  EXPECT_EQ(back->map, 7);
  EXPECT_EQ(back->skill, 4);
  EXPECT_EQ(back->load_game, -1);
  EXPECT_EQ(back->time_limit, 20);
  EXPECT_EQ(back->console_player, 2);
  EXPECT_TRUE(back->fast_monsters);
  EXPECT_EQ(back->player_classes[2], 2);
  EXPECT_EQ(r.left(), 0u);

  WaitData wd;
  wd.num_players = 2, wd.max_players = 4, wd.is_controller = true, wd.console_player = 1;
  wd.player_names = {"ann", "bob"}, wd.player_addresses = {"127.0.0.1", "10.0.0.2"};
  PacketWriter ww(PacketType::kWaitingData);
  ww.wait_data(wd);
  const std::vector<uint8_t> wb = bytes_of(std::move(ww));
  PacketReader wr(wb);
  wr.u16();
  const auto wback = wr.wait_data();
  ASSERT_TRUE(wback);
  EXPECT_EQ(wback->player_names, wd.player_names);
  EXPECT_EQ(wback->player_addresses, wd.player_addresses);
  EXPECT_EQ(wback->console_player, 1);
  // Cut anywhere, a record is refused, never read past the end.
  for (size_t cut = 2; cut < wb.size(); ++cut) {
    PacketReader short_one(std::span<const uint8_t>(wb).first(cut));
    short_one.u16();
    EXPECT_FALSE(short_one.wait_data()) << "cut at " << cut;
  }
}

TEST(NetProtocol, ATicTravelsAsItsChangesAndTurnsLoseTheirLowByteForVanillaDemos) {
  const TicCmd before{25, 0, 640, 1, 7, 0}, now{25, -24, -1000, 1, 9, 'h'};
  const TicDiff d = diff_tic(before, now);
  EXPECT_EQ(d.changed, TicDiff::kSide | TicDiff::kTurn | TicDiff::kConsistancy | TicDiff::kChat);
  for (const bool low : {false, true}) {
    FullTic t;
    t.latency = -3;
    t.in_game = {true, false, true};
    t.cmds[0] = d;
    t.cmds[2] = diff_tic({}, before);
    PacketWriter w(PacketType::kGameData);
    w.full_tic(t, low);
    const std::vector<uint8_t> b = bytes_of(std::move(w));
    PacketReader r(b);
    r.u16();
    const auto back = r.full_tic(low);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->latency, -3);
    EXPECT_EQ(back->in_game, t.in_game);
    const TicCmd patched = patch_tic(before, back->cmds[0]);
    EXPECT_EQ(patched.side, -24);
    EXPECT_EQ(patched.turn, low ? int16_t(-1000 / 256 * 256) : -1000);
    EXPECT_EQ(patched.consistancy, 9);
    EXPECT_EQ(patched.chatchar, 'h');
    TicCmd next = now;
    next.chatchar = 0;
    EXPECT_EQ(patch_tic(patched, diff_tic(now, next)).chatchar, 0) << "a character is typed once";
  }
}

TEST(NetProtocol, EightBitTicNumbersAreMadeWholeNearTheWindow) {
  EXPECT_EQ(expand_tic(0x1f0, 0xf5), 0x1f5u);
  EXPECT_EQ(expand_tic(0x1f0, 0x02), 0x202u) << "past the wrap";
  EXPECT_EQ(expand_tic(0x205, 0xfe), 0x1feu) << "just before it";
}

// ---- the client against a server played by the test

struct Harness {
  Harness() : client(options(), 0) {}
  static Client::Options options() {
    Client::Options o;
    o.connect.game_mission = 1, o.connect.game_mode = 2;
    o.settings.map = 5;
    return o;
  }
  // The packets the client sent by `now`, as their types (reliable bit dropped).
  std::vector<uint32_t> sent(uint32_t now) {
    client.run(now);
    last = client.take_outgoing();
    std::vector<uint32_t> types;
    for (const auto& p : last) types.push_back(PacketReader(p).u16().value() & ~uint32_t(kReliable));
    return types;
  }
  const std::vector<uint8_t>* find(PacketType t) const {
    for (const auto& p : last)
      if ((PacketReader(p).u16().value() & ~uint32_t(kReliable)) == uint32_t(t)) return &p;
    return nullptr;
  }
  void reliable(PacketType t, uint32_t now, const std::function<void(PacketWriter&)>& body = {}) {
    PacketWriter w(t, true);
    w.u8(server_seq++);
    if (body) body(w);
    client.receive(w.bytes(), now);
  }
  void to_game(uint32_t now) {
    sent(now);  // SYN
    reliable(PacketType::kSyn, now, [](PacketWriter& w) { w.str("Chocolate Doom 3.0.0"), w.str(kProtocolName); });
    reliable(PacketType::kLaunch, now, [](PacketWriter& w) { w.u8(2); });
    reliable(PacketType::kGameStart, now, [](PacketWriter& w) {
      GameSettings s;
      s.num_players = 2, s.console_player = 1, s.extratics = 1;
      w.settings(s);
    });
  }
  Client client;
  std::vector<std::vector<uint8_t>> last;
  uint8_t server_seq = 0;
};

uint32_t type_of(const std::vector<uint8_t>& p) { return PacketReader(p).u16().value(); }

TEST(NetClient, JoinsWithSynAcknowledgesReliablePacketsInOrderAndSendsItsSettingsAtTheLaunch) {
  Harness h;
  EXPECT_EQ(h.sent(0), std::vector<uint32_t>{uint32_t(PacketType::kSyn)});
  PacketReader syn(h.last[0]);
  syn.u16();
  EXPECT_EQ(syn.u32(), kMagic);
  EXPECT_EQ(syn.str(), "pseudo3d");
  EXPECT_TRUE(syn.protocol_list_has_ours());
  ASSERT_TRUE(syn.connect_data());
  EXPECT_EQ(syn.str(), "player");
  EXPECT_TRUE(h.sent(500).empty()) << "SYN again after a second, not sooner";
  EXPECT_EQ(h.sent(1001), std::vector<uint32_t>{uint32_t(PacketType::kSyn)});

  h.reliable(PacketType::kSyn, 1100, [](PacketWriter& w) { w.str("Chocolate Doom 3.0.0"), w.str(kProtocolName); });
  EXPECT_EQ(h.client.state(), Client::State::kWaitingLaunch);
  ASSERT_EQ(h.client.take_outgoing().size(), 1u) << "the reliable SYN acknowledged";
  // A reliable packet seen twice is acknowledged twice and acted on once.
  h.server_seq = 0;
  h.reliable(PacketType::kLaunch, 1200, [](PacketWriter& w) { w.u8(2); });
  EXPECT_EQ(h.client.state(), Client::State::kWaitingLaunch) << "an old sequence number: dropped";
  h.reliable(PacketType::kLaunch, 1200, [](PacketWriter& w) { w.u8(2); });
  EXPECT_EQ(h.client.state(), Client::State::kWaitingStart);
  h.sent(1201);
  const std::vector<uint8_t>* start = h.find(PacketType::kGameStart);
  ASSERT_TRUE(start) << "our settings, sent at the launch";
  EXPECT_TRUE(type_of(*start) & kReliable);
  PacketReader sr(*start);
  sr.u16(), sr.u8();
  EXPECT_EQ(sr.settings().value().map, 5);
  EXPECT_TRUE(h.sent(1500).empty() || !h.find(PacketType::kGameStart)) << "not again before a second";
  h.sent(2300);
  EXPECT_TRUE(h.find(PacketType::kGameStart)) << "again, unacknowledged";
}

TEST(NetClient, PlaysTheLockstepInOrderAndAsksAgainForWhatIsMissing) {
  Harness h;
  h.to_game(0);
  ASSERT_EQ(h.client.state(), Client::State::kInGame);
  EXPECT_EQ(h.client.settings().console_player, 1);
  h.client.take_outgoing();
  // Our tics: each packet repeats the last one too (extratics 1).
  h.client.send_tic({25, 0, 0, 0, 0, 0}, 10);
  h.client.send_tic({50, 0, 0, 1, 0, 0}, 40);
  auto ours = h.client.take_outgoing();
  ASSERT_EQ(ours.size(), 2u);
  PacketReader g(ours[1]);
  g.u16();
  EXPECT_EQ(g.u8(), 0u) << "nothing received yet";
  EXPECT_EQ(g.u8(), 0u) << "from tic 0";
  EXPECT_EQ(g.u8(), 2u) << "two tics";
  // The server's tics 0 and 2 arrive, 1 is lost: 0 is played, 1 is asked for again.
  auto server_tics = [&](uint32_t first, std::vector<int8_t> forward, uint32_t now) {
    PacketWriter w(PacketType::kGameData);
    w.u8(first), w.u8(uint32_t(forward.size()));
    TicCmd last{};
    for (int8_t f : forward) {
      FullTic t;
      t.in_game[0] = true;
      TicCmd c = last;
      c.forward = f;
      t.cmds[0] = diff_tic(last, c);
      last = c;
      w.full_tic(t, false);
    }
    h.client.receive(w.bytes(), now);
  };
  server_tics(0, {10}, 50);
  server_tics(2, {30}, 60);
  h.sent(70);
  const std::vector<uint8_t>* resend = h.find(PacketType::kGameDataResend);
  ASSERT_TRUE(resend);
  PacketReader rr(*resend);
  rr.u16();
  EXPECT_EQ(rr.u32(), 1u);
  EXPECT_EQ(rr.u8(), 1u);
  auto t0 = h.client.next_server_tic();
  ASSERT_TRUE(t0);
  EXPECT_TRUE(t0->in_game[0]);
  EXPECT_FALSE(t0->in_game[1]) << "ours is our own";
  EXPECT_EQ(t0->cmds[0].forward, 10);
  EXPECT_FALSE(h.client.next_server_tic()) << "tic 1 is missing: 2 waits";
  server_tics(1, {20}, 80);
  h.sent(90);
  auto t1 = h.client.next_server_tic(), t2 = h.client.next_server_tic();
  ASSERT_TRUE(t1 && t2);
  EXPECT_EQ(t1->cmds[0].forward, 20);
  EXPECT_EQ(t2->cmds[0].forward, 30) << "its change is against the server's tic before it";
  // The server asks again for our tic 0.
  PacketWriter ask(PacketType::kGameDataResend);
  ask.u32(0), ask.u8(1);
  h.client.receive(ask.bytes(), 100);
  auto again = h.client.take_outgoing();
  ASSERT_EQ(again.size(), 1u);
  PacketReader ar(again[0]);
  ar.u16();
  EXPECT_EQ(ar.u8(), 3u) << "three server tics received";
  EXPECT_EQ(ar.u8(), 0u);
  EXPECT_EQ(ar.u8(), 1u);
  // A request for tics at the top of the 32-bit range (found by the fuzzer: the range
  // once wrapped and the search ran four billion steps) asks for nothing we keep.
  for (uint32_t count : {1u, 2u, 255u}) {
    PacketWriter far(PacketType::kGameDataResend);
    far.u32(0xffffffffu), far.u8(count);
    h.client.receive(far.bytes(), 110);
    EXPECT_TRUE(h.client.take_outgoing().empty()) << count;
  }
}

TEST(NetClient, SaysWhyItStopped) {
  Harness refused;
  refused.sent(0);
  PacketWriter no(PacketType::kRejected);
  no.str("Server is full!");
  refused.client.receive(no.bytes(), 10);
  EXPECT_TRUE(refused.sent(1200).empty()) << "no SYN after a refusal";
  EXPECT_EQ(refused.client.state(), Client::State::kConnecting) << "its answer to an earlier SYN may still come";
  refused.sent(1511);
  EXPECT_EQ(refused.client.state(), Client::State::kDisconnected);
  EXPECT_EQ(refused.client.error(), "the server refused: Server is full!");

  Harness late;  // refused, then the answer to the SYN before comes: in
  late.sent(0);
  late.client.receive(no.bytes(), 10);
  late.reliable(PacketType::kSyn, 900, [](PacketWriter& w) { w.str("Chocolate Doom 3.0.0"), w.str(kProtocolName); });
  late.sent(2000);
  EXPECT_EQ(late.client.state(), Client::State::kWaitingLaunch);

  Harness silent;
  silent.sent(0);
  silent.sent(5001);
  EXPECT_EQ(silent.client.state(), Client::State::kDisconnected);
  EXPECT_EQ(silent.client.error(), "no answer from the server");

  Harness lost;
  lost.to_game(0);
  lost.sent(29000);
  EXPECT_EQ(lost.client.state(), Client::State::kInGame);
  lost.sent(30001);
  EXPECT_EQ(lost.client.state(), Client::State::kDisconnected);
  EXPECT_EQ(lost.client.error(), "the server stopped answering (30 s)");
}

// Our server and two of our clients, their packets carried in memory (each a few
// milliseconds later, one in ten lost on the way): the first to join leads and starts
// the game at two players, each is told its number, and each plays the other's
// commands in order; a third to come is refused once the game is on.
TEST(NetServer, TwoClientsPlayEachOthersCommandsThroughALossyLink) {
  Server server;
  Client::Options lead = Harness::options(), other = Harness::options();
  lead.launch_at_players = 2;
  lead.settings.map = 7;
  other.settings.map = 3;  // not the leader's: ignored
  std::array<Client, 2> clients{Client(lead, 0), Client(other, 0)};
  const std::array<std::string, 2> names = {"a", "b"};
  uint32_t dropped = 0, now = 0, lose = 0;
  std::array<std::vector<int8_t>, 2> got;
  auto carry = [&] {
    for (int k = 0; k < 2; ++k)
      for (const auto& p : clients[size_t(k)].take_outgoing())
        if (++lose % 10 != 3) server.receive(names[size_t(k)], p, now); else ++dropped;
    server.run(now);
    for (const auto& [to, p] : server.take_outgoing())
      if (++lose % 10 != 7) clients[to == "a" ? 0 : 1].receive(p, now); else ++dropped;
  };
  for (int step = 0; step < 400; ++step, now += 15) {
    for (int k = 0; k < 2; ++k) {
      if (k == 1 && now < 200) continue;  // the second joins later
      clients[size_t(k)].run(now);
    }
    carry();
    for (int k = 0; k < 2; ++k) {
      Client& c = clients[size_t(k)];
      if (c.state() != Client::State::kInGame || step % 2) continue;
      c.send_tic({int8_t(10 * (k + 1)), 0, 0, 0, 0, 0}, now);
      while (auto t = c.next_server_tic()) got[size_t(k)].push_back(t->cmds[size_t(1 - k)].forward);
    }
  }
  ASSERT_EQ(clients[0].state(), Client::State::kInGame) << clients[0].error();
  ASSERT_EQ(clients[1].state(), Client::State::kInGame) << clients[1].error();
  EXPECT_EQ(clients[0].settings().console_player, 0);
  EXPECT_EQ(clients[1].settings().console_player, 1);
  EXPECT_EQ(clients[1].settings().map, 7) << "the leader's game";
  EXPECT_GT(dropped, 10u);
  EXPECT_GT(got[0].size(), 50u);
  EXPECT_GT(got[1].size(), 50u);
  EXPECT_TRUE(std::all_of(got[0].begin(), got[0].end(), [](int8_t f) { return f == 20; })) << "b's commands, each tic";
  EXPECT_TRUE(std::all_of(got[1].begin(), got[1].end(), [](int8_t f) { return f == 10; }));

  Client late(Harness::options(), now);
  late.run(now);
  for (const auto& p : late.take_outgoing()) server.receive("c", p, now);
  for (const auto& [to, p] : server.take_outgoing())
    if (to == "c") late.receive(p, now);
  late.run(now + 2000);
  EXPECT_EQ(late.error(), "the server refused: Server is not currently accepting connections");
}

}  // namespace
}  // namespace p3d::net
