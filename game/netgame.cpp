#include "game/netgame.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::game {

namespace {

uint32_t now_ms() {
  using namespace std::chrono;
  return uint32_t(duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count());
}

// Chocolate's GameMission_t and GameMode_t.
enum Mission { kDoom = 0, kDoom2 = 1 };
enum Mode { kShareware = 0, kRegistered = 1, kCommercial = 2, kRetail = 3 };
enum Version { kDoom19 = 5, kUltimate = 7 };

// The map Chocolate's settings name, in these WADs' way of naming maps.
std::string map_of(const net::GameSettings& s, bool commercial) {
  char name[16];
  if (commercial)
    std::snprintf(name, sizeof name, "MAP%02d", s.map);
  else
    std::snprintf(name, sizeof name, "E%dM%d", s.episode, s.map);
  return name;
}

}  // namespace

// ---- the socket

UdpLink::UdpLink(const std::string& host_port) : name_(host_port) {
  std::string host = host_port, port = std::to_string(net::kDefaultPort);
  if (const size_t colon = host_port.rfind(':'); colon != std::string::npos) {
    host = host_port.substr(0, colon);
    port = host_port.substr(colon + 1);
  }
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  if (const int e = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); e != 0 || !found)
    throw Error("--connect " + host_port + ": " + gai_strerror(e));
  address_.assign(reinterpret_cast<const uint8_t*>(found->ai_addr), reinterpret_cast<const uint8_t*>(found->ai_addr) + found->ai_addrlen);
  fd_ = socket(found->ai_family, SOCK_DGRAM, 0);
  freeaddrinfo(found);
  if (fd_ < 0) throw Error("--connect " + host_port + ": no UDP socket: " + std::strerror(errno));
}

UdpLink::~UdpLink() {
  if (fd_ >= 0) close(fd_);
}

void UdpLink::send(std::span<const uint8_t> packet) {
  // A packet lost here is a packet lost on the way: the protocol sends it again.
  (void)sendto(fd_, packet.data(), packet.size(), 0, reinterpret_cast<const sockaddr*>(address_.data()),
               socklen_t(address_.size()));
}

std::vector<uint8_t> UdpLink::receive(int wait_ms) {
  pollfd p{fd_, POLLIN, 0};
  if (poll(&p, 1, wait_ms) <= 0) return {};
  std::vector<uint8_t> packet(1500);
  sockaddr_storage from{};
  socklen_t from_size = sizeof from;
  const ssize_t n = recvfrom(fd_, packet.data(), packet.size(), 0, reinterpret_cast<sockaddr*>(&from), &from_size);
  // Only the server's words count (Chocolate's NET_CL_Run drops the rest).
  if (n <= 0 || from_size != address_.size() || std::memcmp(&from, address_.data(), address_.size()) != 0) return {};
  packet.resize(size_t(n));
  return packet;
}

net::ConnectData connect_data_for(const wad::Stack& wads) {
  net::ConnectData d;
  const bool commercial = wads.map("MAP01").has_value();
  d.game_mission = commercial ? kDoom2 : kDoom;
  d.game_mode = commercial ? kCommercial : wads.map("E4M1") ? kRetail : wads.map("E2M1") ? kRegistered : kShareware;
  d.is_freedoom = wads.find("FREEDOOM") != nullptr;
  d.max_players = play::kMaxPlayers;
  return d;
}

// ---- the game

namespace {

// Doom's d_loop.c and G_Ticker for one client: the tics we made, the consistency
// bytes, and the run of each tic once the server has sent the others' commands.
class NetLoop {
 public:
  NetLoop(UdpLink& link, net::Client& client) : link_(link), client_(client) {}

  // Sends what the client has, and hands it what came, for up to wait_ms.
  void pump(int wait_ms) {
    flush();
    for (std::vector<uint8_t> p = link_.receive(wait_ms); !p.empty(); p = link_.receive(0)) client_.receive(p, now_ms());
    client_.run(now_ms());
    flush();
    if (client_.state() == net::Client::State::kDisconnected) throw Error("netgame on " + link_.server() + ": " + client_.error());
  }

  void flush() {
    for (const std::vector<uint8_t>& p : client_.take_outgoing()) link_.send(p);
  }

 private:
  UdpLink& link_;
  net::Client& client_;
};

// G_BuildTiccmd's turn when a client records a vanilla demo: whole 256ths, the rest
// carried to the next tic.
int16_t low_res_turn(int16_t turn, int16_t& carry) {
  const int16_t wanted = int16_t(turn + carry);
  const int16_t sent = int16_t((wanted + 128) & 0xff00);
  carry = int16_t(wanted - sent);
  return sent;
}

}  // namespace

