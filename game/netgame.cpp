#include "game/netgame.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

#include "engine/util/error.h"
#include "engine/util/file.h"
#include "game/front_end.h"
#include "game/settings.h"

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

UdpHost::UdpHost(int port) {
  fd_ = socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  if (fd_ < 0 || bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const std::string why = std::strerror(errno);
    if (fd_ >= 0) close(fd_);
    throw Error("--server: cannot serve on UDP port " + std::to_string(port) + ": " + why);
  }
}

UdpHost::~UdpHost() { close(fd_); }

void UdpHost::pump(uint32_t now_ms) {
  std::vector<uint8_t> packet(1500);
  for (;;) {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 0) <= 0) break;
    sockaddr_storage from{};
    socklen_t size = sizeof from;
    const ssize_t n = recvfrom(fd_, packet.data(), packet.size(), 0, reinterpret_cast<sockaddr*>(&from), &size);
    if (n <= 0) break;
    server_.receive(std::string(reinterpret_cast<const char*>(&from), size), std::span(packet).first(size_t(n)), now_ms);
  }
  server_.run(now_ms);
  for (const auto& [peer, bytes] : server_.take_outgoing())
    (void)sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(peer.data()), socklen_t(peer.size()));
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

// G_BuildTiccmd's turn when a client records a vanilla demo: whole 256ths, the rest
// carried to the next tic.
int16_t low_res_turn(int16_t turn, int16_t& carry) {
  const int16_t wanted = int16_t(turn + carry);
  const int16_t sent = int16_t((wanted + 128) & 0xff00);
  carry = int16_t(wanted - sent);
  return sent;
}

net::Client::Options client_options(const wad::Stack& wads, const NetGameOptions& o) {
  const bool commercial = wads.map("MAP01").has_value();
  net::Client::Options co;
  co.connect = connect_data_for(wads);
  // Recording a vanilla demo, whose turns are whole 256ths: every client turns so (Chocolate's -record).
  co.connect.low_res_turn = !o.record.empty() && o.record.extension() == ".lmp" && !o.long_tics;
  co.player_name = o.player_name;
  co.settings = o.settings;
  co.settings.game_version = commercial ? kDoom19 : kUltimate;
  co.launch_at_players = o.launch_at_players;
  return co;
}

}  // namespace

NetPlay::NetPlay(const bsp::LevelSource& source, const NetGameOptions& o)
    : options_(o),
      host_(o.host_port ? std::make_unique<UdpHost>(o.host_port) : nullptr),
      level_source_(source),
      commercial_(bsp::read_wads(source.wads).map("MAP01").has_value()),
      link_(o.host_port ? "127.0.0.1:" + std::to_string(o.host_port) : o.connect),
      client_(client_options(bsp::read_wads(source.wads), o), now_ms()) {
  if (o.host_port) options_.connect = link_.server();
}

NetPlay::~NetPlay() {
  if (client_.state() != net::Client::State::kDisconnected) leave();
}

void NetPlay::flush() {
  for (const std::vector<uint8_t>& p : client_.take_outgoing()) link_.send(p);
}

void NetPlay::pump(int wait_ms) {
  if (host_) host_->pump(now_ms()), wait_ms = std::min(wait_ms, 1);  // the server runs here too
  flush();
  for (std::vector<uint8_t> p = link_.receive(wait_ms); !p.empty(); p = link_.receive(0)) client_.receive(p, now_ms());
  client_.run(now_ms());
  flush();
  if (client_.state() == net::Client::State::kDisconnected)
    throw Error("netgame on " + link_.server() + ": " + client_.error());
}

void NetPlay::wait_for_start(const std::function<void(const std::string&)>& status) {
  const uint32_t since = now_ms();
  std::string said;
  while (client_.state() != net::Client::State::kInGame) {
    pump(10);
    if (status && client_.wait_data()) {
      const net::WaitData& w = *client_.wait_data();
      const char* lead = !w.is_controller               ? ""
                         : options_.launch_at_players > 0 ? " (we lead: the game starts at --nodes players)"
                                                          : " (we lead: --nodes N starts the game at N players)";
      const std::string now =
          std::to_string(w.num_players) + " of " + std::to_string(w.max_players) + " players have joined" + lead;
      if (now != said) status(said = now);
    }
    if (options_.wait_seconds > 0 && now_ms() - since > uint32_t(options_.wait_seconds) * 1000)
      throw Error("netgame on " + options_.connect + ": the game did not start in " + std::to_string(options_.wait_seconds) + " s");
  }
  const net::GameSettings& s = client_.settings();
  if (s.num_players > play::kMaxPlayers)
    throw Error("netgame on " + options_.connect + ": " + std::to_string(s.num_players) + " players, Doom plays 4 at most");
  level_source_.map = map_of(s, commercial_);
  if (!bsp::read_wads(level_source_.wads).map(level_source_.map))
    throw Error("netgame on " + options_.connect + ": the game is on " + level_source_.map + ", which these WADs lack");
  started_at_ = now_ms();
}

GameFlags NetPlay::flags() const {
  const net::GameSettings& s = client_.settings();
  GameFlags flags;
  flags.fast = s.fast_monsters, flags.respawn = s.respawn_monsters, flags.no_monsters = s.no_monsters;
  flags.deathmatch = s.deathmatch, flags.time_limit = s.time_limit;
  for (int i = 0; i < play::kMaxPlayers; ++i) flags.players[size_t(i)] = i < s.num_players;
  flags.console_player = s.console_player;
  return flags;
}

