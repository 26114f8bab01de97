#include <gtest/gtest.h>

#include <bit>
#include <charconv>

#include "engine/map/source.h"
#include "engine/map/statement.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d::map {
namespace {

// A small valid map: one square room with a pillar-less two-sided window into a
// second room, and a plain segment.
const char* kRoomHeader = R"(title Test room
texture wall wall.png
texture flat flat.png
sector a floor=0 ceiling=128 light=160 floor_tex=flat ceiling_tex=flat
sector b floor=16 ceiling=96 light=200 floor_tex=flat ceiling_tex=flat
vertex v0 0 0
vertex v1 0 256
vertex v2 256 256
vertex v3 256 0
vertex v4 512 256
vertex v5 512 0
vertex s0 64 64
vertex s1 96 96
)";
const char* kRoomWalls = R"(wall v0 v1 front=a middle=wall
wall v1 v2 front=a middle=wall
wall v2 v3 front=a back=b upper=wall lower=wall
wall v3 v0 front=a middle=wall
wall v2 v4 front=b middle=wall
wall v4 v5 front=b middle=wall
wall v5 v3 front=b middle=wall
segment s0 s1 texture=wall
player 32 32 45
)";

class ParseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("parse");
    image::save_png(image::Image(64, 64, image::rgba(200, 0, 0)), dir_ / "wall.png");
    image::save_png(image::Image(32, 32, image::rgba(0, 200, 0)), dir_ / "flat.png");
    image::save_png(image::Image(48, 72), dir_ / "odd.png");
    image::save_png(image::Image(limits::kMaxTextureSize + 1, 1), dir_ / "wide.png");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Source load(const std::string& text) {
    write_file_atomically(dir_ / "test.map", text);
    return load_map(dir_ / "test.map");
  }
  // The error message of loading `text`, with the temp directory replaced by "DIR".
  std::string error(const std::string& text) {
    try {
      load(text);
    } catch (const Error& e) {
      std::string m = e.what();
      const std::string d = dir_.string();
      for (size_t at; (at = m.find(d)) != std::string::npos;) m.replace(at, d.size(), "DIR");
      return m;
    }
    return "(no error)";
  }
  std::filesystem::path dir_;
};

TEST_F(ParseTest, ValidMap) {
  const Source s = load(std::string(kRoomHeader) + kRoomWalls + "thing 2001 100 100 90\n");
  EXPECT_EQ(s.title, "Test room");
  EXPECT_EQ(s.walls.size(), 8u);
  EXPECT_EQ(s.sectors.size(), 2u);
  EXPECT_TRUE(s.walls[2].two_sided());
  EXPECT_EQ(s.walls[2].back.upper, s.walls[2].front.upper);  // back textures default to the front's
  EXPECT_TRUE(s.walls[7].segment);
  EXPECT_EQ(s.player.pos, geom::Vec2(32, 32));
  EXPECT_EQ(s.things.size(), 1u);
  EXPECT_EQ(s.walls[0].loc.line, 14);
  EXPECT_EQ(s.textures[0].image.width, 64);
}

// Doom's textures are 72 or 96 high, and two-sided walls may show a masked middle texture.
TEST_F(ParseTest, TexturesOfAnySizeAndMaskedMiddles) {
  std::string text = std::string(kRoomHeader) + "texture odd odd.png\n" + kRoomWalls;
  const std::string window = "wall v2 v3 front=a back=b upper=wall lower=wall\n";
  text.replace(text.find(window), window.size(), "wall v2 v3 front=a back=b upper=wall lower=wall middle=odd back_middle=odd\n");
  const Source s = load(text);
  const Texture& odd = s.textures[size_t(s.walls[2].front.middle)];
  EXPECT_EQ(odd.image.width, 48);
  EXPECT_EQ(odd.image.height, 72);
  EXPECT_EQ(s.walls[2].back.middle, s.walls[2].front.middle);
}

