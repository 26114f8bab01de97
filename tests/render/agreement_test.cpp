// The BSP front-to-back renderer against the brute-force reference: per-column
// closing wall and distance for every column, and pixels, over hundreds of
// random cameras on random maps and the bundled default map.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/bsp/load.h"
#include "engine/map/generate.h"
#include "engine/map/source.h"
#include "engine/render/renderer.h"
#include "tests/support/support.h"

namespace p3d::render {
namespace {

struct Tally {
  size_t columns = 0, column_mismatches = 0, pixels = 0, pixel_mismatches = 0, frames = 0, early_exits = 0;
};

// Compares one camera: every column must agree; pixels are tallied when count_pixels.
void compare_camera(const level::Level& level, const Camera& camera, int w, int h, Tally& tally, const std::string& what,
                    bool count_pixels = true) {
  auto bsp = make_renderer("bsp");
  auto ref = make_renderer("reference");
  Frame a(w, h), b(w, h);
  Probe pa, pb;
  pa.want_columns = pb.want_columns = true;
  const RenderStats sa = bsp->render(level, camera, a, &pa);
  const RenderStats sb = ref->render(level, camera, b, &pb);
  const ColumnHits &ha = pa.columns, &hb = pb.columns;
  ASSERT_EQ(ha.size(), size_t(w));
  // Front to back writes every pixel exactly once.
  EXPECT_EQ(sa.pixels_written, uint64_t(w) * h) << what;
  EXPECT_EQ(sb.pixels_written, uint64_t(w) * h) << what;
  for (int x = 0; x < w; ++x) {
    ++tally.columns;
    // Exactly: a ray through a shared corner hits one wall by the same rule in both (see WallProjector).
    if (ha[x].wall != hb[x].wall || ha[x].dist != hb[x].dist) {
      ++tally.column_mismatches;
      ADD_FAILURE() << what << " column " << x << ": bsp wall " << ha[x].wall << " at " << ha[x].dist
                    << ", reference wall " << hb[x].wall << " at " << hb[x].dist << " (camera " << camera.pos.x << ","
                    << camera.pos.y << " angle " << camera.angle << " fov " << camera.fov << ")";
    }
  }
  if (count_pixels) {
    for (size_t i = 0; i < a.pixels.size(); ++i) tally.pixel_mismatches += a.pixels[i] != b.pixels[i];
    tally.pixels += a.pixels.size();
  }
  tally.early_exits += sa.early_exit;
  ++tally.frames;
}

void run_cameras(const level::Level& level, uint64_t seed, int cameras, Tally& tally, const std::string& what) {
  Rng rng(seed);
  for (int i = 0; i < cameras; ++i) {
    const Camera c = test::random_camera(level, rng);
    const int w = 48 + int(rng.below(80)), h = 24 + int(rng.below(60));  // odd sizes too
    compare_camera(level, c, w, h, tally, what + " camera " + std::to_string(i) + " seed " + std::to_string(seed));
  }
}

void expect_agreement(const Tally& t, const std::string& what) {
  EXPECT_EQ(t.column_mismatches, 0u) << what;
  EXPECT_EQ(t.pixel_mismatches, 0u) << what << ": " << t.pixel_mismatches << " of " << t.pixels << " pixels differ";
  std::printf("[ stats    ] %s: %zu frames, %zu columns, %zu column mismatches, %zu/%zu pixels differ, %zu early exits\n",
              what.c_str(), t.frames, t.columns, t.column_mismatches, t.pixel_mismatches, t.pixels, t.early_exits);
}

TEST(Agreement, RandomSoups) {
  Tally t;
  for (uint64_t seed : {1, 2, 3}) {
    const level::Level level = test::compile(test::random_soup(300, seed), bsp::Strategy::kGreedy, seed);
    run_cameras(level, seed, 60, t, "soup");
  }
  expect_agreement(t, "soups");
}

TEST(Agreement, RandomRooms) {
  Tally t;
  for (uint64_t seed : {4, 5, 6}) {
    const level::Level level = test::compile(test::random_rooms(400, seed), bsp::Strategy::kRandom, seed);
    run_cameras(level, seed, 60, t, "rooms");
  }
  expect_agreement(t, "rooms");
  EXPECT_GT(t.early_exits, t.frames / 2);
}

// mapgen's shapes, whose trees split along free lines (lines holding no wall).
TEST(Agreement, HostileShapes) {
  for (const std::string& kind : map::shape_kinds()) {
    map::GenerateOptions o;
    o.walls = 1500;
    o.textures = map::builtin_textures();
    const level::Level level = test::compile(map::generate_shape(kind, o));
    Tally t;
    run_cameras(level, 40, 12, t, kind);
    expect_agreement(t, kind);
    Rng rng(41);  // the painter, walking the same tree back to front, paints the same pictures
    for (int i = 0; i < 6; ++i) {
      const Camera c = test::random_camera(level, rng);
      Frame a(64, 40), b(64, 40);
      make_renderer("reference")->render(level, c, a);
      make_renderer("painter")->render(level, c, b);
      EXPECT_EQ(a.pixels, b.pixels) << kind << " camera " << i;
    }
  }
}

TEST(Agreement, DefaultMapEveryStrategy) {
  const map::Source src = map::load_map(test::source_dir() / "maps/outpost.map");
  for (bsp::Strategy s : {bsp::Strategy::kFirst, bsp::Strategy::kRandom, bsp::Strategy::kFreeSplit, bsp::Strategy::kGreedy}) {
    Tally t;
    run_cameras(test::compile(src, s, 9), 20 + uint64_t(s), 40, t, "outpost");
    expect_agreement(t, std::string("outpost ") + bsp::strategy_name(s));
  }
}

// Cameras on wall lines and vertices (an 8-unit grid), with eyes from under the
// floor to far above the ceilings: every pixel is still written exactly once, the
// renderers still agree column by column, and the painter paints the same picture.
// A camera exactly on the boundary of two sectors is in either: there the BSP and
// crossing parity may pick different ones, so such frames skip the pixel tally.
TEST(Agreement, AwkwardCameras) {
  std::vector<std::pair<std::string, level::Level>> levels;
  levels.push_back({"outpost", test::compile(map::load_map(test::source_dir() / "maps/outpost.map"))});
  levels.push_back({"rooms", test::compile(test::random_rooms(300, 8))});
  levels.push_back({"soup", test::compile(test::random_soup(200, 8))});
  for (const auto& [name, level] : levels) {
    Rng rng(31);
    Tally t;
    size_t painter_differ = 0, ambiguous = 0;
    for (int i = 0; i < 60; ++i) {
      const Vec2 p{8 * std::round(rng.uniform(level.bounds.min.x, level.bounds.max.x) / 8),
                   8 * std::round(rng.uniform(level.bounds.min.y, level.bounds.max.y) / 8)};
      const Camera c{p, rng.uniform(-20, 200), 45.0 * double(rng.below(8)), 90};
      const bool unambiguous = level.sector_at(p) == level::sector_at_brute_force(level, p);
      ambiguous += !unambiguous;
      compare_camera(level, c, 64, 40, t, name + " awkward camera " + std::to_string(i), unambiguous);
      Frame a(64, 40), b(64, 40);
      make_renderer("bsp")->render(level, c, a);
      make_renderer("painter")->render(level, c, b);
      painter_differ += a.pixels != b.pixels;
    }
    expect_agreement(t, name + " awkward cameras (" + std::to_string(ambiguous) + " on a sector boundary)");
    EXPECT_EQ(painter_differ, 0u) << name;
  }
}

TEST(Rendering, IsDeterministicAndCulls) {
  const level::Level level = test::compile(test::random_rooms(3000, 7));
  auto bsp = make_renderer("bsp");
  const Camera camera = camera_at(level, level.player_start, 20);
  Frame a(320, 200), b(320, 200);
  const RenderStats s = bsp->render(level, camera, a);
  bsp->render(level, camera, b);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_TRUE(s.early_exit);
  EXPECT_EQ(s.columns_closed, 320u);
  EXPECT_GT(s.subtrees_culled, 0u);
  EXPECT_LT(s.nodes_visited, level.nodes.size() / 10) << "a view inside one room should touch few nodes";
}

}  // namespace
}  // namespace p3d::render

