// A netgame client speaking Chocolate Doom's protocol (protocol.h), as its
// net_client.c and net_common.c behave: the connection (SYN, reliable packets resent
// every second until acknowledged, keepalives, a 30-second timeout), the wait for the
// launch and the start, then the lockstep of tic commands: ours sent with the last
// `extratics` again, the server's received into a window, acknowledged, and asked
// again where a tic is missing.
//
// No sockets and no clock: the caller hands it each packet from the server with the
// time in milliseconds, calls run() now and then, and sends what take_outgoing() gives.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/net/connection.h"
#include "engine/net/protocol.h"

namespace p3d::net {

class Client {
 public:
  struct Options {
    ConnectData connect;
    std::string version = "pseudo3d";  // sent beside the protocol; Chocolate only prints it
    std::string player_name = "player";
    // The game we would start: the controller's settings become everyone's.
    GameSettings settings;
    // As the controller, launch once this many players have joined (Chocolate's -nodes);
    // 0: never by itself (launch()).
    int launch_at_players = 0;
  };
  enum class State { kConnecting, kWaitingLaunch, kWaitingStart, kInGame, kDisconnected };

  Client(Options options, uint32_t now_ms);

  void receive(std::span<const uint8_t> packet, uint32_t now_ms);
  // Timers: SYN every second, reliable packets resent, keepalives, acknowledgements,
  // resend requests, the timeouts.
  void run(uint32_t now_ms);
  std::vector<std::vector<uint8_t>> take_outgoing();

  State state() const { return state_; }
  // Why the client stopped (rejected, no answer, the server gone), once disconnected.
  const std::string& error() const { return error_; }
  const std::optional<WaitData>& wait_data() const { return wait_data_; }
  // The game, from the server's GAMESTART (console_player is ours).
  const GameSettings& settings() const { return settings_; }
  void launch();  // as the controller: start the game with the players there
  void leave(uint32_t now_ms);  // tells the server we go

  // In game: our command for the next tic (0 the first), sent at once.
  void send_tic(const TicCmd& cmd, uint32_t now_ms);
  // The other players' commands of the next tic, in order, once the server sent them
  // (in_game: which players it had a command from; ours is the caller's own).
  struct ServerTic {
    std::array<bool, kMaxPlayers> in_game{};
    std::array<TicCmd, kMaxPlayers> cmds{};
  };
  std::optional<ServerTic> next_server_tic();

 private:
  struct SentTic {
    bool active = false;
    uint32_t seq = 0;
    TicDiff diff;
  };
  struct ReceivedTic {
    bool active = false;
    uint32_t resend_at = 0;  // when we last asked for it again (0: never)
    FullTic tic;
  };

  void send(std::vector<uint8_t> bytes, uint32_t now_ms) { connection_.send(std::move(bytes), now_ms); }
  void send_syn(uint32_t now_ms);
  void disconnect(const std::string& why);
  void parse(PacketReader& in, uint32_t type, uint32_t now_ms);
  void parse_game_data(PacketReader& in, uint32_t now_ms);
  void parse_resend_request(PacketReader& in, uint32_t now_ms);
  void send_tics(uint32_t first, uint32_t last, uint32_t now_ms);
  void ask_again(uint32_t first, uint32_t last, uint32_t now_ms);
  void check_resends(uint32_t now_ms);
  void advance_window();

  Options options_;
  State state_ = State::kConnecting;
  std::string error_;
  Connection connection_;
  uint32_t started_at_ = 0, last_syn_at_ = 0;
  bool syn_sent_ = false, launched_ = false;
  std::optional<std::string> rejection_;  // the server's refusal while connecting
  uint32_t rejected_at_ = 0;
  std::optional<WaitData> wait_data_;
  GameSettings settings_;
  // the game (net_client.c)
  TicCmd last_sent_;
  uint32_t make_tic_ = 0;
  std::array<SentTic, kBackupTics> send_queue_{};
  std::array<ReceivedTic, kBackupTics> window_{};
  uint32_t window_start_ = 0;
  std::array<TicCmd, kMaxPlayers> base_{};  // each player's last command, which diffs patch
  bool need_ack_ = false;
  uint32_t game_data_at_ = 0;
  std::deque<ServerTic> ready_;
};

}  // namespace p3d::net
