// The play simulation itself: a small WAD map made from the input (rooms side by side
// with corners and heights anywhere in Doom's 16-bit range, any line and sector
// specials, tags that may match, things of any type, raw BLOCKMAP, REJECT and node
// lumps beside it), played for a few hundred tics of the input's commands under the
// input's game options. A map may be refused with an Error; nothing may crash or
// overflow.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>

#include "engine/bsp/load.h"
#include "engine/play/world.h"
#include "engine/util/error.h"
#include "tests/fuzz/target.h"
#include "tests/support/wad_writer.h"

using namespace p3d;
using test::TestMap;

namespace {

constexpr int kMaxTics = 400;
// Things worth meeting: monsters that walk, shoot and explode, pickups, keys, a
// teleport's exit (the rest of the types come raw).
constexpr int kThingTypes[] = {3004, 9, 3001, 3002, 3005, 3003, 64, 66, 67, 68, 69, 71, 84, 65, 16, 7, 3006,
                               2035, 2012, 2014, 2015, 2001, 2002, 2006, 8, 2019, 5, 13, 38, 14, 2024, 2023};

int16_t coordinate(FuzzedDataProvider& in) { return in.ConsumeIntegral<int16_t>(); }

// Rooms side by side between cuts along x, all spanning the same y, so that
// neighbours share a wall and it opens between them.
void add_rooms(FuzzedDataProvider& in, TestMap& m) {
  std::vector<int> cuts;
  for (int i = in.ConsumeIntegralInRange(2, 5); i > 0; --i) cuts.push_back(coordinate(in));
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  int y0 = coordinate(in), y1 = coordinate(in);
  if (y0 > y1) std::swap(y0, y1);
  if (cuts.size() < 2 || y0 == y1) throw Error("fuzz: no room");
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    TestMap::Sector s;
    s.floor = coordinate(in), s.ceiling = coordinate(in);
    s.light = in.ConsumeIntegral<uint8_t>();
    s.special = in.ConsumeBool() ? in.ConsumeIntegralInRange(0, 17) : in.ConsumeIntegral<int16_t>();
    s.tag = in.ConsumeBool() ? in.ConsumeIntegralInRange(0, 3) : in.ConsumeIntegral<int16_t>();
    if (in.ConsumeBool()) s.ceiling_flat = "F_SKY1";
    m.add_room({{cuts[i], y0}, {cuts[i], y1}, {cuts[i + 1], y1}, {cuts[i + 1], y0}}, s);
  }
}

// Specials, tags and flags on the lines (the two-sided bit stays the map's own).
void set_lines(FuzzedDataProvider& in, TestMap& m) {
  for (TestMap::Line& line : m.lines) {
    if (!in.ConsumeBool()) continue;
    line.special = in.ConsumeBool() ? in.ConsumeIntegralInRange(0, 141) : in.ConsumeIntegral<uint16_t>();
    line.tag = in.ConsumeBool() ? in.ConsumeIntegralInRange(0, 3) : in.ConsumeIntegral<uint16_t>();
    line.flags = (in.ConsumeIntegral<uint16_t>() & ~TestMap::kTwoSided) | (line.flags & TestMap::kTwoSided);
  }
}

void add_things(FuzzedDataProvider& in, TestMap& m) {
  m.things.push_back({coordinate(in), coordinate(in), in.ConsumeIntegral<int16_t>(), 1});
  for (int i = in.ConsumeIntegralInRange(0, 8); i > 0; --i) {
    const int type = in.ConsumeBool() ? in.PickValueInArray(kThingTypes) : in.ConsumeIntegral<uint16_t>();
    m.things.push_back({coordinate(in), coordinate(in), in.ConsumeIntegral<int16_t>(), type, in.ConsumeIntegral<uint8_t>()});
  }
}

wad::Stack wads_from(FuzzedDataProvider& in) {
  TestMap m;
  add_rooms(in, m);
  set_lines(in, m);
  add_things(in, m);
  test::WadWriter w(true);
  test::add_test_art(w);
  m.add_to(w, "MAP01");
  for (const char* name : {"SEGS", "SSECTORS", "NODES", "REJECT", "BLOCKMAP"})
    if (in.ConsumeBool()) w.lump(name, in.ConsumeBytes<uint8_t>(in.ConsumeIntegralInRange(0, 600)));
  wad::Stack stack;
  stack.add(wad::Wad(w.bytes(), "fuzz.wad"));
  return stack;
}

play::GameOptions options_from(FuzzedDataProvider& in) {
  play::GameOptions o;
  o.skill = in.ConsumeIntegralInRange(1, 5);
  o.fast = in.ConsumeBool(), o.respawn = in.ConsumeBool(), o.no_monsters = in.ConsumeBool();
  o.commercial = in.ConsumeBool(), o.ultimate = in.ConsumeBool();
  o.map = in.ConsumeIntegralInRange(0, 32), o.episode = in.ConsumeIntegralInRange(1, 4);
  return o;
}

}  // namespace

P3D_FUZZ_TARGET(world) {
  FuzzedDataProvider in(data, size);
  try {
    const wad::Stack wads = wads_from(in);
    const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
    play::World world(play::map_from_wads(wads, "MAP01", level), level, options_from(in), play::Random{});
    const int tics = in.ConsumeIntegralInRange(1, kMaxTics);
    for (int t = 0; t < tics && world.exit() == play::ExitKind::kNone; ++t) {
      play::TicCmd cmd;
      cmd.forward = in.ConsumeIntegral<int8_t>(), cmd.side = in.ConsumeIntegral<int8_t>();
      cmd.turn = in.ConsumeIntegral<int16_t>(), cmd.buttons = in.ConsumeIntegral<uint8_t>();
      world.tick(cmd);
    }
    (void)world.state();
  } catch (const Error&) {
  }
  return 0;
}