TEST_F(ParseTest, SegmentsOnlyGetADefaultSector) {
  const Source s = load("texture wall wall.png\nvertex a 0 0\nvertex b 10 0\nsegment a b texture=wall\nplayer 5 5 0\n");
  ASSERT_NE(s.default_sector, kNone);
  EXPECT_EQ(s.sectors.size(), 1u);
}

// Windows editors write a byte order mark and CRLF; old Macs wrote CR alone. Lines are
// counted alike in all three.
TEST_F(ParseTest, LineEndsOfEverySystemAndAByteOrderMark) {
  const std::string lf = std::string(kRoomHeader) + kRoomWalls;
  std::string crlf, cr;
  for (char c : lf) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  for (const std::string& text : {lf, "\xEF\xBB\xBF" + crlf, cr}) {
    const Source s = load(text);
    EXPECT_EQ(s.title, "Test room");
    EXPECT_EQ(s.walls.size(), 8u);
    EXPECT_EQ(s.walls[0].loc.line, 14);
  }
  EXPECT_EQ(error("vertex a 0 0\rvertex a 1 1\r"), "DIR/test.map:2: vertex 'a' is defined twice");
}

// A map reads pictures only from its own directory unless told otherwise, and a refusal
// does not tell whether the file outside exists.
TEST_F(ParseTest, PicturesStayInTheMapsDirectory) {
  const std::string walls = std::string(kRoomWalls);
  std::filesystem::create_directories(dir_ / "sub");
  image::save_png(image::Image(8, 8), dir_ / "sub/pic.png");
  EXPECT_EQ(load(std::string(kRoomHeader) + "texture b ./sub/../sub/pic.png\n" + walls).textures.size(), 3u);
  for (const std::string& file : {dir_.string() + "/wall.png", std::string("../x/wall.png"), std::string("sub/../../y.png"),
                                  std::string("/etc/passwd"), std::string("/nonexistent/q.png")}) {
    const std::string message = error("texture a " + file + "\n");
    EXPECT_NE(message.find("DIR/test.map:1: texture file '"), std::string::npos) << message;
    EXPECT_NE(message.find("' lies outside the map's directory"), std::string::npos) << message;
    EXPECT_EQ(error("sprite 1 " + file + "\n").find("DIR/test.map:1: sprite file '"), 0u) << file;
  }
  // Allowed explicitly: a sibling directory's picture.
  const std::filesystem::path sibling = test::temp_dir("parse-sibling");
  image::save_png(image::Image(8, 8), sibling / "pic.png");
  write_file_atomically(dir_ / "test.map", std::string(kRoomHeader) + "texture b ../" + sibling.filename().string() +
                                               "/pic.png\n" + walls);
  EXPECT_THROW(load_map(dir_ / "test.map"), Error);
  EXPECT_EQ(load_map(dir_ / "test.map", {.textures_anywhere = true}).textures.size(), 3u);
  std::filesystem::remove_all(sibling);
}

// A bare file name found nowhere beside the map comes from the bundled textures, as a
// PWAD takes the IWAD's art; one beside the map wins, and paths with folders never fall back.
TEST_F(ParseTest, BareNamesFallBackOnTheBundledTextures) {
  const std::filesystem::path bundled = test::temp_dir("parse-bundled");
  image::save_png(image::Image(8, 4), bundled / "lib.png");
  image::save_png(image::Image(2, 2), bundled / "wall.png");
  write_file_atomically(dir_ / "test.map", std::string(kRoomHeader) + "texture b lib.png\n" + kRoomWalls);
  EXPECT_THROW(load_map(dir_ / "test.map"), Error);  // no fallback without a bundled directory
  const LoadOptions options{.bundled_textures = bundled};
  const Source s = load_map(dir_ / "test.map", options);
  EXPECT_EQ(s.textures.back().image.width, 8);
  EXPECT_EQ(s.textures[0].image.width, 64);  // wall.png beside the map, not the bundled one
  std::filesystem::create_directories(dir_ / "sub");
  write_file_atomically(dir_ / "test.map", std::string(kRoomHeader) + "texture b sub/lib.png\n" + kRoomWalls);
  EXPECT_THROW(load_map(dir_ / "test.map", options), Error);
  std::filesystem::remove_all(bundled);
}

