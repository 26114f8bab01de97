// A netgame server speaking Chocolate Doom's protocol, as its net_server.c behaves, so
// that Chocolate Doom's clients and ours play in one game: players join (refused when
// the game is of another IWAD, full, or started), the first to join leads and launches,
// every client sends its settings (the leader's are the game's) and is told its player
// number, then each tic's commands are gathered from every player and sent to each of
// the others, with acknowledgements, resend requests both ways, and a client that is
// silent for 30 seconds or leaves dropped from the game.
//
// No sockets and no clock: peers are named by the caller (an address as bytes), which
// hands each packet in with the time and sends what take_outgoing() gives.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/net/connection.h"
#include "engine/net/protocol.h"

namespace p3d::net {

class Server {
 public:
  enum class State { kWaitingLaunch, kWaitingStart, kInGame };
  explicit Server(std::string version = "pseudo3d") : version_(std::move(version)) {}

  void receive(const std::string& peer, std::span<const uint8_t> packet, uint32_t now_ms);
  void run(uint32_t now_ms);
  std::vector<std::pair<std::string, std::vector<uint8_t>>> take_outgoing();
  State state() const { return state_; }
  int players() const;
  // The game over for everyone (the host quits): each client is told, then forgotten.
  void shut_down() { end_game(); }

 private:
  struct Recv {
    bool active = false;
    uint32_t resend_at = 0;
    TicDiff diff;
  };
  struct Peer {
    std::string address;
    Connection connection;
    bool active = true, ready = false, drone = false, low_res_turn = false;
    uint32_t joined_at = 0, last_waiting_at = 0, last_game_data_at = 0;
    int max_players = kMaxPlayers, player = -1;
    std::string name;
    std::array<uint8_t, 20> wad_sha1{}, deh_sha1{};
    bool is_freedoom = false;
    uint32_t send_seq = 0, acknowledged = 0;
    std::array<std::pair<int64_t, FullTic>, kBackupTics> send_queue{};  // (tic, its commands), tic -1: none
    explicit Peer(uint32_t now) : connection(now), joined_at(now) {}
  };

  Peer* find(const std::string& address);
  void reject(const std::string& address, const std::string& why);
  void parse_syn(const std::string& address, PacketReader& in, uint32_t now_ms);
  void parse(Peer& peer, PacketReader& in, uint32_t type, uint32_t now_ms);
  void parse_game_data(Peer& peer, PacketReader& in, uint32_t now_ms);
  void assign_players();
  Peer* controller();
  void send_waiting_data(Peer& peer, uint32_t now_ms);
  void start_game(uint32_t now_ms);
  void end_game();
  void pump_send_queue(Peer& peer, uint32_t now_ms);
  void send_tics(Peer& peer, uint32_t first, uint32_t last, uint32_t now_ms);
  void ask_again(Peer& peer, uint32_t first, uint32_t last, uint32_t now_ms);
  void check_resends(Peer& peer, uint32_t now_ms);
  void check_deadlock(Peer& peer, uint32_t now_ms);
  void advance_window();
  uint32_t expand(uint32_t low_byte) const { return expand_tic(window_start_, low_byte); }

  std::string version_;
  State state_ = State::kWaitingLaunch;
  std::vector<std::unique_ptr<Peer>> peers_;  // in the order they joined
  std::array<Peer*, kMaxPlayers> players_{};
  int game_mode_ = -1, game_mission_ = -1;
  GameSettings settings_;
  std::array<std::array<Recv, kMaxPlayers>, kBackupTics> window_{};
  uint32_t window_start_ = 0;
  std::vector<std::pair<std::string, std::vector<uint8_t>>> outgoing_;  // to peers no longer kept
};

}  // namespace p3d::net
