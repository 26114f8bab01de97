// WAD containers, pictures and art: directories validated with exact messages,
// lump lookup with later WADs overriding, Doom's post format, composite textures.
#include <gtest/gtest.h>

#include "engine/util/bytes.h"
#include "engine/util/doom.h"
#include "engine/util/error.h"
#include "engine/image/image.h"
#include "engine/wad/art.h"
#include "engine/wad/picture.h"
#include "engine/wad/wad.h"
#include "tests/support/wad_writer.h"

namespace p3d::wad {
namespace {

std::string wad_error(std::vector<uint8_t> bytes) {
  try {
    Wad(std::move(bytes), "x.wad");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

void put32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = uint8_t(v >> (8 * i));
}

TEST(Wad, DirectoryIsValidated) {
  test::WadWriter w;
  w.lump("ONE", {1, 2, 3});
  w.lump("two", {4});
  const std::vector<uint8_t> good = w.bytes();
  const Wad wad(good, "x.wad");
  ASSERT_EQ(wad.lumps().size(), 2u);
  EXPECT_EQ(wad.lumps()[1].name, "TWO");  // names are upper-cased
  EXPECT_EQ(wad.find("two")->bytes.size(), 1u);
  EXPECT_FALSE(wad.is_iwad());

  EXPECT_EQ(wad_error({'P', 'W'}), "x.wad: not a WAD file (2 bytes)");
  std::vector<uint8_t> zip(good);
  zip[0] = 'P', zip[1] = 'K', zip[2] = 3, zip[3] = 4;
  EXPECT_EQ(wad_error(zip), "x.wad: not a WAD file (starts with 'PK\\x03\\x04', expected IWAD or PWAD)");
  std::vector<uint8_t> far(good);
  put32(far, 8, 1000);
  EXPECT_EQ(wad_error(far), "x.wad: the directory of 2 lumps at byte 1000 runs past the end of the file (48 bytes)");
  std::vector<uint8_t> negative(good);
  put32(negative, 4, uint32_t(-5));
  EXPECT_EQ(wad_error(negative), "x.wad: bad WAD header (-5 lumps at byte 16)");
  std::vector<uint8_t> outside(good);
  put32(outside, 16 + 4, 100);  // the first lump claims 100 bytes
  EXPECT_EQ(wad_error(outside), "x.wad: lump #0 'ONE' (100 bytes at byte 12) lies outside the file (48 bytes)");
}

TEST(Wad, LaterWadsOverrideAndNamespacesCollect) {
  test::WadWriter iwad(true), pwad;
  iwad.lump("PLAYPAL", {1});
  iwad.lump("F_START");
  iwad.lump("AAA", {1});
  iwad.lump("BBB", {1});
  iwad.lump("F_END");
  pwad.lump("PLAYPAL", {2, 2});
  pwad.lump("FF_START");
  pwad.lump("BBB", {2, 2});
  pwad.lump("CCC", {2, 2});
  pwad.lump("FF_END");
  Stack stack;
  stack.add(Wad(iwad.bytes(), "doom.wad"));
  stack.add(Wad(pwad.bytes(), "mine.wad"));
  EXPECT_EQ(stack.find("playpal")->bytes.size(), 2u);
  const auto flats = stack.namespace_lumps({"F", "FF"});
  ASSERT_EQ(flats.size(), 3u);
  EXPECT_EQ(flats[0]->name, "AAA");
  EXPECT_EQ(flats[1]->bytes.size(), 2u);  // BBB from the PWAD
  EXPECT_EQ(flats[2]->name, "CCC");
}

TEST(Picture, RoundTripsWithHolesAndRejectsBadOffsets) {
  IndexedImage img(5, 7);
  img.left_offset = 2, img.top_offset = -3;
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 5; ++x) {
      img.indices[img.at(x, y)] = uint8_t(x * 10 + y);
      img.opaque[img.at(x, y)] = (x + y) % 3 != 0;
    }
  const std::vector<uint8_t> bytes = test::encode_picture(img);
  EXPECT_TRUE(looks_like_picture(bytes));
  const IndexedImage back = decode_picture(bytes, "P");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.top_offset, -3);
  EXPECT_EQ(back.opaque, img.opaque);
  for (size_t p = 0; p < img.indices.size(); ++p) {
    if (img.opaque[p]) {
      EXPECT_EQ(back.indices[p], img.indices[p]);
    }
  }

  std::vector<uint8_t> bad(bytes);
  put32(bad, 8 + 4, 5000);  // column 1 starts past the end
  EXPECT_FALSE(looks_like_picture(bad));
  try {
    decode_picture(bad, "P");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "P: column 1 starts at byte 5000, past the end of the picture (" +
                                         std::to_string(bytes.size()) + " bytes)");
  }
  std::vector<uint8_t> cut(bytes.begin(), bytes.end() - 3);
  EXPECT_THROW(decode_picture(cut, "P"), Error);
}

