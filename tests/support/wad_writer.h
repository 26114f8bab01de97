// Writing small WADs in tests: a directory of lumps, Doom's binary map records (and
// the same map as UDMF text), pictures in Doom's post format, and a tiny art set.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"

namespace p3d::test {

class WadWriter {
 public:
  explicit WadWriter(bool iwad = false) : iwad_(iwad) {}
  void lump(const std::string& name, std::vector<uint8_t> bytes = {});
  void text_lump(const std::string& name, const std::string& text);
  std::vector<uint8_t> bytes() const;  // header, lumps, directory

 private:
  bool iwad_;
  std::vector<std::pair<std::string, std::vector<uint8_t>>> lumps_;
};

// Doom's binary map records; index fields use 0xFFFF (kNoSide) for "none".
struct TestMap {
  static constexpr int kNoSide = 0xFFFF;
  static constexpr int kBlocking = 1, kTwoSided = 4;  // line flags
  struct Vertex { int x, y; };
  struct Line { int v1, v2, flags = 0, special = 0, tag = 0, front = 0, back = kNoSide; };
  struct Side {
    int x_offset = 0, y_offset = 0;
    std::string upper = "-", lower = "-", middle = "-";
    int sector = 0;
    std::string udmf_fields;  // more of the sidedef's UDMF fields ("offsety_mid = 8;"); the binary format has none
  };
  struct Sector {
    int floor = 0, ceiling = 128;
    std::string floor_flat = "FLOOR", ceiling_flat = "CEIL";
    int light = 160, special = 0, tag = 0;
  };
  struct Thing { int x, y, angle = 0, type = 1, flags = 7; };

  std::vector<Vertex> vertices;
  std::vector<Line> lines;
  std::vector<Side> sides;
  std::vector<Sector> sectors;
  std::vector<Thing> things;

  // A sector bounded by one-sided walls through these points (clockwise seen from
  // above, so the walls face in); returns its index. An edge on an earlier room's
  // one-sided wall opens that wall into this room: two-sided, this room at its back,
  // `wall` as upper and lower textures on both sides.
  int add_room(const std::vector<Vertex>& corners, const Sector& sector, const std::string& wall = "WALL");
  // The line between two points (either way round); throws if there is none.
  Line& line_at(Vertex a, Vertex b);
  int add_vertex(int x, int y);  // reuses an existing vertex at the same place
  int add_side(const Side& side);

  void add_to(WadWriter& wad, const std::string& name) const;  // marker + THINGS ... SECTORS
  std::string udmf() const;                                      // the same map as TEXTMAP text
};

// A picture lump (Doom's post format) of an indexed image with transparency.
std::vector<uint8_t> encode_picture(const wad::IndexedImage& image);

// PLAYPAL, COLORMAP, PNAMES, TEXTURE1 and flats:
//   WALL  64x72 (one patch), a texel's palette index is its row (so rows can be read off a frame)
//   MESH  32x32 with transparent holes (every other column), for masked middles
//   SKY1  256x128
//   SW1TEST and SW2TEST, a switch and its pair
//   FIREWALA, FIREWALB, FIREWALL: Doom's animated fire wall, drawn with WALL, MESH and SKY1's patches
//   FLOOR, CEIL and STEP flats, F_SKY1, and NUKAGE1..3 (solid indices 210, 220, 230)
// Palette index i is rgb(i, 255 - i, 128) and light map m darkens by m/32.
void add_test_art(WadWriter& wad);

// An IWAD of the test art and these maps.
wad::Stack test_stack(const std::vector<std::pair<std::string, TestMap>>& maps);
// The map compiled as MAP01 of such a WAD, as the tools compile WAD maps.
level::Level compile_test_map(const TestMap& map, std::vector<std::string>* warnings = nullptr);

}  // namespace p3d::test
