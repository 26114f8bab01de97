#include "engine/net/server.h"

#include <algorithm>
#include <climits>

namespace p3d::net {

namespace {

constexpr uint32_t kWaitingDataEvery = 1000;  // ms, as net_server.c
constexpr uint32_t kMostUnacknowledged = 40;  // tics sent ahead of the slowest client's acknowledgement

// Chocolate's D_GameMissionString, D_GameModeString and D_ValidGameMode.
const char* mission_name(int m) {
  static const char* const names[] = {"doom", "doom2", "tnt", "plutonia", "chex", "hacx", "heretic", "hexen", "strife", "doom2f"};
  return m >= 0 && m < 10 ? names[m] : "none";
}
const char* mode_name(int m) {
  static const char* const names[] = {"shareware", "registered", "commercial", "retail"};
  return m >= 0 && m < 4 ? names[m] : "unknown";
}
bool valid_game(int mission, int mode) {
  switch (mission) {
    case 0: case 6: return mode == 0 || mode == 1 || mode == 3;  // Doom, Heretic
    case 4: return mode == 3;                                       // Chex Quest
    case 1: case 2: case 3: case 5: case 7: case 8: case 9: return mode == 2;
    default: return false;
  }
}

}  // namespace

std::vector<std::pair<std::string, std::vector<uint8_t>>> Server::take_outgoing() {
  auto out = std::exchange(outgoing_, {});
  for (const auto& p : peers_)
    for (std::vector<uint8_t>& bytes : p->connection.take_outgoing()) out.emplace_back(p->address, std::move(bytes));
  return out;
}

int Server::players() const {
  return int(std::count_if(peers_.begin(), peers_.end(), [](const auto& p) { return p->active && !p->drone; }));
}

Server::Peer* Server::find(const std::string& address) {
  for (const auto& p : peers_)
    if (p->active && p->address == address) return p.get();
  return nullptr;
}

void Server::reject(const std::string& address, const std::string& why) {
  PacketWriter w(PacketType::kRejected);
  w.str(why);
  outgoing_.emplace_back(address, std::move(w.bytes()));
}

// NET_SV_AssignPlayers: players numbered in the order they joined.
void Server::assign_players() {
  players_.fill(nullptr);
  int n = 0;
  for (const auto& p : peers_) {
    if (!p->active) continue;
    p->player = p->drone || n >= kMaxPlayers ? -1 : n;
    if (p->player >= 0) players_[size_t(n++)] = p.get();
  }
}

Server::Peer* Server::controller() {
  for (const auto& p : peers_)
    if (p->active && !p->drone) return p.get();
  return nullptr;
}

void Server::receive(const std::string& address, std::span<const uint8_t> bytes, uint32_t now_ms) {
  PacketReader in(bytes);
  {
    PacketReader peek(bytes);
    const auto type = peek.u16();
    if (!type) return;
    if (*type == uint32_t(PacketType::kSyn)) {
      in.u16();
      return parse_syn(address, in, now_ms);
    }
  }
  Peer* peer = find(address);
  if (!peer) return;
  if (const auto type = peer->connection.receive(in, now_ms)) parse(*peer, in, *type, now_ms);
}

void Server::parse_syn(const std::string& address, PacketReader& in, uint32_t now_ms) {
  const auto magic = in.u32();
  if (!magic) return;
  if (*magic == kOldMagic) return reject(address, "You are using an old client version that is not supported by this server.");
  if (*magic != kMagic) return;
  const auto client_version = in.str();
  if (!client_version) return;
  if (!in.protocol_list_has_ours())
    return reject(address, "Version mismatch: server version is: " + version_ + "; client is: " + *client_version +
                               ". No common compatible protocol could be negotiated.");
  const auto data = in.connect_data();
  const auto name = data ? in.str() : std::nullopt;
  if (!name || !valid_game(data->game_mission, data->game_mode) || data->max_players > kMaxPlayers) return;
  if (find(address)) return;  // its SYN again: our answer is on its way again too
  if (state_ != State::kWaitingLaunch) return reject(address, "Server is not currently accepting connections");
  assign_players();
  const Peer* first = controller();
  const int max_players = first ? first->max_players : data->max_players;
  if ((!data->drone && players() >= max_players) || int(peers_.size()) >= 16) return reject(address, "Server is full!");
  if (players() == 0 && !data->drone) game_mode_ = data->game_mode, game_mission_ = data->game_mission;
  if (data->game_mode != game_mode_ || data->game_mission != game_mission_)
    return reject(address, std::string("Game mismatch: server is ") + mission_name(game_mission_) + " (" + mode_name(game_mode_) +
                               "), client is " + mission_name(data->game_mission) + " (" + mode_name(data->game_mode) + ")");
  auto peer = std::make_unique<Peer>(now_ms);
  peer->address = address;
  peer->name = *name;
  peer->drone = data->drone;
  peer->low_res_turn = data->low_res_turn;
  peer->max_players = data->max_players;
  peer->wad_sha1 = data->wad_sha1, peer->deh_sha1 = data->deh_sha1, peer->is_freedoom = data->is_freedoom;
  for (auto& q : peer->send_queue) q.first = -1;
  PacketWriter reply = peer->connection.new_reliable(PacketType::kSyn);
  reply.str(version_);
  reply.str(kProtocolName);
  peer->connection.queue_reliable(std::move(reply));
  std::erase_if(peers_, [](const auto& p) { return !p->active; });
  peers_.push_back(std::move(peer));
}

void Server::parse(Peer& peer, PacketReader& in, uint32_t type, uint32_t now_ms) {
  switch (PacketType(type)) {
    case PacketType::kDisconnect:
      peer.connection.send(PacketWriter(PacketType::kDisconnectAck).bytes(), now_ms);
      for (std::vector<uint8_t>& bytes : peer.connection.take_outgoing()) outgoing_.emplace_back(peer.address, std::move(bytes));
      peer.active = false;
      return;
    case PacketType::kLaunch: {
      if (&peer != controller() || state_ != State::kWaitingLaunch) return;
      std::erase_if(peers_, [](const auto& p) { return !p->active; });  // those gone before the launch
      assign_players();
      for (const auto& p : peers_) {
        if (!p->active) continue;
        PacketWriter w = p->connection.new_reliable(PacketType::kLaunch);
        w.u8(uint32_t(players()));
        p->connection.queue_reliable(std::move(w));
      }
      state_ = State::kWaitingStart;
      return;
    }
    case PacketType::kGameStart: {
      if (state_ != State::kWaitingStart) return;
      if (&peer == controller()) {
        const auto s = in.settings();
        if (!s || s->ticdup < 1 || s->extratics < 0 || s->deathmatch < 0 || s->deathmatch > 2 || s->skill < -1 ||
            s->skill > 4)
          return;
        settings_ = *s;
      }
      peer.ready = true;
      return;
    }
    case PacketType::kGameData: return parse_game_data(peer, in, now_ms);
    case PacketType::kGameDataAck: {
      if (state_ != State::kInGame) return;
      if (const auto ack = in.u8()) peer.acknowledged = std::max(peer.acknowledged, expand(*ack));
      return;
    }
    case PacketType::kGameDataResend: {
      const auto start = in.u32();
      const auto count = start ? in.u8() : std::nullopt;
      if (!count || *count == 0) return;
      const int64_t first = *start, last = first + *count - 1;  // 64 bits: no wrap near 2^32
      for (int64_t t = first; t <= last; ++t)
        if (peer.send_queue[size_t(t % kBackupTics)].first != t) return;  // no longer kept: cannot resend
      return send_tics(peer, uint32_t(first), uint32_t(last), now_ms);
    }
    default: return;
  }
}

void Server::send_waiting_data(Peer& peer, uint32_t now_ms) {
  assign_players();
  Peer* lead = controller();
  WaitData w;
  w.num_players = players();
  w.num_drones = int(std::count_if(peers_.begin(), peers_.end(), [](const auto& p) { return p->active && p->drone; }));
  w.ready_players = int(std::count_if(peers_.begin(), peers_.end(), [](const auto& p) { return p->active && !p->drone && p->ready; }));
  w.max_players = lead ? lead->max_players : kMaxPlayers;
  w.is_controller = &peer == lead;
  w.console_player = peer.player;
  if (!lead) lead = &peer;
  w.wad_sha1 = lead->wad_sha1, w.deh_sha1 = lead->deh_sha1, w.is_freedoom = lead->is_freedoom;
  for (int i = 0; i < w.num_players; ++i) {
    w.player_names.push_back(players_[size_t(i)]->name.substr(0, kMaxPlayerName - 1));
    w.player_addresses.push_back("");  // addresses are not told
  }
  PacketWriter p(PacketType::kWaitingData);
  p.wait_data(w);
  peer.connection.send(std::move(p.bytes()), now_ms);
  peer.last_waiting_at = now_ms;
}

void Server::start_game(uint32_t now_ms) {
  assign_players();
  settings_.low_res_turn = false;
  for (const Peer* p : players_) settings_.low_res_turn |= p && p->low_res_turn;
  settings_.num_players = players();
  for (const auto& p : peers_) {
    if (!p->active) continue;
    p->last_game_data_at = now_ms;
    GameSettings s = settings_;
    s.console_player = p->player;
    PacketWriter w = p->connection.new_reliable(PacketType::kGameStart);
    w.settings(s);
    p->connection.queue_reliable(std::move(w));
  }
  state_ = State::kInGame;
  window_ = {};
  window_start_ = 0;
}

void Server::end_game() {
  for (const auto& p : peers_)
    if (p->active) {
      for (int i = 0; i < 3; ++i) p->connection.send(PacketWriter(PacketType::kDisconnect).bytes(), 0);
      p->active = false;
      for (std::vector<uint8_t>& bytes : p->connection.take_outgoing()) outgoing_.emplace_back(p->address, std::move(bytes));
    }
  state_ = State::kWaitingLaunch;
  game_mode_ = game_mission_ = -1;
}

void Server::parse_game_data(Peer& peer, PacketReader& in, uint32_t now_ms) {
  if (state_ != State::kInGame || peer.drone || peer.player < 0) return;
  const auto ack = in.u8();
  const auto low = ack ? in.u8() : std::nullopt;
  const auto count = low ? in.u8() : std::nullopt;
  if (!count) return;
  const uint32_t seq = expand(*low);
  for (uint32_t i = 0; i < *count; ++i) {
    const auto latency = in.s16();
    const auto diff = latency ? in.tic_diff(settings_.low_res_turn) : std::nullopt;
    if (!diff) return;
    const int64_t index = int64_t(seq) + i - window_start_;
    if (index < 0 || index >= kBackupTics) continue;
    Recv& r = window_[size_t(index)][size_t(peer.player)];
    r.active = true;
    r.diff = *diff;
    peer.last_game_data_at = now_ms;
  }
  peer.acknowledged = std::max(peer.acknowledged, expand(*ack));
  int64_t end = int64_t(seq) - window_start_;  // tics missing before these, never asked for: ask now
  if (end <= 0) return;
  end = std::min<int64_t>(end, kBackupTics - 1);
  int64_t start = end;
  for (int64_t i = end - 1; i >= 0 && !window_[size_t(i)][size_t(peer.player)].active &&
                            window_[size_t(i)][size_t(peer.player)].resend_at == 0;
       --i)
    start = i;
  if (start < end) ask_again(peer, window_start_ + uint32_t(start), window_start_ + uint32_t(end) - 1, now_ms);
}

void Server::ask_again(Peer& peer, uint32_t first, uint32_t last, uint32_t now_ms) {
  PacketWriter p(PacketType::kGameDataResend);
  p.u32(first);
  p.u8(last - first + 1);
  peer.connection.send(std::move(p.bytes()), now_ms);
  for (uint32_t t = first; t <= last; ++t) {
    const int64_t index = int64_t(t) - window_start_;
    if (index >= 0 && index < kBackupTics) window_[size_t(index)][size_t(peer.player)].resend_at = now_ms;
  }
}

void Server::check_resends(Peer& peer, uint32_t now_ms) {
  int64_t first = -1, last = -1;
  for (int64_t i = 0; i < kBackupTics; ++i) {
    const Recv& r = window_[size_t(i)][size_t(peer.player)];
    if (!r.active && r.resend_at != 0 && later(now_ms, r.resend_at, kAskAgainAfter)) {
      if (first < 0) first = i;
      last = i;
    } else if (first >= 0) {
      ask_again(peer, window_start_ + uint32_t(first), window_start_ + uint32_t(last), now_ms);
      first = -1;
    }
  }
  if (first >= 0) ask_again(peer, window_start_ + uint32_t(first), window_start_ + uint32_t(last), now_ms);
}

// NET_SV_CheckDeadlock: a client silent for a second is asked for its next tics, and
// sent again what it has not acknowledged.
void Server::check_deadlock(Peer& peer, uint32_t now_ms) {
  if (peer.drone || !later(now_ms, peer.last_game_data_at, kDeadlockAfter)) return;
  for (int64_t i = 0; i < kBackupTics; ++i)
    if (!window_[size_t(i)][size_t(peer.player)].active) {
      ask_again(peer, window_start_ + uint32_t(i), window_start_ + uint32_t(i) + 5, now_ms);
      peer.last_game_data_at = now_ms;
      if (peer.send_seq > peer.acknowledged) send_tics(peer, peer.acknowledged, peer.send_seq - 1, now_ms);
      return;
    }
}

void Server::send_tics(Peer& peer, uint32_t first, uint32_t last, uint32_t now_ms) {
  PacketWriter p(PacketType::kGameData);
  p.u8(first & 0xff);
  p.u8(last - first + 1);
  for (uint32_t t = first; t <= last; ++t) p.full_tic(peer.send_queue[t % kBackupTics].second, settings_.low_res_turn);
  peer.connection.send(std::move(p.bytes()), now_ms);
}

// NET_SV_PumpSendQueue: the client's next tic, once every other player's command for it
// has come (a player gone plays no more).
void Server::pump_send_queue(Peer& peer, uint32_t now_ms) {
  uint32_t lowest = UINT32_MAX;
  for (const auto& p : peers_)
    if (p->active) lowest = std::min(lowest, p->acknowledged);
  if (peer.send_seq - lowest > kMostUnacknowledged && peer.send_seq > lowest) return;
  const int64_t index = int64_t(peer.send_seq) - window_start_;
  if (index < 0 || index >= kBackupTics) return;
  int others = 0;
  for (int i = 0; i < kMaxPlayers; ++i) {
    const Peer* p = players_[size_t(i)];
    if (p == &peer || !p || !p->active) continue;
    if (!window_[size_t(index)][size_t(i)].active) return;
    ++others;
  }
  if (others == 0 && peer.send_seq > window_start_ + 10) return;
  FullTic tic;
  for (int i = 0; i < kMaxPlayers; ++i) {
    const Peer* p = players_[size_t(i)];
    if (p == &peer || !p || !window_[size_t(index)][size_t(i)].active) continue;
    tic.in_game[size_t(i)] = true;
    tic.cmds[size_t(i)] = window_[size_t(index)][size_t(i)].diff;
  }
  peer.send_queue[peer.send_seq % kBackupTics] = {int64_t(peer.send_seq), tic};
  const uint32_t first = peer.send_seq >= uint32_t(settings_.extratics) ? peer.send_seq - uint32_t(settings_.extratics) : 0;
  send_tics(peer, first, peer.send_seq, now_ms);
  ++peer.send_seq;
}

// NET_SV_AdvanceWindow: past a tic every client acknowledged and every player sent.
void Server::advance_window() {
  if (players() <= 0) return;
  uint32_t lowest = UINT32_MAX;
  for (const auto& p : peers_)
    if (p->active) lowest = std::min(lowest, p->acknowledged);
  while (window_start_ < lowest) {
    for (int i = 0; i < kMaxPlayers; ++i) {
      const Peer* p = players_[size_t(i)];
      if (p && p->active && !window_[0][size_t(i)].active) return;
    }
    std::move(window_.begin() + 1, window_.end(), window_.begin());
    window_.back() = {};
    ++window_start_;
  }
}

void Server::run(uint32_t now_ms) {
  for (const auto& p : peers_) {
    if (!p->active) continue;
    p->connection.run(now_ms);
    if (p->connection.timed_out(now_ms)) p->active = false;
  }
  if (state_ != State::kWaitingLaunch && players() == 0) return end_game();
  switch (state_) {
    case State::kWaitingLaunch:
      for (const auto& p : peers_)
        if (p->active && (p->last_waiting_at == 0 || later(now_ms, p->last_waiting_at, kWaitingDataEvery)))
          send_waiting_data(*p, now_ms);
      return;
    case State::kWaitingStart: {
      const bool all_ready = std::all_of(peers_.begin(), peers_.end(), [](const auto& p) { return !p->active || p->ready; });
      for (const auto& p : peers_)
        if (!p->active && !p->drone && !p->ready) return end_game();  // one left before the start: Chocolate aborts
      if (all_ready) start_game(now_ms);
      return;
    }
    case State::kInGame:
      for (const auto& p : peers_)
        if (p->active) {
          pump_send_queue(*p, now_ms);
          check_deadlock(*p, now_ms);
        }
      advance_window();
      for (Peer* p : players_)
        if (p && p->active) check_resends(*p, now_ms);
      return;
  }
}

}  // namespace p3d::net
