// Doom's binary map lumps, little-endian records:
//   THINGS    10 bytes: i16 x, y, angle, type, flags
//   LINEDEFS  14 bytes: u16 v1, v2, flags, special, tag, front sidedef, back sidedef (0xFFFF: none)
//   SIDEDEFS  30 bytes: i16 x offset, y offset, name[8] upper, lower, middle, u16 sector
//   VERTEXES   4 bytes: i16 x, y
//   SECTORS   26 bytes: i16 floor, ceiling, name[8] floor flat, ceiling flat, i16 light, special, tag
// Indices are read unsigned (maps with more than 32767 sidedefs exist).
#include "engine/util/bytes.h"
#include "engine/util/error.h"
#include "engine/wad/map_data.h"

namespace p3d::wad {

namespace {

constexpr uint16_t kNoSidedef = 0xFFFF;

std::string name8(ByteReader& in) {
  const auto raw = in.raw(kNameSize);
  return normalize_name(std::string_view(reinterpret_cast<const char*>(raw.data()), kNameSize));
}

// The lump's records: throws when the lump is missing or not a whole number of records.
ByteReader records(const MapLumps& m, const std::string& where, std::string_view lump_name, size_t record,
                   size_t& count) {
  const Lump* lump = m.find(lump_name);
  if (!lump) throw Error(where + ": the map has no " + std::string(lump_name) + " lump");
  if (lump->bytes.size() % record != 0)
    throw Error(where + ": " + std::string(lump_name) + " is " + std::to_string(lump->bytes.size()) +
                " bytes, not a whole number of " + std::to_string(record) + "-byte records");
  count = lump->bytes.size() / record;
  return ByteReader(lump->bytes, where + ": " + std::string(lump_name));
}

int16_t s16(ByteReader& in) { return static_cast<int16_t>(in.u16()); }

}  // namespace

MapData read_binary_map(const MapLumps& m) {
  MapData d;
  d.name = m.name;
  d.where = m.wad_name + ":" + m.name;
  if (m.find("BEHAVIOR"))
    throw Error(d.where + ": a Hexen-format map (BEHAVIOR lump): only Doom's format and UDMF are supported");
  size_t n = 0;

  ByteReader vertices = records(m, d.where, "VERTEXES", kVertexRecord, n);
  d.vertices.resize(n);
  for (MapVertex& v : d.vertices) {
    v.x = s16(vertices);
    v.y = s16(vertices);
  }

  ByteReader sectors = records(m, d.where, "SECTORS", kSectorRecord, n);
  d.sectors.resize(n);
  for (MapSector& s : d.sectors) {
    s.floor = s16(sectors);
    s.ceiling = s16(sectors);
    s.floor_flat = name8(sectors);
    s.ceiling_flat = name8(sectors);
    s.light = s16(sectors);
    s.special = s16(sectors);
    s.tag = sectors.u16();
  }

  ByteReader sides = records(m, d.where, "SIDEDEFS", kSidedefRecord, n);
  d.sidedefs.resize(n);
  for (MapSidedef& s : d.sidedefs) {
    s.x_offset = s16(sides);
    s.y_offset = s16(sides);
    s.upper = name8(sides);
    s.lower = name8(sides);
    s.middle = name8(sides);
    s.sector = sides.u16();
  }

  ByteReader lines = records(m, d.where, "LINEDEFS", kLinedefRecord, n);
  d.linedefs.resize(n);
  for (size_t i = 0; i < n; ++i) {
    MapLinedef& l = d.linedefs[i];
    l.v1 = lines.u16();
    l.v2 = lines.u16();
    l.flags = lines.u16();
    l.special = lines.u16();
    l.tag = lines.u16();
    const uint16_t front = lines.u16(), back = lines.u16();
    l.front = front == kNoSidedef ? kNoSide : front;
    l.back = back == kNoSidedef ? kNoSide : back;
    for (int v : {l.v1, l.v2})
      if (size_t(v) >= d.vertices.size())
        throw Error(d.where + ": LINEDEFS #" + std::to_string(i) + ": vertex " + std::to_string(v) +
                    " does not exist (VERTEXES has " + std::to_string(d.vertices.size()) + ")");
  }

  ByteReader things = records(m, d.where, "THINGS", kThingRecord, n);
  d.things.resize(n);
  for (MapThing& t : d.things) {
    t.x = s16(things);
    t.y = s16(things);
    t.angle = s16(things);
    t.type = things.u16();
    t.flags = things.u16();
  }
  return d;
}

MapData read_map(const MapLumps& m) {
  if (const Lump* text = m.find("TEXTMAP")) {
    if (!m.find("ENDMAP")) throw Error(m.wad_name + ":" + m.name + ": TEXTMAP without an ENDMAP lump after it");
    MapData d = parse_udmf(std::string_view(reinterpret_cast<const char*>(text->bytes.data()), text->bytes.size()),
                           m.wad_name + ":" + m.name);
    d.name = m.name;
    return d;
  }
  return read_binary_map(m);
}

}  // namespace p3d::wad
