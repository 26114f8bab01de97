#include "engine/net/client.h"

namespace p3d::net {

namespace {

constexpr uint32_t kSynEvery = 1000, kConnectTimeout = 5000;  // ms, as net_client.c
constexpr uint32_t kAckAfter = 200;
constexpr uint32_t kRejectionGrace = 1500;  // more than the server's resending of its answer

}  // namespace

Client::Client(Options options, uint32_t now_ms) : options_(std::move(options)), connection_(now_ms), started_at_(now_ms) {}

std::vector<std::vector<uint8_t>> Client::take_outgoing() { return connection_.take_outgoing(); }

void Client::leave(uint32_t now_ms) {
  // Three times, not waiting for the answer: a lost word leaves the server to its timeout.
  if (state_ != State::kDisconnected)
    for (int i = 0; i < 3; ++i) send(PacketWriter(PacketType::kDisconnect).bytes(), now_ms);
  disconnect("left the game");
}

void Client::send_syn(uint32_t now_ms) {
  PacketWriter p(PacketType::kSyn);
  p.u32(kMagic);
  p.str(options_.version);
  p.protocol_list();
  p.connect_data(options_.connect);
  p.str(options_.player_name);
  send(std::move(p.bytes()), now_ms);
  last_syn_at_ = now_ms;
  syn_sent_ = true;
}

void Client::disconnect(const std::string& why) {
  if (state_ == State::kDisconnected) return;
  state_ = State::kDisconnected;
  error_ = why;
}

void Client::launch() {
  if (launched_ || state_ != State::kWaitingLaunch) return;
  launched_ = true;
  connection_.queue_reliable(connection_.new_reliable(PacketType::kLaunch));
}

void Client::run(uint32_t now_ms) {
  switch (state_) {
    case State::kDisconnected: return;
    case State::kConnecting:
      if (rejection_ && later(now_ms, rejected_at_, kRejectionGrace)) return disconnect("the server refused: " + *rejection_);
      if (later(now_ms, started_at_, kConnectTimeout)) return disconnect(rejection_ ? "the server refused: " + *rejection_ : "no answer from the server");
      if (!rejection_ && (!syn_sent_ || later(now_ms, last_syn_at_, kSynEvery))) send_syn(now_ms);
      return;
    default: break;
  }
  if (connection_.timed_out(now_ms)) return disconnect("the server stopped answering (30 s)");
  connection_.run(now_ms);
  if (state_ == State::kWaitingLaunch && wait_data_ && wait_data_->is_controller && options_.launch_at_players > 0 &&
      wait_data_->num_players + wait_data_->num_drones >= options_.launch_at_players)
    launch();
  if (state_ == State::kInGame) {
    advance_window();
    check_resends(now_ms);
  }
}

void Client::receive(std::span<const uint8_t> bytes, uint32_t now_ms) {
  if (state_ == State::kDisconnected) return;
  PacketReader in(bytes);
  if (const auto type = connection_.receive(in, now_ms)) parse(in, *type, now_ms);
}

void Client::parse(PacketReader& in, uint32_t type, uint32_t now_ms) {
  switch (PacketType(type)) {
    case PacketType::kSyn: {  // the server's answer: connected
      const auto version = in.str();
      if (!version || state_ != State::kConnecting || !in.str()) return;
      state_ = State::kWaitingLaunch;
      return;
    }
    case PacketType::kRejected:
      // Refused, or our SYN sent again after the server took us in and launched (its
      // answer lost on the way, and on its way again): wait for that answer a little.
      if (const auto why = in.str(); why && state_ == State::kConnecting && !rejection_) rejection_ = *why, rejected_at_ = now_ms;
      return;
    case PacketType::kDisconnect: {
      send(PacketWriter(PacketType::kDisconnectAck).bytes(), now_ms);
      return disconnect("the server ended the game");
    }
    case PacketType::kWaitingData: {
      auto w = in.wait_data();
      if (!w || w->num_players > w->max_players || w->ready_players > w->num_players || w->max_players > kMaxPlayers ||
          w->console_player < 0 || w->console_player >= w->num_players)
        return;
      wait_data_ = std::move(*w);
      return;
    }
    case PacketType::kLaunch: {
      if (state_ != State::kWaitingLaunch || !in.u8()) return;
      state_ = State::kWaitingStart;
      PacketWriter start = connection_.new_reliable(PacketType::kGameStart);  // D_StartNetGame: our settings
      start.settings(options_.settings);
      connection_.queue_reliable(std::move(start));
      return;
    }
    case PacketType::kGameStart: {
      const auto s = in.settings();
      if (!s || state_ != State::kWaitingStart || s->num_players > kMaxPlayers || s->console_player < 0 ||
          s->console_player >= s->num_players || s->ticdup < 1)
        return;
      settings_ = *s;
      state_ = State::kInGame;
      return;
    }
    case PacketType::kGameData: return parse_game_data(in, now_ms);
    case PacketType::kGameDataResend: return parse_resend_request(in, now_ms);
    default: return;  // keepalives, console messages, queries: nothing to do
  }
}

// ---- in game

void Client::send_tic(const TicCmd& cmd, uint32_t now_ms) {
  if (state_ != State::kInGame) return;
  SentTic& s = send_queue_[make_tic_ % kBackupTics];
  s = {true, make_tic_, diff_tic(last_sent_, cmd)};
  last_sent_ = cmd;
  const uint32_t first = make_tic_ >= uint32_t(settings_.extratics) ? make_tic_ - uint32_t(settings_.extratics) : 0;
  send_tics(first, make_tic_, now_ms);
  ++make_tic_;
}

void Client::send_tics(uint32_t first, uint32_t last, uint32_t now_ms) {
  PacketWriter p(PacketType::kGameData);
  p.u8(window_start_ & 0xff);  // what we have received, in full
  p.u8(first & 0xff);
  p.u8(last - first + 1);
  for (uint32_t t = first; t <= last; ++t) {
    p.u16(0);  // our latency: Chocolate's clock sync, which we do not ask for
    p.tic_diff(send_queue_[t % kBackupTics].diff, settings_.low_res_turn);
  }
  send(std::move(p.bytes()), now_ms);
  need_ack_ = false;
}

void Client::parse_resend_request(PacketReader& in, uint32_t now_ms) {
  const auto start = in.u32();
  const auto count = start ? in.u8() : std::nullopt;
  if (!count || *count == 0) return;
  // In 64 bits: a request near 2^32 must not wrap into four billion steps.
  int64_t first = *start, last = int64_t(*start) + *count - 1;
  auto have = [&](int64_t t) {
    const SentTic& s = send_queue_[size_t(t % kBackupTics)];
    return s.active && s.seq == t;
  };
  while (first <= last && !have(first)) ++first;
  while (first <= last && !have(last)) --last;
  if (first <= last) send_tics(uint32_t(first), uint32_t(last), now_ms);
}

void Client::parse_game_data(PacketReader& in, uint32_t now_ms) {
  const auto low = in.u8();
  const auto count = low ? in.u8() : std::nullopt;
  if (!count) return;
  if (!need_ack_) need_ack_ = true, game_data_at_ = now_ms;
  const uint32_t seq = expand_tic(window_start_, *low);
  for (uint32_t i = 0; i < *count; ++i) {
    const auto tic = in.full_tic(settings_.low_res_turn);
    if (!tic) return;
    const int64_t index = int64_t(seq) + i - window_start_;
    if (index < 0 || index >= kBackupTics) continue;
    window_[size_t(index)].active = true;
    window_[size_t(index)].tic = *tic;
  }
  // Tics missing before this packet's, never asked for: ask now.
  int64_t end = int64_t(seq) - window_start_;
  if (end <= 0) return;
  end = std::min<int64_t>(end, kBackupTics - 1);
  int64_t start = end;
  for (int64_t i = end - 1; i >= 0 && !window_[size_t(i)].active && window_[size_t(i)].resend_at == 0; --i) start = i;
  if (start < end) ask_again(window_start_ + uint32_t(start), window_start_ + uint32_t(end) - 1, now_ms);
}

void Client::ask_again(uint32_t first, uint32_t last, uint32_t now_ms) {
  PacketWriter p(PacketType::kGameDataResend);
  p.u32(first);
  p.u8(last - first + 1);
  send(std::move(p.bytes()), now_ms);
  for (uint32_t t = first; t <= last; ++t) {
    const int64_t index = int64_t(t) - window_start_;
    if (index >= 0 && index < kBackupTics) window_[size_t(index)].resend_at = now_ms;
  }
}

void Client::check_resends(uint32_t now_ms) {
  const bool maybe_deadlocked = later(now_ms, game_data_at_, kDeadlockAfter);
  int64_t first = -1, last = -1;
  for (int64_t i = 0; i < kBackupTics; ++i) {
    const ReceivedTic& r = window_[size_t(i)];
    const bool again = (!r.active && r.resend_at != 0 && later(now_ms, r.resend_at, kAskAgainAfter)) ||
                       (i == 0 && !r.active && r.resend_at == 0 && maybe_deadlocked);
    if (again) {
      if (first < 0) first = i;
      last = i;
    } else if (first >= 0) {
      ask_again(window_start_ + uint32_t(first), window_start_ + uint32_t(last), now_ms);
      first = -1;
    }
  }
  if (first >= 0) ask_again(window_start_ + uint32_t(first), window_start_ + uint32_t(last), now_ms);
  if (need_ack_ && later(now_ms, game_data_at_, kAckAfter)) {
    PacketWriter ack(PacketType::kGameDataAck);
    ack.u8(window_start_ & 0xff);
    send(std::move(ack.bytes()), now_ms);
    need_ack_ = false;
  }
}

void Client::advance_window() {
  while (window_[0].active) {
    ServerTic t;
    const FullTic& full = window_[0].tic;
    for (int i = 0; i < kMaxPlayers; ++i) {
      if (i == settings_.console_player || !full.in_game[size_t(i)]) continue;
      base_[size_t(i)] = patch_tic(base_[size_t(i)], full.cmds[size_t(i)]);
      t.in_game[size_t(i)] = true;
      t.cmds[size_t(i)] = base_[size_t(i)];
    }
    ready_.push_back(t);
    std::move(window_.begin() + 1, window_.end(), window_.begin());
    window_.back() = {};
    ++window_start_;
  }
}

std::optional<Client::ServerTic> Client::next_server_tic() {
  if (ready_.empty()) return std::nullopt;
  ServerTic t = ready_.front();
  ready_.pop_front();
  return t;
}

}  // namespace p3d::net
