#include "engine/net/protocol.h"

#include <algorithm>

namespace p3d::net {

TicDiff diff_tic(const TicCmd& before, const TicCmd& now) {
  TicDiff d;
  d.cmd = now;
  if (before.forward != now.forward) d.changed |= TicDiff::kForward;
  if (before.side != now.side) d.changed |= TicDiff::kSide;
  if (before.turn != now.turn) d.changed |= TicDiff::kTurn;
  if (before.buttons != now.buttons) d.changed |= TicDiff::kButtons;
  if (before.consistancy != now.consistancy) d.changed |= TicDiff::kConsistancy;
  if (now.chatchar != 0) d.changed |= TicDiff::kChat;
  return d;
}

TicCmd patch_tic(const TicCmd& before, const TicDiff& diff) {
  TicCmd c = before;
  if (diff.changed & TicDiff::kForward) c.forward = diff.cmd.forward;
  if (diff.changed & TicDiff::kSide) c.side = diff.cmd.side;
  if (diff.changed & TicDiff::kTurn) c.turn = diff.cmd.turn;
  if (diff.changed & TicDiff::kButtons) c.buttons = diff.cmd.buttons;
  if (diff.changed & TicDiff::kConsistancy) c.consistancy = diff.cmd.consistancy;
  c.chatchar = (diff.changed & TicDiff::kChat) ? diff.cmd.chatchar : 0;  // a character is sent once
  return c;
}

uint32_t expand_tic(uint32_t relative, uint32_t low_byte) {
  const uint32_t high = relative & ~0xffu, low = relative & 0xffu;
  uint32_t result = high | low_byte;
  if (low < 0x40 && low_byte > 0xb0) result -= 0x100;
  if (low > 0xb0 && low_byte < 0x40) result += 0x100;
  return result;
}

// ---- writing

void PacketWriter::str(const std::string& s) {
  bytes_.insert(bytes_.end(), s.begin(), std::find(s.begin(), s.end(), '\0'));
  bytes_.push_back(0);
}

void PacketWriter::protocol_list() {
  u8(1);
  str(kProtocolName);
}

void PacketWriter::connect_data(const ConnectData& d) {
  for (int v : {d.game_mode, d.game_mission, int(d.low_res_turn), int(d.drone), d.max_players, int(d.is_freedoom)}) u8(uint32_t(v));
  blob(d.wad_sha1);
  blob(d.deh_sha1);
  u8(uint32_t(d.player_class));
}

void PacketWriter::settings(const GameSettings& s) {
  for (int v : {s.ticdup, s.extratics, s.deathmatch, int(s.no_monsters), int(s.fast_monsters), int(s.respawn_monsters),
                s.episode, s.map, s.skill, s.game_version, int(s.low_res_turn), int(s.new_sync)})
    u8(uint32_t(v));
  u32(uint32_t(s.time_limit));
  for (int v : {s.load_game, s.random, s.num_players, s.console_player}) u8(uint32_t(v));
  for (int i = 0; i < s.num_players && i < kMaxPlayers; ++i) u8(uint32_t(s.player_classes[size_t(i)]));
}

void PacketWriter::tic_diff(const TicDiff& d, bool low_res_turn) {
  const uint8_t changed = d.changed & ~(TicDiff::kRaven | TicDiff::kStrife);
  u8(changed);
  if (changed & TicDiff::kForward) u8(uint32_t(d.cmd.forward));
  if (changed & TicDiff::kSide) u8(uint32_t(d.cmd.side));
  if (changed & TicDiff::kTurn) low_res_turn ? u8(uint32_t(d.cmd.turn / 256)) : u16(uint32_t(d.cmd.turn));
  if (changed & TicDiff::kButtons) u8(d.cmd.buttons);
  if (changed & TicDiff::kConsistancy) u8(d.cmd.consistancy);
  if (changed & TicDiff::kChat) u8(d.cmd.chatchar);
}

void PacketWriter::full_tic(const FullTic& t, bool low_res_turn) {
  u16(uint32_t(t.latency));
  uint32_t mask = 0;
  for (int i = 0; i < kMaxPlayers; ++i) mask |= uint32_t(t.in_game[size_t(i)]) << i;
  u8(mask);
  for (int i = 0; i < kMaxPlayers; ++i)
    if (t.in_game[size_t(i)]) tic_diff(t.cmds[size_t(i)], low_res_turn);
}

void PacketWriter::wait_data(const WaitData& w) {
  for (int v : {w.num_players, w.num_drones, w.ready_players, w.max_players, int(w.is_controller), w.console_player})
    u8(uint32_t(v));
  for (int i = 0; i < w.num_players && i < kMaxPlayers; ++i) {
    str(size_t(i) < w.player_names.size() ? w.player_names[size_t(i)] : "");
    str(size_t(i) < w.player_addresses.size() ? w.player_addresses[size_t(i)] : "");
  }
  blob(w.wad_sha1);
  blob(w.deh_sha1);
  u8(w.is_freedoom);
}

// ---- reading

std::optional<uint32_t> PacketReader::u8() {
  if (left() < 1) return std::nullopt;
  return bytes_[at_++];
}

std::optional<uint32_t> PacketReader::u16() {
  if (left() < 2) return std::nullopt;
  const uint32_t v = uint32_t(bytes_[at_]) << 8 | bytes_[at_ + 1];
  at_ += 2;
  return v;
}

std::optional<uint32_t> PacketReader::u32() {
  const auto high = u16();
  const auto low = high ? u16() : std::nullopt;
  if (!low) return std::nullopt;
  return *high << 16 | *low;
}

std::optional<int32_t> PacketReader::s8() {
  const auto v = u8();
  return v ? std::optional<int32_t>(int8_t(*v)) : std::nullopt;
}

std::optional<int32_t> PacketReader::s16() {
  const auto v = u16();
  return v ? std::optional<int32_t>(int16_t(*v)) : std::nullopt;
}

std::optional<std::string> PacketReader::str() {
  const auto end = std::find(bytes_.begin() + ptrdiff_t(at_), bytes_.end(), uint8_t(0));
  if (end == bytes_.end()) return std::nullopt;
  std::string s(bytes_.begin() + ptrdiff_t(at_), end);
  at_ = size_t(end - bytes_.begin()) + 1;
  return s;
}

bool PacketReader::blob(std::span<uint8_t> out) {
  if (left() < out.size()) return false;
  std::copy_n(bytes_.begin() + ptrdiff_t(at_), out.size(), out.begin());
  at_ += out.size();
  return true;
}

bool PacketReader::protocol_list_has_ours() {
  const auto count = u8();
  if (!count) return false;
  bool ours = false;
  for (uint32_t i = 0; i < *count; ++i) {
    const auto name = str();
    if (!name) return false;
    ours |= *name == kProtocolName;
  }
  return ours;
}

std::optional<ConnectData> PacketReader::connect_data() {
  ConnectData d;
  const auto mode = u8(), mission = u8(), low = u8(), drone = u8(), max = u8(), freedoom = u8();
  if (!freedoom || !blob(d.wad_sha1) || !blob(d.deh_sha1)) return std::nullopt;
  const auto player_class = u8();
  if (!player_class) return std::nullopt;
  d.game_mode = int(*mode), d.game_mission = int(*mission), d.low_res_turn = *low, d.drone = *drone;
  d.max_players = int(*max), d.is_freedoom = *freedoom, d.player_class = int(*player_class);
  return d;
}

std::optional<GameSettings> PacketReader::settings() {
  GameSettings s;
  const auto ticdup = u8(), extratics = u8(), deathmatch = u8(), no_monsters = u8(), fast = u8(), respawn = u8();
  const auto episode = u8(), map = u8();
  const auto skill = s8();
  const auto version = u8(), low = u8(), new_sync = u8();
  const auto time_limit = u32();
  const auto load_game = s8();
  const auto random = u8(), players = u8();
  const auto console = s8();
  if (!console) return std::nullopt;  // each read after a failed one fails too
  s.ticdup = int(*ticdup), s.extratics = int(*extratics), s.deathmatch = int(*deathmatch);
  s.no_monsters = *no_monsters, s.fast_monsters = *fast, s.respawn_monsters = *respawn;
  s.episode = int(*episode), s.map = int(*map), s.skill = *skill, s.game_version = int(*version);
  s.low_res_turn = *low, s.new_sync = *new_sync, s.time_limit = int32_t(*time_limit);
  s.load_game = *load_game, s.random = int(*random), s.num_players = int(*players), s.console_player = *console;
  for (int i = 0; i < s.num_players && i < kMaxPlayers; ++i) {
    const auto c = u8();
    if (!c) return std::nullopt;
    s.player_classes[size_t(i)] = int(*c);
  }
  return s;
}

std::optional<TicDiff> PacketReader::tic_diff(bool low_res_turn) {
  TicDiff d;
  const auto changed = u8();
  if (!changed) return std::nullopt;
  d.changed = uint8_t(*changed);
  auto field = [&](uint8_t bit, auto read, auto store) {
    if (!(d.changed & bit)) return true;
    const auto v = read();
    if (v) store(*v);
    return v.has_value();
  };
  const bool ok =
      field(TicDiff::kForward, [&] { return s8(); }, [&](int32_t v) { d.cmd.forward = int8_t(v); }) &&
      field(TicDiff::kSide, [&] { return s8(); }, [&](int32_t v) { d.cmd.side = int8_t(v); }) &&
      field(TicDiff::kTurn, [&] { return low_res_turn ? s8() : s16(); },
            [&](int32_t v) { d.cmd.turn = int16_t(low_res_turn ? v * 256 : v); }) &&
      field(TicDiff::kButtons, [&] { return u8(); }, [&](uint32_t v) { d.cmd.buttons = uint8_t(v); }) &&
      field(TicDiff::kConsistancy, [&] { return u8(); }, [&](uint32_t v) { d.cmd.consistancy = uint8_t(v); }) &&
      field(TicDiff::kChat, [&] { return u8(); }, [&](uint32_t v) { d.cmd.chatchar = uint8_t(v); }) &&
      field(TicDiff::kRaven, [&] { return u16(); }, [](uint32_t) {}) &&  // lookfly, arti
      field(TicDiff::kStrife, [&] { auto b = u8(); return b ? u16() : b; }, [](uint32_t) {});  // buttons2, inventory
  if (!ok) return std::nullopt;
  return d;
}

std::optional<FullTic> PacketReader::full_tic(bool low_res_turn) {
  FullTic t;
  const auto latency = s16();
  const auto mask = latency ? u8() : std::nullopt;
  if (!mask) return std::nullopt;
  t.latency = *latency;
  for (int i = 0; i < kMaxPlayers; ++i) {
    t.in_game[size_t(i)] = (*mask >> i) & 1;
    if (!t.in_game[size_t(i)]) continue;
    const auto d = tic_diff(low_res_turn);
    if (!d) return std::nullopt;
    t.cmds[size_t(i)] = *d;
  }
  return t;
}

std::optional<WaitData> PacketReader::wait_data() {
  WaitData w;
  const auto players = u8(), drones = u8(), ready = u8(), max = u8(), controller = u8();
  const auto console = s8();
  if (!console) return std::nullopt;
  w.num_players = int(*players), w.num_drones = int(*drones), w.ready_players = int(*ready), w.max_players = int(*max);
  w.is_controller = *controller, w.console_player = *console;
  for (int i = 0; i < w.num_players && i < kMaxPlayers; ++i) {
    auto name = str();
    auto address = name ? str() : std::nullopt;
    if (!address || name->size() >= size_t(kMaxPlayerName) || address->size() >= size_t(kMaxPlayerName)) return std::nullopt;
    w.player_names.push_back(*name);
    w.player_addresses.push_back(*address);
  }
  const auto freedoom = blob(w.wad_sha1) && blob(w.deh_sha1) ? u8() : std::nullopt;
  if (!freedoom) return std::nullopt;
  w.is_freedoom = *freedoom;
  return w;
}

}  // namespace p3d::net
