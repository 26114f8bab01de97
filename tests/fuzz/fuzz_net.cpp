// Packets from a server, any bytes: the client takes each (in order, a few
// milliseconds apart, its timers run between) and never reads past one or stops on
// it. An odd first byte brings the client into a game first, so that the game's
// packets are reached. Each packet is a length byte and that many bytes.
#include "engine/net/client.h"
#include "tests/fuzz/target.h"

using namespace p3d;

namespace {

void receive(net::Client& c, net::PacketWriter w, uint32_t now) { c.receive(w.bytes(), now); }

void into_game(net::Client& c) {
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

}  // namespace

P3D_FUZZ_TARGET(net) {
  if (size == 0) return 0;
  net::Client client(net::Client::Options{}, 0);
  if (data[0] & 1) into_game(client);
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
  return 0;
}
