#include "tests/support/wad_writer.h"

#include <algorithm>
#include <stdexcept>

#include "engine/bsp/load.h"
#include "engine/util/bytes.h"
#include "engine/wad/write.h"

namespace p3d::test {

namespace {

void name8(ByteWriter& out, const std::string& name) {
  for (size_t i = 0; i < 8; ++i) out.u8(i < name.size() ? uint8_t(name[i]) : 0);
}

void i16(ByteWriter& out, int v) { out.u16(uint16_t(int16_t(v))); }

}  // namespace

void WadWriter::lump(const std::string& name, std::vector<uint8_t> bytes) { lumps_.push_back({name, std::move(bytes)}); }

void WadWriter::text_lump(const std::string& name, const std::string& text) {
  lump(name, std::vector<uint8_t>(text.begin(), text.end()));
}

std::vector<uint8_t> WadWriter::bytes() const {
  std::vector<wad::LumpToWrite> lumps;
  for (const auto& [name, data] : lumps_) lumps.push_back({name, data});
  return wad::write_wad(iwad_, lumps);
}

int TestMap::add_vertex(int x, int y) {
  for (size_t i = 0; i < vertices.size(); ++i)
    if (vertices[i].x == x && vertices[i].y == y) return int(i);
  vertices.push_back({x, y});
  return int(vertices.size()) - 1;
}

int TestMap::add_side(const Side& side) {
  sides.push_back(side);
  return int(sides.size()) - 1;
}

int TestMap::add_room(const std::vector<Vertex>& corners, const Sector& sector, const std::string& wall) {
  sectors.push_back(sector);
  const int s = int(sectors.size()) - 1;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vertex a = corners[i], b = corners[(i + 1) % corners.size()];
    const int v1 = add_vertex(a.x, a.y), v2 = add_vertex(b.x, b.y);
    const auto shared = std::find_if(lines.begin(), lines.end(), [&](const Line& l) { return l.v1 == v2 && l.v2 == v1; });
    if (shared != lines.end() && shared->back == kNoSide) {  // an earlier room's wall: open it into this room
      Side& front = sides[size_t(shared->front)];
      front.upper = front.lower = wall;
      front.middle = "-";
      Side back;
      back.upper = back.lower = wall;
      back.sector = s;
      shared->back = add_side(back);
      shared->flags = kTwoSided;
      continue;
    }
    Side side;
    side.middle = wall;
    side.sector = s;
    lines.push_back({v1, v2, kBlocking, 0, 0, add_side(side), kNoSide});
  }
  return s;
}

TestMap::Line& TestMap::line_at(Vertex a, Vertex b) {
  for (Line& l : lines) {
    const Vertex p = vertices[size_t(l.v1)], q = vertices[size_t(l.v2)];
    if ((p.x == a.x && p.y == a.y && q.x == b.x && q.y == b.y) || (p.x == b.x && p.y == b.y && q.x == a.x && q.y == a.y))
      return l;
  }
  throw std::logic_error("no line between these points");
}

void TestMap::add_to(WadWriter& wad, const std::string& name) const {
  wad.lump(name);
  ByteWriter things_out, lines_out, sides_out, vertices_out, sectors_out;
  for (const Thing& t : things) {
    i16(things_out, t.x), i16(things_out, t.y), i16(things_out, t.angle);
    things_out.u16(uint16_t(t.type)), things_out.u16(uint16_t(t.flags));
  }
  for (const Line& l : lines) {
    lines_out.u16(uint16_t(l.v1)), lines_out.u16(uint16_t(l.v2)), lines_out.u16(uint16_t(l.flags));
    lines_out.u16(uint16_t(l.special)), lines_out.u16(uint16_t(l.tag));
    lines_out.u16(uint16_t(l.front)), lines_out.u16(uint16_t(l.back));
  }
  for (const Side& s : sides) {
    i16(sides_out, s.x_offset), i16(sides_out, s.y_offset);
    name8(sides_out, s.upper), name8(sides_out, s.lower), name8(sides_out, s.middle);
    sides_out.u16(uint16_t(s.sector));
  }
  for (const Vertex& v : vertices) i16(vertices_out, v.x), i16(vertices_out, v.y);
  for (const Sector& s : sectors) {
    i16(sectors_out, s.floor), i16(sectors_out, s.ceiling);
    name8(sectors_out, s.floor_flat), name8(sectors_out, s.ceiling_flat);
    i16(sectors_out, s.light), i16(sectors_out, s.special), i16(sectors_out, s.tag);
  }
  wad.lump("THINGS", things_out.release());
  wad.lump("LINEDEFS", lines_out.release());
  wad.lump("SIDEDEFS", sides_out.release());
  wad.lump("VERTEXES", vertices_out.release());
  wad.lump("SEGS");
  wad.lump("SSECTORS");
  wad.lump("NODES");
  wad.lump("SECTORS", sectors_out.release());
  wad.lump("REJECT");
  wad.lump("BLOCKMAP");
}