TEST_F(ParseTest, CommentsAndFractionsAndTabs) {
  const Source s = load("# heading\ntexture wall wall.png # trailing\nvertex a\t0.5 -0.25\nvertex b 10 0\n\n"
                        "segment a b texture=wall\nplayer 5 5 0\n");
  EXPECT_EQ(s.vertices[0].pos.x, 128);
  EXPECT_EQ(s.vertices[0].pos.y, -64);
}

struct BadCase {
  const char* name;
  std::string text;
  std::string message;
};

TEST_F(ParseTest, BadInputGivesLocatedMessages) {
  const std::string base = kRoomHeader;
  const std::string walls = kRoomWalls;
  const std::vector<BadCase> cases = {
      {"unknown statement", base + "floorplan 3\n" + walls, "DIR/test.map:14: unknown statement 'floorplan'"},
      {"missing vertex", base + "wall v0 v9 front=a middle=wall\n" + walls, "DIR/test.map:14: unknown vertex 'v9'"},
      {"unknown sector", base + "wall v0 v5 front=c middle=wall\n" + walls, "DIR/test.map:14: unknown sector 'c'"},
      {"dangling sector", base + "sector lonely floor=0 ceiling=64 floor_tex=flat ceiling_tex=flat\n" + walls,
       "DIR/test.map:14: sector 'lonely' is not bounded by any wall"},
      {"open sector", base + std::string(walls).replace(walls.find("wall v3 v0"), 31, ""),
       "DIR/test.map:4: sector 'a' is not closed: its boundary has an open end at (0.000000, 0.000000)"},
      {"crossing walls", base + walls + "vertex x0 -10 128\nvertex x1 100 128\nsegment x0 x1 texture=wall\n",
       "DIR/test.map:25: wall crosses the wall at DIR/test.map:14"},
      {"overlapping walls", base + walls + "vertex x0 0 10\nvertex x1 0 20\nsegment x0 x1 texture=wall\n",
       "DIR/test.map:25: wall overlaps the collinear wall at DIR/test.map:14"},
      {"zero-length wall", base + "vertex z 0 0\nsegment v0 z texture=wall\n" + walls,
       "DIR/test.map:15: zero-length wall: both ends are at the same point"},
      {"not a number", base + "vertex q 1x 0\n" + walls, "DIR/test.map:14: x coordinate '1x' is not a number"},
      {"nan", base + "vertex q nan 0\n" + walls, "DIR/test.map:14: x coordinate 'nan' is not finite"},
      {"infinity", base + "vertex q 0 inf\n" + walls, "DIR/test.map:14: y coordinate 'inf' is not finite"},
      {"huge", base + "vertex q 1e999 0\n" + walls, "DIR/test.map:14: x coordinate '1e999' is out of range"},
      {"out of range", base + "vertex q 3000000 0\n" + walls, "DIR/test.map:14: x coordinate '3000000' is outside +-2097152"},
      {"missing texture file", "texture wall nowhere.png\n", "DIR/test.map:1: texture file 'DIR/nowhere.png' does not exist"},
      {"bad texture size", "texture wide wide.png\n",
       "DIR/test.map:1: texture 'wide' is 4097x1: sides must be at most 4096"},
      {"unknown texture", base + "segment v0 v4 texture=nope\n" + walls, "DIR/test.map:14: unknown texture 'nope'"},
      {"unknown option", base + "wall v0 v5 front=a middle=wall colour=red\n" + walls,
       "DIR/test.map:14: wall: unknown option 'colour'"},
      {"a hundred options", base + "wall v0 v5" + [] {
         std::string options;
         for (int i = 0; i < 100; ++i) options += " k" + std::to_string(i) + "=1";
         return options;
       }() + "\n" + walls,
       "DIR/test.map:14: more than 64 key=value options"},
      {"unknown options, first by name", base + "wall v0 v5 zebra=1 front=a middle=wall colour=red\n" + walls,
       "DIR/test.map:14: wall: unknown option 'colour'"},
      {"missing option", base + "sector c floor=0 ceiling=1 floor_tex=flat\n" + walls,
       "DIR/test.map:14: sector: missing option ceiling_tex="},
      {"repeated option", base + "segment v0 v4 texture=wall texture=wall\n" + walls,
       "DIR/test.map:14: option 'texture' given twice"},
      {"ceiling below floor", base + "sector c floor=10 ceiling=5 floor_tex=flat ceiling_tex=flat\n" + walls,
       "DIR/test.map:14: ceiling is below the floor"},
      {"light range", base + "sector c floor=0 ceiling=5 light=300 floor_tex=flat ceiling_tex=flat\n" + walls,
       "DIR/test.map:14: light '300' must be an integer from 0 to 255"},
      {"duplicate vertex", base + "vertex v0 5 5\n" + walls, "DIR/test.map:14: vertex 'v0' is defined twice"},
      {"no player", base + "wall v0 v1 front=a middle=wall\n", "DIR/test.map: no player start (add 'player X Y ANGLE')"},
      {"two players", base + walls + "player 1 1 0\n", "DIR/test.map:23: player start is defined twice"},
      {"one-sided without texture", base + "wall v0 v5 front=a\n" + walls,
       "DIR/test.map:14: one-sided wall needs a middle= texture"},
      {"missing upper texture",
       base + std::string(walls).replace(walls.find("upper=wall "), 11, ""),
       "DIR/test.map:16: wall needs an upper texture on its front side (sector 'b' has a lower ceiling than 'a')"},
      {"sky without sky", base + "sector c floor=0 ceiling=64 floor_tex=flat ceiling_tex=sky\n" + walls,
       "DIR/test.map:14: ceiling_tex=sky needs a 'sky TEXTURE' statement before it"},
      {"binary junk", std::string("vertex a 0 0\n\x01\x02\0\x03\n", 18), "DIR/test.map:2: binary data in a text map"},
      {"empty", "", "DIR/test.map: no player start (add 'player X Y ANGLE')"},
      // Unprintable bytes are escaped in messages, never echoed raw to a terminal.
      {"escape sequence", "vertex a 0 0\nwa\x1b[2Jll a\n", "DIR/test.map:2: unknown statement 'wa\\x1B[2Jll'"},
      {"byte order mark inside", "vertex a 0 0\n\xEF\xBB\xBFwall\n", "DIR/test.map:2: unknown statement '<BOM>wall'"},
      {"delete byte", "\x7fvertex a 0 0\n", "DIR/test.map:1: unknown statement '\\x7Fvertex'"},
  };
  for (const BadCase& c : cases) EXPECT_EQ(error(c.text), c.message) << c.name;
}

