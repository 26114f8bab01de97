// Packets from the other end, any bytes, to our client or our server: each is taken in
// order, a few milliseconds apart, the timers running between, and nothing reads past
// one, stops on it or loops on it. The first byte chooses: bit 1 the server (else the
// client), bit 0 a game already started (so that the game's packets are reached). Each
// packet is a length byte and that many bytes; to the server, the length byte's top bit
// says which of two addresses sent it (one of them the player in the game).
#include "engine/net/client.h"
#include "engine/net/server.h"
#include "tests/fuzz/target.h"

using namespace p3d;

namespace {

void receive(net::Client& c, net::PacketWriter w, uint32_t now) { c.receive(w.bytes(), now); }

void client_into_game(net::Client& c) {
  uint8_t seq = 0;
  auto reliable = [&](net::PacketType t) {
    net::PacketWriter w(t, true);
    w.u8(seq++);
    return w;
  };
  c.run(0);
  net::PacketWriter syn = reliable(net::PacketType::kSyn);
  syn.str("Chocolate Doom 3.0.0"), syn.str(net::kProtocolName);
  receive(c, std::move(syn), 1);
  net::PacketWriter launch = reliable(net::PacketType::kLaunch);
  launch.u8(2);
  receive(c, std::move(launch), 2);
  net::PacketWriter start = reliable(net::PacketType::kGameStart);
  net::GameSettings s;
  s.num_players = 4, s.console_player = 1, s.extratics = 2;
  start.settings(s);
  receive(c, std::move(start), 3);
}

void fuzz_client(const uint8_t* data, size_t size) {
  net::Client client(net::Client::Options{}, 0);
  if (data[0] & 1) client_into_game(client);
  uint32_t now = 10;
  for (size_t at = 1; at < size;) {
    const size_t n = std::min<size_t>(data[at], size - at - 1);
    client.receive(std::span<const uint8_t>(data + at + 1, n), now);
    at += 1 + n;
    now += 7;
    client.run(now);
    if (client.state() == net::Client::State::kInGame) client.send_tic({int8_t(n), 0, int16_t(n * 256), 0, 0, 0}, now);
    while (client.next_server_tic()) {
    }
    (void)client.take_outgoing();
  }
}

// One of our clients joins as "a" and starts a one-player game, carried in memory.
uint32_t server_into_game(net::Server& server) {
  net::Client::Options o;
  o.connect.game_mission = 1, o.connect.game_mode = 2;
  o.launch_at_players = 1;
  net::Client a(o, 0);
  uint32_t now = 0;
  for (; now < 2000 && a.state() != net::Client::State::kInGame; now += 10) {
    a.run(now);
    for (const auto& p : a.take_outgoing()) server.receive("a", p, now);
    server.run(now);
    for (const auto& [to, p] : server.take_outgoing()) a.receive(p, now);
  }
  return now;
}

void fuzz_server(const uint8_t* data, size_t size) {
  net::Server server;
  uint32_t now = (data[0] & 1) ? server_into_game(server) : 10;
  for (size_t at = 1; at < size;) {
    const size_t n = std::min<size_t>(data[at] & 0x7f, size - at - 1);
    server.receive(data[at] & 0x80 ? "b" : "a", std::span<const uint8_t>(data + at + 1, n), now);
    at += 1 + n;
    now += 7;
    server.run(now);
    (void)server.take_outgoing();
  }
}

}  // namespace

P3D_FUZZ_TARGET(net) {
  if (size == 0) return 0;
  if (data[0] & 2)
    fuzz_server(data, size);
  else
    fuzz_client(data, size);
  return 0;
}
