// A netgame beside Chocolate Doom: our game as a client of a Chocolate Doom server
// (chocolate-server, or chocolate-doom -server), over UDP, with net::Client speaking
// the protocol. Doom's d_loop.c and G_Ticker around it: our commands built at 35 a
// second (at most 8 tics ahead), each tic run once every player's command for it is
// there, the consistency check of each command, a player who left the game dropped.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "engine/bsp/load.h"
#include "engine/net/client.h"
#include "engine/net/server.h"
#include "engine/play/world.h"
#include "game/session.h"

namespace p3d::game {

// A UDP socket bound to any local port, talking to one server. Throws Error.
class UdpLink {
 public:
  explicit UdpLink(const std::string& host_port);  // "host", "host:port" (port 2342 by default)
  ~UdpLink();
  UdpLink(const UdpLink&) = delete;
  UdpLink& operator=(const UdpLink&) = delete;
  void send(std::span<const uint8_t> packet);
  // The next packet from the server, waiting up to `wait_ms`; empty when none came.
  std::vector<uint8_t> receive(int wait_ms);
  const std::string& server() const { return name_; }

 private:
  int fd_ = -1;
  std::string name_;
  std::vector<uint8_t> address_;  // the server's sockaddr
};

// A server of ours for a netgame (net::Server) on a UDP port of this machine: Chocolate
// Doom's clients and ours join it as they join chocolate-server.
class UdpHost {
 public:
  explicit UdpHost(int port);  // throws Error (the port taken)
  ~UdpHost();
  UdpHost(const UdpHost&) = delete;
  UdpHost& operator=(const UdpHost&) = delete;
  // Hands the server what came, runs it, sends what it has.
  void pump(uint32_t now_ms);
  void shut_down(uint32_t now_ms) {
    server_.shut_down();
    pump(now_ms);
  }
  const net::Server& server() const { return server_; }

 private:
  int fd_ = -1;
  net::Server server_;
};

struct NetGameOptions {
  std::string connect;  // host[:port]
  int host_port = 0;    // also serve the game on this port (our client joins it there)
  std::string player_name = "pseudo3d";
  int launch_at_players = 0;  // as the controller: start when this many have joined (Chocolate's -nodes)
  // The game we would start if we are the controller: the map, skill and rules.
  net::GameSettings settings;
  uint64_t quit_after_tics = 0;  // 0: play until the server ends the game
  int wait_seconds = 0;          // for the game to start (0: as long as the server is there)
  std::filesystem::path record;  // every player's commands as a Doom demo (.lmp), if named
  bool long_tics = false;        // the demo in v1.91's long tics (Chocolate's -longtics)
  std::filesystem::path save_dir;  // headless: where the game's saves go (every player's); empty: none
};

// The commands of our player, tic by tic (the caller's input, a demo's, or nothing).
using TicSource = std::function<play::TicCmd(uint64_t tic)>;
// Called after every tic run (the session stands after it).
using AfterTic = std::function<void(const Session&, uint64_t tic)>;

// One netgame as a client: joined, waited for, then played tic by tic, the caller
// running each tic (the window through its front end, or a headless loop).
class NetPlay {
 public:
  // Joins (throws Error: the server cannot be named or reached).
  NetPlay(const bsp::LevelSource& source, const NetGameOptions& options);
  ~NetPlay();
  // Waits for the game to start, saying who has joined on `status` (throws Error:
  // refused, lost, not started in wait_seconds).
  void wait_for_start(const std::function<void(const std::string&)>& status);
  // The game the server started: its map of the WADs, skill and rules.
  const bsp::LevelSource& level_source() const { return level_source_; }
  int skill() const { return client_.settings().skill + 1; }
  GameFlags flags() const;
  // Sends the tics due by now (our command from `input`, once per tic), then runs every
  // tic all commands are there for: the others' queued into the session, ours given to
  // `run` (which ticks the session). Throws Error: lost, or a consistency failure.
  // Returns the tics run so far.
  uint64_t step(Session& session, const std::function<play::TicCmd()>& input,
                const std::function<void(const play::TicCmd&)>& run);
  uint64_t tics_made() const { return make_tic_; }
  void leave();

 private:
  void pump(int wait_ms);
  void flush();

  NetGameOptions options_;
  std::unique_ptr<UdpHost> host_;  // first: our client joins it
  bsp::LevelSource level_source_;
  bool commercial_ = true;
  UdpLink link_;
  net::Client client_;
  std::array<std::array<uint8_t, net::kBackupTics>, play::kMaxPlayers> consistency_{};  // G_Ticker's consistancy[][]
  std::array<play::TicCmd, net::kBackupTics> ours_{};
  int16_t turn_carry_ = 0;
  uint64_t make_tic_ = 0, game_tic_ = 0;
  uint32_t started_at_ = 0;
};

// Joins the server, waits for the game to start, then plays it with no window until
// quit_after_tics or the server's end. The session is made for the settings the server
// gave (its map of `source`'s WADs). Throws Error with the reason (refused, no answer,
// lost, a consistency failure). Returns the tics played.
uint64_t play_netgame_headless(const bsp::LevelSource& source, const NetGameOptions& options, const TicSource& input,
                               const AfterTic& after_tic);

// What Chocolate Doom says a client plays (its gamemode, gamemission, is_freedoom) for
// these WADs, with our version and the WAD's checksum left zero (Chocolate warns, and
// plays on).
net::ConnectData connect_data_for(const wad::Stack& wads);

}  // namespace p3d::game