const char* kGrid = R"(title Little grid
cell 32
texture wall wall.png
texture flat flat.png
floor 0 flat
ceiling 64 flat
tile W wall
map
WWWWW
W>..W
W.W.W
W...W
WWWWW
end
)";

TEST_F(ParseTest, GridBecomesMergedWallsAndFaces) {
  write_file_atomically(dir_ / "g.grid", kGrid);
  const Source s = load_source(dir_ / "g.grid");
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_EQ(s.grid->cols, 5);
  EXPECT_EQ(s.grid->rows, 5);
  EXPECT_EQ(s.player.pos, geom::Vec2(48, 112));  // tile (1, 3) from the south-west, facing east
  EXPECT_EQ(s.player.angle, 0);
  // The ring of empty tiles around the pillar: 4 outer runs of 3 tiles, 4 pillar faces.
  EXPECT_EQ(s.walls.size(), 8u);
  // Each empty tile's face towards a solid tile names a wall lying along it.
  int faces = 0;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c)
      for (int f = 0; f < 4; ++f) {
        const int32_t w = s.grid->faces[(size_t(r) * 5 + c) * 4 + f];
        faces += w != kNone;
        if (w != kNone) {
          EXPECT_FALSE(s.grid->solid[size_t(r) * 5 + c]);
        }
      }
  EXPECT_EQ(faces, 16);
}

