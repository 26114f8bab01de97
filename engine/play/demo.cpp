#include "engine/play/demo.h"

#include <cmath>
#include <cstring>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::play {

namespace {
constexpr char kDemoMagic[8] = {'P', '3', 'D', 'D', 'E', 'M', 'O', '\n'};
constexpr uint32_t kDemoVersion = 4;  // 4: Doom's tic commands and rules; 3 and older walked without them
constexpr size_t kTicBytes = 6;
constexpr size_t kMaxDemoTics = 35 * 60 * 60 * 24;  // a day of play
constexpr uint8_t kFast = 1, kRespawn = 2, kNoMonsters = 4, kCustomStart = 8, kOptions = 15;
constexpr uint8_t kAllKeys = 63;
}  // namespace

uint64_t fingerprint(const level::Level& level) {
  ByteWriter out;
  for (const level::Wall& w : level.walls) {
    out.i64(w.p1.x), out.i64(w.p1.y), out.i64(w.p2.x), out.i64(w.p2.y);
    out.u32(w.flags);
    out.i32(w.sides[0].sector), out.i32(w.sides[1].sector);
  }
  for (const level::Wall& w : level.walls) out.i32(w.special), out.i32(w.tag);
  for (const level::Sector& s : level.sectors) out.f64(s.floor), out.f64(s.ceiling), out.i32(s.special), out.i32(s.tag);
  for (const level::Thing& t : level.things) out.i32(t.type), out.f64(t.pos.x), out.f64(t.pos.y), out.u32(t.flags);
  out.i32(level.default_sector);
  return fnv1a64(out.bytes());
}

std::vector<uint8_t> encode_demo(const Demo& d) {
  ByteWriter out;
  out.raw(std::span(reinterpret_cast<const uint8_t*>(kDemoMagic), 8));
  out.u32(kDemoVersion);
  out.u64(d.level_fingerprint);
  out.u8(uint8_t(d.skill));
  out.u8(uint8_t((d.fast ? kFast : 0) | (d.respawn ? kRespawn : 0) | (d.no_monsters ? kNoMonsters : 0) |
                 (d.custom_start ? kCustomStart : 0)));
  out.f64(d.start.x);
  out.f64(d.start.y);
  out.f64(d.angle);
  out.u8(d.keys);
  out.u32(uint32_t(d.tics.size()));
  for (const DemoTic& t : d.tics) {
    out.u8(uint8_t(t.cmd.forward));
    out.u8(uint8_t(t.cmd.side));
    out.u16(uint16_t(t.cmd.turn));
    out.u8(t.cmd.buttons);
    out.u8(t.cheats);
  }
  out.u64(fnv1a64(out.bytes()));
  return out.release();
}

Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kDemoMagic, 8) != 0) throw Error(what + ": not a demo (bad magic)");
  if (bytes.size() < 8 + 4) throw Error(what + ": truncated demo");
  ByteReader head(bytes.subspan(8, 4), what);
  const uint32_t version = head.u32();
  if (version < kDemoVersion)
    throw Error(what + ": demo version " + std::to_string(version) +
                " was recorded before the game played by Doom's rules: record it again");
  if (version != kDemoVersion)
    throw Error(what + ": demo version " + std::to_string(version) + " is not supported (expected " +
                std::to_string(kDemoVersion) + ")");
  if (bytes.size() < 8 + 4 + 8 + 2 + 24 + 1 + 4 + 8) throw Error(what + ": truncated demo");
  const uint64_t expected = fnv1a64(bytes.subspan(0, bytes.size() - 8));
  ByteReader tail(bytes.subspan(bytes.size() - 8), what);
  ByteReader in(bytes.subspan(12, bytes.size() - 20), what);
  Demo d;
  d.level_fingerprint = in.u64();
  d.skill = in.u8();
  if (d.skill < 1 || d.skill > 5) throw Error(what + ": demo skill " + std::to_string(d.skill) + " is not 1..5");
  const uint8_t options = in.u8();
  if (options & ~kOptions) throw Error(what + ": unknown game options in the demo");
  d.fast = options & kFast;
  d.respawn = options & kRespawn;
  d.no_monsters = options & kNoMonsters;
  d.custom_start = options & kCustomStart;
  d.start = {in.f64(), in.f64()};
  d.angle = in.f64();
  if (!std::isfinite(d.start.x) || !std::isfinite(d.start.y) || !std::isfinite(d.angle))
    throw Error(what + ": demo start is not finite");
  if (std::fabs(d.start.x) > 32767 || std::fabs(d.start.y) > 32767 || std::fabs(d.angle) > 1e6)
    throw Error(what + ": demo start is out of range");
  d.keys = in.u8();
  if (d.keys & ~kAllKeys) throw Error(what + ": unknown keys at the demo's start");
  const uint32_t count = in.count(kTicBytes, "tics");
  if (count > kMaxDemoTics) throw Error(what + ": demo is longer than a day");
  if (in.remaining() != size_t(count) * kTicBytes) throw Error(what + ": truncated or padded demo");
  if (tail.u64() != expected) throw Error(what + ": checksum mismatch (the demo is corrupted)");
  d.tics.resize(count);
  for (DemoTic& t : d.tics) {
    t.cmd.forward = int8_t(in.u8());
    t.cmd.side = int8_t(in.u8());
    t.cmd.turn = int16_t(in.u16());
    t.cmd.buttons = in.u8();
    t.cheats = in.u8();
    if (t.cheats & ~kDemoCheats) throw Error(what + ": unknown cheats in a tic");
  }
  return d;
}

bool is_our_demo(std::span<const uint8_t> bytes) {
  return bytes.size() >= 8 && std::memcmp(bytes.data(), kDemoMagic, 8) == 0;
}

std::array<TicCmd, kMaxPlayers> players_tic(const DoomDemo& doom, size_t tic) {
  std::array<TicCmd, kMaxPlayers> cmds{};
  for (int n = 0; n < kMaxPlayers; ++n)
    if (doom.players[size_t(n)]) {
      const DoomTic d = doom.player_tic(tic, n);
      cmds[size_t(n)] = TicCmd{d.forward, d.side, d.turn, d.buttons};
    }
  return cmds;
}

Demo demo_from_doom(const DoomDemo& doom, const level::Level& level) {
  Demo d;
  d.level_fingerprint = fingerprint(level);
  d.skill = doom.skill;
  d.fast = doom.fast;
  d.respawn = doom.respawn;
  d.no_monsters = doom.no_monsters;
  d.tics.reserve(doom.tic_count());
  for (size_t t = 0; t < doom.tic_count(); ++t) {
    const DoomTic c = doom.console_tic(t);
    d.tics.push_back({TicCmd{c.forward, c.side, c.turn, c.buttons}, 0});
  }
  return d;
}

DoomDemo doom_from_demo(const Demo& demo, int episode, int map, bool long_tics) {
  DoomDemo d;
  if (long_tics) d.version = DoomDemo::kVersionLongTics;
  d.skill = demo.skill;
  d.fast = demo.fast;
  d.respawn = demo.respawn;
  d.no_monsters = demo.no_monsters;
  d.episode = episode;
  d.map = map;
  for (const DemoTic& t : demo.tics)
    d.commands.push_back({t.cmd.forward, t.cmd.side, long_tics ? t.cmd.turn : doom_demo_turn(t.cmd.turn), t.cmd.buttons});
  return d;
}

}  // namespace p3d::play