// DeePsea's tall patches: a post starting at or above the previous one continues from it.
TEST(Picture, TallPatchesUseRelativeOffsets) {
  // One column, 400 high: a post at row 200 (50 long), then delta 150 <= 200: row 350.
  std::vector<uint8_t> b = {1, 0, 144, 1, 0, 0, 0, 0, 12, 0, 0, 0};
  b.push_back(200), b.push_back(50), b.push_back(0);
  for (int i = 0; i < 50; ++i) b.push_back(7);
  b.push_back(0);
  b.push_back(150), b.push_back(20), b.push_back(0);
  for (int i = 0; i < 20; ++i) b.push_back(9);
  b.push_back(0), b.push_back(0xFF);
  const IndexedImage img = decode_picture(b, "tall");
  EXPECT_EQ(img.height, 400);
  EXPECT_EQ(img.indices[img.at(0, 249)], 7);
  EXPECT_FALSE(img.opaque[img.at(0, 300)]);
  EXPECT_EQ(img.indices[img.at(0, 360)], 9);
  EXPECT_FALSE(img.opaque[img.at(0, 370)]);
}

TEST(Art, CompositeTexturesFlatsAndSkies) {
  test::WadWriter w(true);
  test::add_test_art(w);
  Stack stack;
  stack.add(Wad(w.bytes(), "art.wad"));
  const Art art(stack);
  std::vector<std::string> problems;
  const auto wall = art.texture("wall", problems);  // case-insensitive
  ASSERT_TRUE(wall);
  EXPECT_EQ(wall->height, 72);
  EXPECT_EQ(wall->indices[wall->at(3, 71)], 171);
  const auto mesh = art.texture("MESH", problems);
  ASSERT_TRUE(mesh);
  EXPECT_FALSE(mesh->opaque[mesh->at(0, 5)]);
  EXPECT_TRUE(mesh->opaque[mesh->at(1, 5)]);
  EXPECT_FALSE(art.texture("NOPE", problems));
  EXPECT_TRUE(art.flat("floor", problems));
  EXPECT_FALSE(art.flat("WALL", problems));  // textures and flats are separate namespaces
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(art.palette()[3], image::rgba(3, 252, 128));

  EXPECT_EQ(sky_texture_name("E1M4"), "SKY1");
  EXPECT_EQ(sky_texture_name("e3m1"), "SKY3");
  EXPECT_EQ(sky_texture_name("MAP11"), "SKY1");
  EXPECT_EQ(sky_texture_name("MAP12"), "SKY2");
  EXPECT_EQ(sky_texture_name("MAP20"), "SKY2");
  EXPECT_EQ(sky_texture_name("MAP21"), "SKY3");
}