namespace p3d::render {
namespace {

// The frame is split into column strips drawn on as many threads as given: the
// pixels, the per-column hits and every statistic are the same for any count, with
// the vector column loops or without, and the same as the reference's pixels.
// Freedoom MAP01 with its things, and random rooms.
TEST(Threads, FramesAndStatisticsAreTheSameForAnyThreadCount) {
  std::vector<std::pair<std::string, level::Level>> levels;
  levels.push_back({"rooms", test::compile(test::random_rooms(600, 12))});
  levels.push_back({"freedoom2 MAP01", bsp::build_wad_map(bsp::read_wads({test::freedoom_path("freedoom2.wad")}), "MAP01", {},
                                                           nullptr)});
  size_t frames = 0, sprites = 0;
  for (const auto& [name, level] : levels) {
    std::vector<std::unique_ptr<Renderer>> renderers;
    for (int threads : {1, 2, 3, 8}) renderers.push_back(make_renderer("bsp", {.threads = threads}));
    renderers.push_back(make_renderer("bsp", {.threads = 2, .vector_columns = false}));  // the scalar loops
    auto reference = make_renderer("reference");
    Rng rng(77);
    for (int i = 0; i < 24; ++i) {
      Camera c = test::random_camera(level, rng);
      int w = 40 + int(rng.below(300)), h = 30 + int(rng.below(200));
      // A WAD level at 90 degrees follows Doom's rules: vanilla's at 320 columns (a flat's
      // span may start in a strip to the left), Crispy's at other widths.
      if (i % 3 == 1) c.fov = 90;
      if (i % 6 == 1) w = 320, h = 200;
      Frame first(w, h), frame(w, h), ref(w, h);
      Probe first_probe, probe;
      first_probe.want_columns = probe.want_columns = true;
      const RenderStats s1 = renderers[0]->render(level, c, first, &first_probe);
      for (size_t r = 1; r < renderers.size(); ++r) {
        const RenderStats s = renderers[r]->render(level, c, frame, &probe);
        EXPECT_EQ(frame.pixels, first.pixels) << name << " camera " << i << " renderer " << r;
        EXPECT_EQ(statdump(stat_fields(s)), statdump(stat_fields(s1))) << name << " camera " << i;
        for (int x = 0; x < w; ++x)
          EXPECT_TRUE(probe.columns[x].wall == first_probe.columns[x].wall && probe.columns[x].dist == first_probe.columns[x].dist)
              << name << " camera " << i << " column " << x;
      }
      reference->render(level, c, ref);
      EXPECT_EQ(ref.pixels, first.pixels) << name << " camera " << i;
      ++frames;
      sprites += s1.sprites_drawn;
    }
  }
  std::printf("[ stats    ] %zu frames on 1, 2, 3 and 8 threads, %zu sprites\n", frames, sprites);
  EXPECT_GT(sprites, 0u);
}

}  // namespace
}  // namespace p3d::render