// A level with more walls than limits::kMaxWalls is refused with a message, before its
// walls are made, not after the compiler has run out of memory. (A 1,500-tile square
// checkerboard: 4.5 million faces.)
TEST_F(ParseTest, TooManyWallsAreRefusedBeforeTheyAreMade) {
  std::string text = "texture wall wall.png\ntexture flat flat.png\nfloor 0 flat\nceiling 64 flat\ntile W wall\nmap\n";
  const int side = 1500;
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) text += r == 0 && c == 1 ? '>' : (r + c) % 2 ? '.' : 'W';
    text += '\n';
  }
  text += "end\n";
  write_file_atomically(dir_ / "g.grid", text);
  try {
    load_grid(dir_ / "g.grid");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "g.grid").string() + ": more walls than a level may have (2,097,152)");
  }
}

TEST_F(ParseTest, BadGridsGiveLocatedMessages) {
  const std::string head = "texture wall wall.png\ntexture flat flat.png\nfloor 0 flat\nceiling 64 flat\ntile W wall\n";
  const std::vector<BadCase> cases = {
      {"ragged", head + "map\nWWW\nW>W\nWW\nend\n", "DIR/g.grid:9: row has 2 tiles, expected 3"},
      {"unknown tile", head + "map\nWWW\nW>X\nWWW\nend\n", "DIR/g.grid:8: unknown tile 'X' in column 3 (add 'tile X TEXTURE')"},
      {"no player", head + "map\nWWW\nW.W\nWWW\nend\n", "DIR/g.grid: no player marker (> ^ < or v) in the map rows"},
      {"two players", head + "map\nWWWW\nW><W\nWWWW\nend\n", "DIR/g.grid:8: a second player marker"},
      {"no end", head + "map\nWWW\nW>W\n", "DIR/g.grid:6: map rows are not closed by a line 'end'"},
      {"no floor", "texture wall wall.png\ntile W wall\nceiling 64 wall\nmap\nW>W\nend\n", "DIR/g.grid: no floor (add 'floor HEIGHT TEXTURE')"},
      {"bad tile", head + "tile . wall\n", "DIR/g.grid:6: a tile is one character other than '.', space, '#', '=' and the player markers > ^ < v"},
      {"statement after map", head + "map\nW>W\nend\nlight 3\n", "DIR/g.grid:9: statements must come before the map rows"},
      {"cell", "cell 0\n", "DIR/g.grid:1: cell size '0' must be an integer from 1 to 4096"},
  };
  for (const BadCase& c : cases) {
    write_file_atomically(dir_ / "g.grid", c.text);
    std::string message = "(no error)";
    try {
      load_source(dir_ / "g.grid");
    } catch (const Error& e) {
      message = e.what();
      const std::string d = dir_.string();
      for (size_t at; (at = message.find(d)) != std::string::npos;) message.replace(at, d.size(), "DIR");
    }
    EXPECT_EQ(message, c.message) << c.name;
  }
}

// Short integers take a loop of their own rather than from_chars: every number must
// come out as from_chars reads it, bit for bit (-0 too), and every text it refuses
// must still be refused.
TEST(Statement, NumbersAreReadAsFromCharsReadsThem) {
  const FileLoc file("t.map");
  detail::Words words{{"k"}, {}};
  const detail::Statement s(file, 1, words);
  for (const std::string text : {"0", "-0", "7", "-12", "007", "-000", "123456789012345", "-999999999999999",
                                 "1234567890123456", "99999999999999999999", "1.5", "-2.25", "1e3", "+5", "-", "",
                                 "--1", "12a", " 1", "0x10", "1-", "nan", "inf", "1e999"}) {
    double expected = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), expected);
    const bool valid = ec == std::errc() && end == text.data() + text.size() && std::isfinite(expected);
    if (valid) {
      EXPECT_EQ(std::bit_cast<uint64_t>(s.number(text, "n")), std::bit_cast<uint64_t>(expected)) << "'" << text << "'";
    } else {
      EXPECT_THROW(s.number(text, "n"), Error) << "'" << text << "'";
    }
  }
}

}  // namespace
}  // namespace p3d::map
