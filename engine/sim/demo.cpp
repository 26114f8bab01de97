#include "engine/sim/demo.h"

#include <cmath>
#include <cstring>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::sim {

namespace {
constexpr char kDemoMagic[8] = {'P', '3', 'D', 'D', 'E', 'M', 'O', '\n'};
constexpr uint32_t kDemoVersion = 3;
constexpr size_t kTicBytes = 5;
constexpr size_t kMaxDemoTics = 35 * 60 * 60 * 24;  // a day of play
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
  out.f64(d.start.x);
  out.f64(d.start.y);
  out.f64(d.angle);
  out.u8(uint8_t(d.skill));
  out.u8(d.keys);
  out.u32(uint32_t(d.tics.size()));
  for (const TicCommand& t : d.tics) {
    out.u8(uint8_t(t.forward));
    out.u8(uint8_t(t.side));
    out.u16(uint16_t(t.turn));
    out.u8(t.buttons);
  }
  out.u64(fnv1a64(out.bytes()));
  return out.release();
}

Demo decode_demo(std::span<const uint8_t> bytes, const std::string& what) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kDemoMagic, 8) != 0) throw Error(what + ": not a demo (bad magic)");
  if (bytes.size() < 8 + 4 + 8 + 24 + 2 + 4 + 8) throw Error(what + ": truncated demo");
  const uint64_t expected = fnv1a64(bytes.subspan(0, bytes.size() - 8));
  ByteReader tail(bytes.subspan(bytes.size() - 8), what);
  ByteReader in(bytes.subspan(8, bytes.size() - 16), what);
  const uint32_t version = in.u32();
  if (version != kDemoVersion)
    throw Error(what + ": demo version " + std::to_string(version) + " is not supported (expected " +
                std::to_string(kDemoVersion) + ")");
  Demo d;
  d.level_fingerprint = in.u64();
  d.start = {in.f64(), in.f64()};
  d.angle = in.f64();
  if (!std::isfinite(d.start.x) || !std::isfinite(d.start.y) || !std::isfinite(d.angle))
    throw Error(what + ": demo start is not finite");
  if (std::fabs(d.start.x) > geom::kMaxCoord || std::fabs(d.start.y) > geom::kMaxCoord || std::fabs(d.angle) > 1e6)
    throw Error(what + ": demo start is out of range");
  d.skill = in.u8();
  if (d.skill < 1 || d.skill > 5) throw Error(what + ": demo skill " + std::to_string(d.skill) + " is not 1..5");
  d.keys = in.u8();
  if (d.keys & ~kAllKeys) throw Error(what + ": unknown keys at the demo's start");
  const uint32_t count = in.count(kTicBytes, "tics");
  if (count > kMaxDemoTics) throw Error(what + ": demo is longer than a day");
  if (in.remaining() != size_t(count) * kTicBytes) throw Error(what + ": truncated or padded demo");
  if (tail.u64() != expected) throw Error(what + ": checksum mismatch (the demo is corrupted)");
  d.tics.resize(count);
  for (TicCommand& t : d.tics) {
    t.forward = int8_t(in.u8());
    t.side = int8_t(in.u8());
    t.turn = int16_t(in.u16());
    t.buttons = in.u8();
    if (t.buttons & ~kButtons) throw Error(what + ": unknown buttons in a tic");
  }
  return d;
}

bool is_our_demo(std::span<const uint8_t> bytes) {
  return bytes.size() >= 8 && std::memcmp(bytes.data(), kDemoMagic, 8) == 0;
}

Demo demo_from_doom(const play::DoomDemo& doom, const level::Level& level) {
  Demo d;
  d.level_fingerprint = fingerprint(level);
  d.start = level.player_start;
  d.angle = level.player_angle;
  d.skill = doom.skill;
  d.tics.reserve(doom.tic_count());
  for (size_t t = 0; t < doom.tic_count(); ++t) {
    const play::DoomTic c = doom.console_tic(t);
    TicCommand cmd{c.forward, c.side, int16_t(c.turn * 256), 0};
    if (!(c.buttons & play::kButtonSpecial) && (c.buttons & play::kButtonUse)) cmd.buttons = kUse;
    d.tics.push_back(cmd);
  }
  return d;
}

play::DoomDemo doom_from_demo(const Demo& demo, int episode, int map) {
  play::DoomDemo d;
  d.skill = demo.skill;
  d.episode = episode;
  d.map = map;
  for (const TicCommand& t : demo.tics)
    d.commands.push_back({t.forward, t.side, int8_t(doom_demo_turn(t.turn) >> 8), uint8_t(t.buttons & kUse ? play::kButtonUse : 0)});
  return d;
}

}  // namespace p3d::sim