std::string TestMap::udmf() const {
  std::string t = "// written by the tests\nnamespace = \"doom\";\n";
  for (const Vertex& v : vertices) t += "vertex { x = " + std::to_string(v.x) + ".0; y = " + std::to_string(v.y) + ".0; }\n";
  for (const Line& l : lines) {
    t += "linedef\n{\n  v1 = " + std::to_string(l.v1) + ";\n  v2 = " + std::to_string(l.v2) +
         ";\n  sidefront = " + std::to_string(l.front) + ";\n";
    if (l.back != kNoSide) t += "  sideback = " + std::to_string(l.back) + ";\n  twosided = true;\n";
    if (l.flags & 1) t += "  blocking = true;\n";
    if (l.flags & 8) t += "  dontpegtop = true;\n";
    if (l.flags & 16) t += "  dontpegbottom = true;\n";
    if (l.special) t += "  special = " + std::to_string(l.special) + ";\n";
    if (l.tag) t += "  id = " + std::to_string(l.tag) + ";\n";
    t += "}\n";
  }
  for (const Side& s : sides)
    t += "sidedef { sector = " + std::to_string(s.sector) + "; texturetop = \"" + s.upper + "\"; texturebottom = \"" +
         s.lower + "\"; texturemiddle = \"" + s.middle + "\"; offsetx = " + std::to_string(s.x_offset) +
         "; offsety = " + std::to_string(s.y_offset) + "; " + s.udmf_fields + " }\n";
  for (const Sector& s : sectors)
    t += "sector { heightfloor = " + std::to_string(s.floor) + "; heightceiling = " + std::to_string(s.ceiling) +
         "; texturefloor = \"" + s.floor_flat + "\"; textureceiling = \"" + s.ceiling_flat +
         "\"; lightlevel = " + std::to_string(s.light) + "; /* a comment */ }\n";
  for (const Thing& th : things) {
    t += "thing { x = " + std::to_string(th.x) + ".0; y = " + std::to_string(th.y) + ".0; angle = " +
         std::to_string(th.angle) + "; type = " + std::to_string(th.type) + "; single = true;";
    if (th.flags & 1) t += " skill1 = true; skill2 = true;";
    if (th.flags & 2) t += " skill3 = true;";
    if (th.flags & 4) t += " skill4 = true; skill5 = true;";
    t += " }\n";
  }
  return t;
}

std::vector<uint8_t> encode_picture(const wad::IndexedImage& img) {
  ByteWriter out;
  i16(out, img.width), i16(out, img.height), i16(out, img.left_offset), i16(out, img.top_offset);
  const size_t table = out.size();
  for (int x = 0; x < img.width; ++x) out.u32(0);
  std::vector<uint32_t> offsets;
  for (int x = 0; x < img.width; ++x) {
    offsets.push_back(uint32_t(out.size()));
    for (int y = 0; y < img.height;) {
      if (!img.opaque[img.at(x, y)]) {
        ++y;
        continue;
      }
      int end = y;
      while (end < img.height && end - y < 128 && img.opaque[img.at(x, end)]) ++end;
      out.u8(uint8_t(y)), out.u8(uint8_t(end - y)), out.u8(0);
      for (int k = y; k < end; ++k) out.u8(img.indices[img.at(x, k)]);
      out.u8(0);
      y = end;
    }
    out.u8(0xFF);
  }
  std::vector<uint8_t> bytes = out.release();
  for (int x = 0; x < img.width; ++x)
    for (int b = 0; b < 4; ++b) bytes[table + 4 * size_t(x) + b] = uint8_t(offsets[size_t(x)] >> (8 * b));
  return bytes;
}