uint64_t play_netgame_headless(const bsp::LevelSource& source, const NetGameOptions& o, const TicSource& input,
                               const AfterTic& after_tic) {
  const wad::Stack wads = bsp::read_wads(source.wads);
  const bool commercial = wads.map("MAP01").has_value();
  net::Client::Options co;
  co.connect = connect_data_for(wads);
  co.player_name = o.player_name;
  co.settings = o.settings;
  co.settings.game_version = commercial ? kDoom19 : kUltimate;
  co.launch_at_players = o.launch_at_players;
  UdpLink link(o.connect);
  net::Client client(co, now_ms());
  NetLoop loop(link, client);

  // Joined, then launched and started.
  const uint32_t waiting_since = now_ms();
  while (client.state() != net::Client::State::kInGame) {
    loop.pump(10);
    if (now_ms() - waiting_since > uint32_t(o.wait_seconds) * 1000)
      throw Error("netgame on " + o.connect + ": the game did not start in " + std::to_string(o.wait_seconds) + " s");
  }
  const net::GameSettings& s = client.settings();
  if (s.num_players > play::kMaxPlayers)
    throw Error("netgame on " + o.connect + ": " + std::to_string(s.num_players) + " players, Doom plays 4 at most");
  bsp::LevelSource level_source = source;
  level_source.map = map_of(s, commercial);
  if (!wads.map(level_source.map)) throw Error("netgame on " + o.connect + ": the game is on " + level_source.map + ", which these WADs lack");
  GameFlags flags;
  flags.fast = s.fast_monsters, flags.respawn = s.respawn_monsters, flags.no_monsters = s.no_monsters;
  flags.deathmatch = s.deathmatch, flags.time_limit = s.time_limit;
  for (int i = 0; i < play::kMaxPlayers; ++i) flags.players[size_t(i)] = i < s.num_players;
  flags.console_player = s.console_player;
  Session session(level_source, s.skill + 1, flags);
  if (!o.record.empty()) session.start_recording(true, o.long_tics);

  // The lockstep (d_loop.c's TryRunTics with new_sync, ticdup 1).
  constexpr uint64_t kMostAhead = 8;  // BuildNewTic's limit
  std::array<std::array<uint8_t, net::kBackupTics>, play::kMaxPlayers> consistency{};  // G_Ticker's consistancy[][]
  std::array<play::TicCmd, net::kBackupTics> ours{};
  int16_t carry = 0;
  const int me = s.console_player;
  uint64_t make_tic = 0, game_tic = 0;
  const uint32_t start = now_ms();
  while (o.quit_after_tics == 0 || game_tic < o.quit_after_tics) {
    loop.pump(1);
    const uint64_t due = uint64_t(now_ms() - start) * kTicRate / 1000 + 1;
    while (make_tic < due && make_tic - game_tic < kMostAhead && (o.quit_after_tics == 0 || make_tic < o.quit_after_tics)) {
      play::TicCmd cmd = input(make_tic);
      if (s.low_res_turn) cmd.turn = low_res_turn(cmd.turn, carry);
      ours[make_tic % net::kBackupTics] = cmd;
      client.send_tic({cmd.forward, cmd.side, cmd.turn, cmd.buttons, consistency[size_t(me)][make_tic % net::kBackupTics], 0},
                      now_ms());
      ++make_tic;
    }
    loop.flush();
    while (game_tic < make_tic) {
      const std::optional<net::Client::ServerTic> tic = client.next_server_tic();
      if (!tic) break;
      std::array<play::TicCmd, play::kMaxPlayers> others{};
      const size_t slot = game_tic % net::kBackupTics;
      for (int i = 0; i < s.num_players && i < play::kMaxPlayers; ++i) {
        if (i == me || !tic->in_game[size_t(i)]) continue;
        const net::TicCmd& c = tic->cmds[size_t(i)];
        if (game_tic > net::kBackupTics && c.consistancy != consistency[size_t(i)][slot])
          throw Error("netgame on " + o.connect + ": consistency failure at tic " + std::to_string(game_tic) + " (player " +
                      std::to_string(i + 1) + " sent " + std::to_string(c.consistancy) + ", here " +
                      std::to_string(consistency[size_t(i)][slot]) + "): the games have parted");
        others[size_t(i)] = {c.forward, c.side, c.turn, c.buttons};
      }
      session.queue_other_players(others);
      session.tic(ours[slot]);
      for (int i = 0; i < s.num_players && i < play::kMaxPlayers; ++i) {
        const std::optional<play::Fixed> x = session.world().tic_start_x()[size_t(i)];
        consistency[size_t(i)][slot] = uint8_t(x ? *x : session.screen_random().other_index());  // Doom's rndindex
      }
      if (after_tic) after_tic(session, game_tic);
      ++game_tic;
    }
  }
  client.leave(now_ms());
  loop.flush();
  if (!o.record.empty()) write_file_atomically(o.record, session.encode_recording(o.record));
  return game_tic;
}

}  // namespace p3d::game