uint64_t NetPlay::step(Session& session, const std::function<play::TicCmd()>& input,
                       const std::function<void(const play::TicCmd&)>& run) {
  constexpr uint64_t kMostAhead = 8;  // d_loop.c's BuildNewTic with new_sync
  const net::GameSettings& s = client_.settings();
  const int me = s.console_player;
  const uint64_t quit = options_.quit_after_tics;
  pump(0);
  const uint64_t due = uint64_t(now_ms() - started_at_) * kTicRate / 1000 + 1;
  while (make_tic_ < due && make_tic_ - game_tic_ < kMostAhead && (quit == 0 || make_tic_ < quit)) {
    play::TicCmd cmd = input();
    if (s.low_res_turn) cmd.turn = low_res_turn(cmd.turn, turn_carry_);
    ours_[make_tic_ % net::kBackupTics] = cmd;
    const uint8_t check = consistency_[size_t(me)][make_tic_ % net::kBackupTics];
    client_.send_tic({cmd.forward, cmd.side, cmd.turn, cmd.buttons, check, cmd.chatchar}, now_ms());
    ++make_tic_;
  }
  flush();
  while (game_tic_ < make_tic_) {
    const std::optional<net::Client::ServerTic> tic = client_.next_server_tic();
    if (!tic) break;
    std::array<play::TicCmd, play::kMaxPlayers> others{};
    const size_t slot = game_tic_ % net::kBackupTics;
    for (int i = 0; i < s.num_players && i < play::kMaxPlayers; ++i) {
      if (i == me || !tic->in_game[size_t(i)]) continue;
      const net::TicCmd& c = tic->cmds[size_t(i)];
      if (game_tic_ > net::kBackupTics && c.consistancy != consistency_[size_t(i)][slot])
        throw Error("netgame on " + options_.connect + ": consistency failure at tic " + std::to_string(game_tic_) +
                    " (player " + std::to_string(i + 1) + " sent " + std::to_string(c.consistancy) + ", here " +
                    std::to_string(consistency_[size_t(i)][slot]) + "): the games have parted");
      others[size_t(i)] = {c.forward, c.side, c.turn, c.buttons, c.chatchar};
    }
    for (int i = 0; i < s.num_players && i < play::kMaxPlayers; ++i)
      if (i != me && !tic->in_game[size_t(i)] && session.world().in_game(i)) session.player_left(i);  // RunTic
    session.queue_other_players(others);
    // G_Ticker keeps each player's x as the tic starts (after a respawn or a level
    // loaded at its start), or Doom's rndindex where there is no body. In a tic the
    // level plays, the World kept it; in the tally's tics (even the last, after which
    // we load the next level) it is the x the level left.
    const play::World* before = &session.world();
    const int level_time = before->level_time();
    std::array<std::optional<play::Fixed>, play::kMaxPlayers> standing{};
    for (int i = 0; i < play::kMaxPlayers; ++i)
      if (const play::Mobj* mo = before->player(i).mo) standing[size_t(i)] = mo->x;
    run(ours_[slot]);
    const bool played = &session.world() == before && session.world().level_time() != level_time;
    for (int i = 0; i < s.num_players && i < play::kMaxPlayers; ++i) {
      const std::optional<play::Fixed> x = played ? session.world().tic_start_x()[size_t(i)] : standing[size_t(i)];
      consistency_[size_t(i)][slot] = uint8_t(x ? *x : session.screen_random().other_index());  // Doom's rndindex
    }
    ++game_tic_;
  }
  return game_tic_;
}

void NetPlay::leave() {
  client_.leave(now_ms());
  flush();
  if (host_) host_->shut_down(now_ms());  // the game was ours: it is over for everyone
}

uint64_t play_netgame_headless(const bsp::LevelSource& source, const NetGameOptions& o, const TicSource& input,
                               const AfterTic& after_tic) {
  NetPlay net(source, o);
  net.wait_for_start({});
  // Doom's front end runs the tics, as in the window: the level, the tally between
  // levels (which every player's press hurries on) and the finales.
  Settings settings;
  FrontEndOptions front_options;
  front_options.save_dir = o.save_dir;
  FrontEnd front(std::make_unique<Session>(net.level_source(), net.skill(), net.flags()), settings, front_options);
  Session& session = *front.session();
  if (!o.record.empty()) session.start_recording(true, o.long_tics);
  const auto ours = [&] { return input(net.tics_made()); };
  const auto run = [&](const play::TicCmd& cmd) {
    front.tic(play::DemoTic{cmd, 0});
    if (after_tic) after_tic(session, session.tics() - 1);
  };
  uint64_t played = 0;
  while (o.quit_after_tics == 0 || played < o.quit_after_tics) {
    played = net.step(session, ours, run);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  // A second more of answering (no tic is made or run past quit_after_tics): the
  // server may still ask for our last tics again.
  for (const uint32_t until = now_ms() + 1000; int32_t(until - now_ms()) > 0;) {
    net.step(session, ours, run);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  net.leave();
  if (!o.record.empty()) write_file_atomically(o.record, session.encode_recording(o.record));
  return played;
}

}  // namespace p3d::game