void add_test_art(WadWriter& wad) {
  ByteWriter palette;
  for (int i = 0; i < 256; ++i) palette.u8(uint8_t(i)), palette.u8(uint8_t(255 - i)), palette.u8(128);
  wad.lump("PLAYPAL", palette.release());
  // Light map m maps index i to index i * (32 - m) / 32: darker and darker.
  ByteWriter colormap;
  for (int m = 0; m < 34; ++m)
    for (int i = 0; i < 256; ++i) colormap.u8(uint8_t(m < 32 ? i * (32 - m) / 32 : 0));
  wad.lump("COLORMAP", colormap.release());

  wad::IndexedImage wall(64, 72), mesh(32, 32), sky(256, 128);
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 64; ++x) wall.indices[wall.at(x, y)] = uint8_t(y + 100), wall.opaque[wall.at(x, y)] = 1;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) mesh.indices[mesh.at(x, y)] = 40, mesh.opaque[mesh.at(x, y)] = x % 2;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x) sky.indices[sky.at(x, y)] = uint8_t(x), sky.opaque[sky.at(x, y)] = 1;
  wad.lump("P_START");
  wad.lump("WALLP", encode_picture(wall));
  wad.lump("MESHP", encode_picture(mesh));
  wad.lump("SKYP", encode_picture(sky));
  wad.lump("P_END");

  ByteWriter pnames;
  pnames.u32(3);
  name8(pnames, "WALLP"), name8(pnames, "MESHP"), name8(pnames, "SKYP");
  wad.lump("PNAMES", pnames.release());

  struct Def {
    const char* name;
    int w, h, patch;
  };
  const Def defs[] = {{"WALL", 64, 72, 0}, {"MESH", 32, 32, 1}, {"SKY1", 256, 128, 2},
                      {"SW1TEST", 64, 72, 0}, {"SW2TEST", 64, 72, 2},
                      // Doom's animated fire wall (FIREWALA to FIREWALL in definition order)
                      {"FIREWALA", 64, 72, 0}, {"FIREWALB", 32, 32, 1}, {"FIREWALL", 256, 128, 2}};
  constexpr int kDefs = int(std::size(defs));
  ByteWriter textures;
  textures.u32(kDefs);
  const size_t table = textures.size();
  for (int i = 0; i < kDefs; ++i) textures.u32(0);
  std::vector<uint32_t> offsets;
  for (const Def& d : defs) {
    offsets.push_back(uint32_t(textures.size()));
    name8(textures, d.name);
    textures.u32(0);
    i16(textures, d.w), i16(textures, d.h);
    textures.u32(0);
    i16(textures, 1);
    i16(textures, 0), i16(textures, 0), i16(textures, d.patch), i16(textures, 1), i16(textures, 0);
  }
  std::vector<uint8_t> tex = textures.release();
  for (size_t i = 0; i < offsets.size(); ++i)
    for (int b = 0; b < 4; ++b) tex[table + 4 * i + b] = uint8_t(offsets[i] >> (8 * b));
  wad.lump("TEXTURE1", tex);

  wad.lump("F_START");
  for (const char* flat : {"FLOOR", "CEIL", "F_SKY1", "STEP"}) {
    std::vector<uint8_t> pixels(64 * 64);
    for (size_t p = 0; p < pixels.size(); ++p) pixels[p] = uint8_t(flat[0] == 'F' ? 20 + p % 8 : 60 + p % 8);
    wad.lump(flat, pixels);
  }
  for (int frame = 1; frame <= 3; ++frame)  // Doom's animated nukage: one colour a frame
    wad.lump("NUKAGE" + std::to_string(frame), std::vector<uint8_t>(64 * 64, uint8_t(200 + 10 * frame)));
  wad.lump("F_END");
}

wad::Stack test_stack(const std::vector<std::pair<std::string, TestMap>>& maps) {
  WadWriter w(true);
  add_test_art(w);
  for (const auto& [name, map] : maps) map.add_to(w, name);
  wad::Stack stack;
  stack.add(wad::Wad(w.bytes(), "test.wad"));
  return stack;
}

level::Level compile_test_map(const TestMap& map, std::vector<std::string>* warnings) {
  return bsp::build_wad_map(test_stack({{"MAP01", map}}), "MAP01", {}, warnings);
}

}  // namespace p3d::test