// Two patches on one canvas, each partly off it, the second with holes over the first
// in one column: every texel against a composition done here post by post, by Doom's
// rules (R_GenerateLookup, R_DrawColumnInCache): a column only one patch covers is that
// patch's column from the texture's top, whatever the patch's place up or down; in a
// column of several, each post lands at its place, one reaching above the top cut to
// fit but from its own first row. A flat is its lump's rows.
TEST(Art, PatchesLandAsDoomComposesThemAndFlatsAreRows) {
  struct Placed {
    IndexedImage image;
    int x, y;
  };
  std::vector<Placed> patches = {{IndexedImage(4, 6), -1, -2}, {IndexedImage(5, 5), 2, 7}};
  for (size_t k = 0; k < patches.size(); ++k)
    for (int y = 0; y < patches[k].image.height; ++y)
      for (int x = 0; x < patches[k].image.width; ++x) {
        IndexedImage& img = patches[k].image;
        img.indices[img.at(x, y)] = uint8_t(100 * k + 10 * y + x);
        img.opaque[img.at(x, y)] = k == 0 || (x + y) % 2 == 0;
      }
  constexpr int kW = 12, kH = 10;
  test::WadWriter w(true);
  test::add_test_art(w);  // the palette and light maps; its PNAMES and TEXTURE1 are replaced below
  auto name8 = [](ByteWriter& out, const std::string& n) {
    for (size_t i = 0; i < 8; ++i) out.u8(i < n.size() ? uint8_t(n[i]) : 0);
  };
  ByteWriter pnames;
  pnames.u32(2);
  name8(pnames, "PA"), name8(pnames, "PB");
  ByteWriter texture1;
  texture1.u32(1), texture1.u32(8);
  name8(texture1, "DUO");
  texture1.u32(0), texture1.u16(kW), texture1.u16(kH), texture1.u32(0), texture1.u16(2);
  for (size_t k = 0; k < patches.size(); ++k)
    texture1.u16(uint16_t(patches[k].x)), texture1.u16(uint16_t(patches[k].y)), texture1.u16(uint16_t(k)),
        texture1.u16(1), texture1.u16(0);
  w.lump("PNAMES", pnames.release());
  w.lump("TEXTURE1", texture1.release());
  w.lump("P_START");
  w.lump("PA", test::encode_picture(patches[0].image));
  w.lump("PB", test::encode_picture(patches[1].image));
  w.lump("P_END");
  std::vector<uint8_t> flat(64 * 64);
  for (size_t p = 0; p < flat.size(); ++p) flat[p] = uint8_t(p % 64 + p / 64 % 3 * 64);  // column + 64 * (row % 3)
  w.lump("F_START");
  w.lump("RAMP", flat);
  w.lump("F_END");
  Stack stack;
  stack.add(Wad(w.bytes(), "art.wad"));
  const Art art(stack);
  std::vector<std::string> problems;
  const auto duo = art.texture("DUO", problems);
  ASSERT_TRUE(duo);
  EXPECT_TRUE(problems.empty());
  for (int x = 0; x < kW; ++x) {
    std::vector<int> want(kH, -1);  // transparent
    int over = 0;
    for (const Placed& p : patches) over += x >= p.x && x < p.x + p.image.width;
    for (const Placed& p : patches) {
      const int px = x - p.x;
      if (px < 0 || px >= p.image.width) continue;
      for (int t = 0; t < p.image.height;) {  // each post: a run of opaque rows
        int end = t;
        while (end < p.image.height && p.image.opaque[p.image.at(px, end)]) ++end;
        const int at = (over == 1 ? 0 : p.y) + t;
        for (int i = std::max(0, -at); i < end - t && std::max(at, 0) + i - std::max(0, -at) < kH; ++i)
          want[size_t(std::max(at, 0) + i - std::max(0, -at))] = p.image.indices[p.image.at(px, t + i - std::max(0, -at))];
        t = std::max(end, t + 1);
      }
    }
    for (int y = 0; y < kH; ++y) {
      EXPECT_EQ(duo->opaque[duo->at(x, y)], want[size_t(y)] >= 0) << x << "," << y;
      if (want[size_t(y)] >= 0) {
        EXPECT_EQ(duo->indices[duo->at(x, y)], want[size_t(y)]) << x << "," << y;
      }
    }
  }
  const auto ramp = art.flat("RAMP", problems);
  ASSERT_TRUE(ramp);
  for (int y = 0; y < 64; y += 7)
    for (int x = 0; x < 64; x += 5) EXPECT_EQ(ramp->indices[ramp->at(x, y)], x + y % 3 * 64) << x << "," << y;
}

TEST(Art, MissingArtIsAClearError) {
  test::WadWriter w;
  w.lump("MAP01");
  Stack stack;
  stack.add(Wad(w.bytes(), "map.wad"));
  try {
    Art art(stack);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "map.wad: no PLAYPAL lump: the WADs hold no Doom art (give an IWAD with --iwad)");
  }
}

}  // namespace
}  // namespace p3d::wad

namespace p3d::doom {
namespace {

TEST(MapOrder, NextMapFollowsDoomsOrder) {
  const auto all = [](const std::string&) { return true; };
  EXPECT_EQ(next_map("E1M1", false, all), "E1M2");
  EXPECT_EQ(next_map("e1m3", true, all), "E1M9") << "a secret exit goes to M9";
  EXPECT_EQ(next_map("E1M9", false, all), "E1M4");
  EXPECT_EQ(next_map("E2M9", false, all), "E2M6");
  EXPECT_EQ(next_map("E3M9", false, all), "E3M7");
  EXPECT_EQ(next_map("E4M9", false, all), "E4M3");
  EXPECT_EQ(next_map("E1M8", false, all), "") << "the episode ends";
  EXPECT_EQ(next_map("MAP01", false, all), "MAP02");
  EXPECT_EQ(next_map("MAP01", true, all), "MAP02") << "Doom II's other secret exits are normal ones";
  EXPECT_EQ(next_map("MAP15", true, all), "MAP31");
  EXPECT_EQ(next_map("MAP31", true, all), "MAP32");
  EXPECT_EQ(next_map("MAP31", false, all), "MAP16");
  EXPECT_EQ(next_map("MAP32", false, all), "MAP16");
  EXPECT_EQ(next_map("MAP30", false, all), "") << "the game ends";
  EXPECT_EQ(next_map("MAP15", true, [](const std::string& n) { return n != "MAP31"; }), "MAP16");
  EXPECT_EQ(next_map("MAP07", false, [](const std::string& n) { return n != "MAP08"; }), "") << "a missing map";
  EXPECT_EQ(next_map("START", false, all), "") << "not one of Doom's names";
}

}  // namespace
}  // namespace p3d::doom
