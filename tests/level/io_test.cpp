#include <gtest/gtest.h>

#include <cmath>

#include "engine/level/format.h"
#include "engine/map/source.h"
#include "engine/level/io.h"
#include "engine/util/bytes.h"
#include "engine/util/checksum.h"
#include "engine/util/file.h"
#include "engine/util/limits.h"
#include "engine/util/rng.h"
#include "tests/support/support.h"

namespace p3d::level {
namespace {

std::string decode_error(const std::vector<uint8_t>& bytes) {
  try {
    decode(bytes, "x.bsp");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Rewrites the header so that a deliberately edited payload passes the checksum.
void reseal(std::vector<uint8_t>& bytes) {
  const std::span<const uint8_t> payload(bytes.data() + format::kHeaderSize, bytes.size() - format::kHeaderSize);
  const uint64_t size = payload.size(), sum = checksum64(payload);
  for (int i = 0; i < 8; ++i) {
    bytes[16 + i] = uint8_t(size >> (8 * i));
    bytes[24 + i] = uint8_t(sum >> (8 * i));
  }
}

class LevelIo : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { level_ = new Level(test::compile(test::random_rooms(300, 3))); }
  static void TearDownTestSuite() { delete level_; }
  static Level* level_;
};
Level* LevelIo::level_ = nullptr;

TEST_F(LevelIo, RoundTripIsExact) {
  const std::vector<uint8_t> bytes = encode(*level_);
  const Level back = decode(bytes, "x.bsp");
  EXPECT_EQ(encode(back), bytes);
  ASSERT_EQ(back.walls.size(), level_->walls.size());
  EXPECT_EQ(back.walls[5].p1, level_->walls[5].p1);
  EXPECT_EQ(back.fragments[7].t1, level_->fragments[7].t1);
  EXPECT_EQ(back.nodes[3].bbox.max, level_->nodes[3].bbox.max);
  EXPECT_EQ(back.textures[1].texels, level_->textures[1].texels);
  EXPECT_EQ(back.leaves[9].sector, level_->leaves[9].sector);
  EXPECT_EQ(back.bounds.min, level_->bounds.min);
}

// A file is written as it is encoded, in pieces, its header patched at the end: the
// same bytes as the encoding made whole in memory.
TEST_F(LevelIo, WrittenFileIsTheEncoding) {
  const Level level = test::compile(test::random_rooms(20000, 5));
  const std::vector<uint8_t> bytes = encode(level);
  ASSERT_GT(bytes.size(), size_t{3} << 20);  // several of the writer's 1 MB pieces
  const std::filesystem::path path = test::temp_dir("level_io") / "x.bsp";
  write(level, path);
  EXPECT_EQ(read_file_bytes(path), bytes);
  EXPECT_EQ(encode(read(path)), bytes);
}

// The compiler never writes what the reader refuses: random levels, and one with every
// value at the limits the parsers allow, round-trip exactly; one value past a limit is
// refused by the compiler, not written.
TEST(LevelRoundTrip, WhatCompilesIsReadBack) {
  std::vector<map::Source> sources;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    sources.push_back(test::random_rooms(150 * seed, seed));
    sources.push_back(test::random_soup(200 * seed, seed));
  }
  map::Source edge = test::random_rooms(100, 7);
  edge.title = std::string(limits::kMaxTitleLength, 't');
  edge.sectors[0].name = std::string(limits::kMaxNameLength, 's');
  edge.textures[0].name = std::string(limits::kMaxNameLength, 'x');
  edge.sectors[1].floor = -geom::kMaxCoord;
  edge.sectors[1].ceiling = geom::kMaxCoord;
  edge.sectors[2].light = 0;
  edge.sectors[3].light = 255;
  for (map::Side* side : {&edge.walls[0].front, &edge.walls[1].front}) {
    side->x_offset = limits::kMaxOffset;
    side->y_offset = -limits::kMaxOffset;
    side->parts = int(edge.part_offsets.size());
    map::PartOffsets& parts = edge.part_offsets.emplace_back();
    for (double& v : parts.x) v = -limits::kMaxOffset;
    for (double& v : parts.y) v = limits::kMaxOffset;
  }
  edge.animations.push_back({{1, 0}, 8, 1});  // as a WAD's animated textures
  map::validate(edge);
  sources.push_back(edge);
  for (const map::Source& src : sources) {
    const std::vector<uint8_t> bytes = encode(test::compile(src));
    std::vector<uint8_t> again;
    ASSERT_NO_THROW(again = encode(decode(bytes, "x.bsp"))) << src.title.substr(0, 40);
    EXPECT_EQ(again, bytes);
  }
  const auto refused = [](void (*edit)(map::Source&)) {
    map::Source s = test::random_rooms(100, 7);
    edit(s);
    try {
      test::compile(s);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(compiled)");
  };
  EXPECT_NE(refused([](map::Source& s) { s.title = std::string(limits::kMaxTitleLength + 1, 't'); }), "(compiled)");
  EXPECT_NE(refused([](map::Source& s) { s.sectors[0].name = std::string(limits::kMaxNameLength + 1, 's'); }), "(compiled)");
  EXPECT_NE(refused([](map::Source& s) { s.textures[0].name = std::string(limits::kMaxNameLength + 1, 'x'); }), "(compiled)");
  EXPECT_NE(refused([](map::Source& s) { s.walls[0].front.x_offset = limits::kMaxOffset * 2; }), "(compiled)");
  EXPECT_NE(refused([](map::Source& s) {
              s.walls[0].front.parts = int(s.part_offsets.size());
              s.part_offsets.push_back({{0, 0, limits::kMaxOffset * 2}, {0, 0, 0}});
            }),
            "(compiled)");
  EXPECT_NE(refused([](map::Source& s) { s.sectors[1].ceiling = geom::kMaxCoord * 2; }), "(compiled)");
}

TEST_F(LevelIo, RejectsDamagedFiles) {
  const std::vector<uint8_t> good = encode(*level_);
  EXPECT_EQ(decode_error({}), "x.bsp: not a compiled level (bad magic; compile maps with mapc)");
  std::vector<uint8_t> text(good);
  text[0] = 'w';
  EXPECT_EQ(decode_error(text), "x.bsp: not a compiled level (bad magic; compile maps with mapc)");

  std::vector<uint8_t> version(good);  // the last format, before leaves held fragments
  version[8] = uint8_t(format::kVersion - 1);
  EXPECT_EQ(decode_error(version), "x.bsp: compiled level version " + std::to_string(format::kVersion - 1) +
                                       " is not supported (expected " + std::to_string(format::kVersion) +
                                       "; recompile with mapc)");

  std::vector<uint8_t> truncated(good.begin(), good.begin() + good.size() / 2);
  EXPECT_NE(decode_error(truncated).find("x.bsp: truncated or padded file"), std::string::npos);
  EXPECT_NE(decode_error(std::vector<uint8_t>(good.begin(), good.begin() + 20)).find("x.bsp: truncated"),
            std::string::npos);

  for (size_t at : {size_t(40), good.size() / 3, good.size() - 1}) {
    std::vector<uint8_t> flipped(good);
    flipped[at] ^= 0x10;
    EXPECT_EQ(decode_error(flipped), "x.bsp: checksum mismatch (the file is corrupted)") << "byte " << at;
  }

  std::vector<uint8_t> padded(good);
  padded.push_back(0);
  reseal(padded);
  EXPECT_EQ(decode_error(padded), "x.bsp: 1 unexpected bytes after the last section");

  std::vector<uint8_t> cut(good.begin(), good.end() - 6);
  reseal(cut);
  EXPECT_NE(decode_error(cut).find("x.bsp: truncated"), std::string::npos) << decode_error(cut);
}

// The first leaf holding fragments.
Leaf& held_leaf(Level& l) { return *std::find_if(l.leaves.begin(), l.leaves.end(), [](const Leaf& x) { return x.fragment_count > 0; }); }

// Edits that keep a valid checksum must still be caught by the structural checks.
TEST_F(LevelIo, RejectsInconsistentStructure) {
  struct Case {
    const char* name;
    void (*edit)(Level&);
    const char* message;
  };
  const Case cases[] = {
      {"child out of range", [](Level& l) { l.nodes[0].child[0] = 100000; }, "x.bsp: section NODE, record 0: node child out of order"},
      {"leaf out of range", [](Level& l) { l.nodes[0].child[0] = leaf_child(100000); }, "x.bsp: section NODE, record 0: leaf index 100000 is out of range"},
      {"fragment wall", [](Level& l) { l.fragments[0].wall = 1u << 30; }, "x.bsp: section FRAG, record 0: fragment wall index 1073741824 is out of range"},
      {"empty fragment", [](Level& l) { l.fragments[0].t1 = l.fragments[0].t0; }, "x.bsp: section FRAG, record 0: fragment with an empty or inverted range"},
      {"sector light", [](Level& l) { l.sectors[1].light = 300; }, "x.bsp: section SECS, record 1: sector light out of range"},
      {"nan height", [](Level& l) { l.sectors[0].floor = std::nan(""); }, "x.bsp: section SECS, record 0: sector floor is not finite"},
      {"bad texture index", [](Level& l) { l.walls[2].sides[0].middle = 77; }, "x.bsp: section WALL, record 2: side texture index 77 is out of range"},
      {"bad part offsets index", [](Level& l) { l.walls[2].sides[1].parts = 0; }, "x.bsp: section WALL, record 2: side part offsets index 0 is out of range"},
      {"part offset range", [](Level& l) { l.walls[2].sides[1].parts = 0, l.part_offsets.emplace_back().y[2] = 1e300; },
       "x.bsp: section PRTS, record 0: side part y offset is out of range"},
      {"two parents", [](Level& l) { l.nodes[0].child[1] = l.nodes[0].child[0]; }, nullptr},
      {"fragment off its line",
       [](Level& l) {
         for (Fragment& f : l.fragments)
           if (!geom::same_line(l.walls[f.wall].line(), l.walls[l.fragments[0].wall].line())) {
             std::swap(f.wall, l.fragments[0].wall);
             std::swap(f.t0, l.fragments[0].t0), std::swap(f.t1, l.fragments[0].t1);
             std::swap(f.cut, l.fragments[0].cut);
             return;
           }
       },
       "is not on its node's splitter"},
      {"coordinate range", [](Level& l) { l.walls[0].p1.x = int64_t(1) << 40; }, "x.bsp: section WALL, record 0: wall coordinate out of range"},
      {"fragment side", [](Level& l) { l.fragments[3].side = 2; }, "x.bsp: section FRAG, record 3: bad fragment side"},
      {"leaf range", [](Level& l) { l.leaves.back().fragment_count = 1u << 30; }, "leaf fragment range out of bounds"},
      {"fragment in a node and a leaf", [](Level& l) { held_leaf(l).first_fragment = l.nodes[0].first_fragment; },
       "belongs to two nodes or leaves"},
      {"fragment in none", [](Level& l) { held_leaf(l).fragment_count = 0; }, "belongs to no node or leaf"},
      {"free line through one point", [](Level& l) { l.free_lines.push_back({{256, 0}, {256, 0}}); },
       "x.bsp: section LINE, record 0: free line through one point"},
      {"free line range", [](Level& l) { l.free_lines.push_back({{0, 0}, {int64_t(1) << 40, 0}}); },
       "x.bsp: section LINE, record 0: free line coordinate out of range"},
      {"splitter line", [](Level& l) { l.nodes[0].splitter = uint32_t(l.walls.size()); },
       "node splitter index"},
  };
  for (const Case& c : cases) {
    Level copy = *level_;
    c.edit(copy);
    const std::string error = decode_error(encode(copy));
    if (c.message && std::string(c.message).rfind("x.bsp: ", 0) == 0)
      EXPECT_EQ(error, c.message) << c.name;
    else if (c.message)
      EXPECT_NE(error.find(c.message), std::string::npos) << c.name << ": " << error;
    else
      EXPECT_NE(error, "(no error)") << c.name;
  }
}

TEST_F(LevelIo, GridRoundTripsAndIsValidated) {
  Level grid = test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"));
  const std::vector<uint8_t> bytes = encode(grid);
  const Level back = decode(bytes, "x.bsp");
  ASSERT_TRUE(back.grid.has_value());
  EXPECT_EQ(back.grid->faces, grid.grid->faces);
  EXPECT_EQ(back.grid->solid, grid.grid->solid);
  // A face pointing at the wrong wall, and a solid tile left without its walls.
  for (size_t i = 0; i < grid.grid->faces.size(); ++i)
    if (grid.grid->faces[i] >= 0) {
      Level copy = grid;
      copy.grid->faces[i] = (copy.grid->faces[i] + 1) % int32_t(copy.walls.size());
      EXPECT_EQ(decode_error(encode(copy)),
                "x.bsp: section GRID, record " + std::to_string(i / 4) + ": grid face wall does not lie along its face");
      break;
    }
  Level copy = grid;
  copy.grid->solid[size_t(copy.grid->rows / 2) * copy.grid->cols + copy.grid->cols / 2] ^= 1;
  const std::string error = decode_error(encode(copy));
  EXPECT_EQ(error.rfind("x.bsp: section GRID, record ", 0), 0u) << error;
  EXPECT_NE(error.find(": grid face wall does not match the tiles"), std::string::npos) << error;
}

TEST_F(LevelIo, CellAtIsTheLeafCellOfThePoint) {
  const geom::BBox box{level_->bounds.min - geom::Vec2(10), level_->bounds.max + geom::Vec2(10)};
  const auto cells = leaf_cells(*level_, box);
  Rng rng(2);
  for (int i = 0; i < 200; ++i) {
    const geom::Vec2 p{rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
    const auto cell = cell_at(*level_, p, box);
    EXPECT_EQ(cell, cells[level_->leaf_at(p)]);
    for (size_t k = 0; k < cell.size(); ++k)  // convex and counter-clockwise: p is left of every edge
      EXPECT_GE(geom::cross(cell[(k + 1) % cell.size()] - cell[k], p - cell[k]), -1e-9);
  }
}

TEST_F(LevelIo, TexturesAreColumnMajor) {
  const uint32_t rows[8] = {1, 2, 3, 4, 5, 6, 7, 8};  // 4 wide, 2 high
  const Texture t = make_texture("t", 4, 2, rows);
  EXPECT_EQ(t.at(0, 0), 1u);
  EXPECT_EQ(t.at(3, 0), 4u);
  EXPECT_EQ(t.at(0, 1), 5u);
  EXPECT_EQ(t.at(5, 3), 6u);  // wraps
  EXPECT_EQ(t.column(2)[1], 7u);
}

// A texture given in columns is the texture given in rows, transposed: texels, indices,
// holes and runs (textures of every shape up to 40 on a side, some with holes).
TEST_F(LevelIo, TexturesFromColumnsMatchTexturesFromRows) {
  Rng rng(5);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 1 + int(rng.below(40)), h = 1 + int(rng.below(40));
    std::vector<uint32_t> rows(size_t(w) * size_t(h)), columns(rows.size());
    std::vector<uint8_t> index_rows(rows.size()), index_columns(rows.size());
    const bool holes = trial % 2;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint32_t c = holes && rng.below(3) == 0 ? 0 : 0xFF000000u | uint32_t(rng.below(1u << 24));
        const uint8_t i = uint8_t(rng.below(256));
        rows[size_t(y) * w + x] = columns[size_t(x) * h + y] = c;
        index_rows[size_t(y) * w + x] = index_columns[size_t(x) * h + y] = i;
      }
    const Texture a = make_texture("t", w, h, rows.data(), index_rows.data());
    const Texture b = make_texture_from_columns("t", w, h, columns, index_columns);
    EXPECT_EQ(a.texels, b.texels);
    EXPECT_EQ(a.texels, columns);
    EXPECT_EQ(a.indices, index_columns);
    EXPECT_EQ(b.indices, index_columns);
    EXPECT_EQ(a.holes, b.holes);
    EXPECT_EQ(a.pow2_width, b.pow2_width);
    EXPECT_EQ(a.pow2_height, b.pow2_height);
    EXPECT_EQ(a.run_start, b.run_start);
    ASSERT_EQ(a.runs.size(), b.runs.size());
    for (size_t r = 0; r < a.runs.size(); ++r) EXPECT_TRUE(a.runs[r].first == b.runs[r].first && a.runs[r].end == b.runs[r].end);
  }
}

// Sides that are not powers of two (Doom's 72-high textures) wrap by modulo, on both signs.
TEST_F(LevelIo, TexturesOfAnySizeWrap) {
  const uint32_t a = 0xFF000000u;  // opaque
  const uint32_t rows[6] = {a | 1, a | 2, a | 3, a | 4, a | 5, a | 6};  // 3 wide, 2 high
  const Texture t = make_texture("t", 3, 2, rows);
  EXPECT_FALSE(t.pow2_width);
  EXPECT_TRUE(t.pow2_height);
  for (int64_t u : {-7, -4, -1, 0, 2, 3, 5, 3000001})
    for (int64_t v : {-3, -1, 0, 1, 2, 5})
      EXPECT_EQ(t.at(u, v), rows[floor_mod(v, 2) * 3 + floor_mod(u, 3)]) << u << "," << v;
  EXPECT_FALSE(t.holes);
  const uint32_t holes[2] = {0xFF0000FFu, 0x00000000u};
  EXPECT_TRUE(make_texture("h", 1, 2, holes).holes);
}

// A texture with holes lists each column's runs of opaque texels (Doom's posts): every
// opaque texel in exactly one run, runs in order, separated by transparent texels.
// Columns up to 300 tall, in stretches of up to 80 texels: runs across the 64-row words
// the runs are found by; any alpha but 0 is opaque.
TEST_F(LevelIo, TexturesWithHolesListTheirOpaqueRuns) {
  Rng rng(17);
  for (int trial = 0; trial < 100; ++trial) {
    const int w = 1 + int(rng.below(9)), h = 1 + int(rng.below(trial < 50 ? 40 : 300));
    std::vector<uint32_t> columns(size_t(w) * size_t(h)), rows(columns.size());
    const uint64_t stretch = trial < 50 ? 1 : 80;
    for (size_t i = 0; i < columns.size();) {
      const bool opaque = rng.below(3) != 0;
      for (uint64_t n = 1 + rng.below(stretch); n > 0 && i < columns.size(); --n, ++i)
        columns[i] = opaque ? uint32_t(1 + rng.below(255)) << 24 | uint32_t(rng.below(256)) : 0;
    }
    for (int u = 0; u < w; ++u)
      for (int v = 0; v < h; ++v) rows[size_t(v) * size_t(w) + size_t(u)] = columns[size_t(u) * size_t(h) + size_t(v)];
    rows[0] = 0;  // some texel is transparent
    const Texture t = make_texture("t", w, h, rows.data());
    ASSERT_TRUE(t.holes);
    ASSERT_EQ(t.run_start.size(), size_t(w) + 1);
    EXPECT_EQ(t.run_start.back(), t.runs.size());
    for (int u = 0; u < w; ++u) {
      std::vector<bool> covered(size_t(h), false);
      int previous_end = -1;
      for (uint32_t r = t.run_start[size_t(u)]; r < t.run_start[size_t(u) + 1]; ++r) {
        const Texture::Run run = t.runs[r];
        ASSERT_LT(run.first, run.end);
        ASSERT_LE(run.end, h);
        EXPECT_GT(int(run.first), previous_end) << "runs apart and in order";
        previous_end = run.end;
        for (int v = run.first; v < run.end; ++v) covered[size_t(v)] = true;
      }
      for (int v = 0; v < h; ++v) EXPECT_EQ(covered[size_t(v)], (t.at(u, v) >> 24) != 0) << trial << ": " << u << "," << v;
    }
  }
  const uint32_t opaque[2] = {0xFF000001u, 0xFF000002u};
  EXPECT_TRUE(make_texture("o", 1, 2, opaque).runs.empty()) << "no holes, no runs: drawn whole";
}

// A paletted level (WAD art) stores palette indices and opacity, and reads back exactly;
// Doom's line, sector and thing data survive; a ceiling below its floor is Doom's and is kept.
TEST_F(LevelIo, PalettedLevelsAndDoomDataRoundTrip) {
  Level l = *level_;
  l.palette.resize(limits::kPaletteSize);
  for (int i = 0; i < limits::kPaletteSize; ++i) l.palette[size_t(i)] = image::rgba(i, 255 - i, i / 2);
  l.light_maps.resize(size_t(limits::kStoredMaps) * limits::kPaletteSize);
  for (size_t i = 0; i < l.light_maps.size(); ++i) l.light_maps[i] = l.palette[(i * 7) % limits::kPaletteSize];
  for (Texture& t : l.textures) {
    std::vector<uint32_t> rgba(size_t(t.width) * t.height);
    std::vector<uint8_t> idx(rgba.size());
    for (size_t p = 0; p < rgba.size(); ++p) {
      idx[p] = uint8_t(p * 31 % 256);
      rgba[p] = p % 5 == 0 ? 0u : l.palette[idx[p]];  // every fifth texel transparent
    }
    t = make_texture(t.name, t.width, t.height, rgba.data(), idx.data());
  }
  l.walls[3].source = 4711;
  l.walls[3].special = 1;
  l.walls[3].tag = 7;
  l.walls[3].flags |= kImpassable | kSecret;
  l.walls[3].sides[0].parts = int32_t(l.part_offsets.size());
  l.part_offsets.emplace_back().x[kUpperPart] = 8;
  l.walls[3].sides[0].light = 200;
  l.sectors[2].special = 9;
  l.sectors[2].tag = 7;
  l.sectors[2].ceiling = l.sectors[2].floor - 1;
  l.things.push_back({2001, {10, 20}, 90, 16, kNone, 0});
  const std::vector<uint8_t> bytes = encode(l);
  const Level back = decode(bytes, "x.bsp");
  EXPECT_EQ(encode(back), bytes);
  EXPECT_TRUE(back.paletted());
  EXPECT_EQ(back.light_maps, l.light_maps);
  for (size_t i = 0; i < l.textures.size(); ++i) {
    EXPECT_EQ(back.textures[i].indices, l.textures[i].indices);
    EXPECT_EQ(back.textures[i].texels, l.textures[i].texels);
  }
  EXPECT_EQ(back.walls[3].source, 4711);
  EXPECT_EQ(back.walls[3].tag, 7);
  EXPECT_EQ(back.walls[3].flags, l.walls[3].flags);
  EXPECT_EQ(back.part_x(back.walls[3].sides[0], kUpperPart), 8);
  EXPECT_EQ(back.walls[3].sides[0].light, 200);
  EXPECT_EQ(back.sectors[2].ceiling, l.sectors[2].ceiling);
  EXPECT_EQ(back.sectors[2].special, 9);
  EXPECT_EQ(back.things.back().flags, 16u);
}

// A texture kept without colours (a level only written: indices and opacity bytes)
// writes the bytes its coloured twin writes, at sizes whose texels are not a multiple
// of the sixteen the opacity bits are packed by, with holes and without.
TEST_F(LevelIo, ATextureWithoutColoursWritesItsTwinsBytes) {
  Level coloured = *level_;
  coloured.palette.resize(limits::kPaletteSize);
  for (int i = 0; i < limits::kPaletteSize; ++i) coloured.palette[size_t(i)] = image::rgba(i, 255 - i, i / 2);
  coloured.light_maps.assign(size_t(limits::kStoredMaps) * limits::kPaletteSize, coloured.palette[0]);
  Level uncoloured = coloured;
  coloured.textures.clear();
  uncoloured.textures.clear();
  const std::pair<int, int> sizes[] = {{1, 1}, {3, 5}, {17, 3}, {16, 1}, {33, 7}, {64, 64}, {5, 13}};
  for (const bool holes : {true, false})
    for (const auto& [w, h] : sizes) {
      const size_t n = size_t(w) * size_t(h);
      std::vector<uint32_t> texels(n);
      std::vector<uint8_t> indices(n), opaque(n);
      for (size_t p = 0; p < n; ++p) {
        indices[p] = uint8_t(p * 31 % 256);
        opaque[p] = holes && (p * 7 % 5 == 0) ? 0 : 1;
        texels[p] = opaque[p] ? coloured.palette[indices[p]] : 0u;
      }
      coloured.textures.push_back(make_texture_from_columns("t", w, h, texels, indices));
      uncoloured.textures.push_back(make_texture_without_colours("t", w, h, indices, opaque));
      EXPECT_EQ(uncoloured.textures.back().holes, coloured.textures.back().holes) << w << "x" << h;
    }
  EXPECT_EQ(encode(uncoloured), encode(coloured));
}

}  // namespace
}  // namespace p3d::level
