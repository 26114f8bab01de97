// The comparison renderers against their oracles: the grid ray caster against the
// BSP renderer on grid maps, sphere tracing against the reference, the painter
// against front to back, over hundreds of random cameras.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/map/generate.h"
#include "engine/map/source.h"
#include "engine/render/renderer.h"
#include "engine/render/view.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d::render {
namespace {

struct Rendered {
  Frame frame;
  Probe probe;
  RenderStats stats;
};

Rendered render_with(const std::string& name, const level::Level& level, const Camera& camera, int w, int h,
                const RendererOptions& options = {}) {
  Rendered r{Frame(w, h), {}, {}};
  r.probe.want_columns = true;
  r.stats = make_renderer(name, options)->render(level, camera, r.frame, &r.probe);
  return r;
}

bool same_or_tie(const ColumnHit& a, const ColumnHit& b) {
  if (a.wall == b.wall) return a.wall < 0 || a.dist == b.dist;
  return a.wall >= 0 && b.wall >= 0 && std::fabs(a.dist - b.dist) <= 1e-9 * b.dist;
}

// Grid levels: the bundled ones and random caves and mazes written with builtin textures.
std::vector<std::pair<std::string, level::Level>> grid_levels() {
  std::vector<std::pair<std::string, level::Level>> levels;
  for (const char* name : {"bunker", "caves", "labyrinth"})
    levels.push_back({name, test::compile(map::load_grid(test::source_dir() / "maps" / (std::string(name) + ".grid")))});
  const auto dir = test::temp_dir("grids");
  map::GridOptions o;
  for (int i = 0; i < 7; ++i) {
    o.texture_files.push_back("t" + std::to_string(i) + ".png");
    image::save_png(map::builtin_textures()[i % 5].image, dir / o.texture_files.back());
  }
  for (uint64_t seed : {1, 2, 3})
    for (const char* kind : {"caves", "maze"}) {
      o.kind = kind;
      o.seed = seed;
      o.cols = 20 + int(seed) * 7;
      o.rows = 16 + int(seed) * 5;
      o.cell = seed == 2 ? 48 : 64;
      write_file_atomically(dir / "g.grid", map::generate_grid_text(o));
      levels.push_back({std::string(kind) + " seed " + std::to_string(seed), test::compile(map::load_grid(dir / "g.grid"))});
    }
  std::filesystem::remove_all(dir);
  return levels;
}

TEST(GridRayCaster, AgreesWithTheBspRendererOnGridMaps) {
  size_t columns = 0, mismatches = 0, pixels = 0, pixel_mismatches = 0, frames = 0;
  for (const auto& [name, level] : grid_levels()) {
    ASSERT_TRUE(level.grid.has_value()) << name;
    Rng rng(std::hash<std::string>()(name));
    for (int i = 0; i < 30; ++i) {
      const Camera c = test::random_camera(level, rng);
      const int w = 40 + int(rng.below(90)), h = 30 + int(rng.below(50));
      const Rendered dda = render_with("dda", level, c, w, h), bsp = render_with("bsp", level, c, w, h);
      for (int x = 0; x < w; ++x) {
        ++columns;
        if (!same_or_tie(dda.probe.columns[x], bsp.probe.columns[x])) {
          ++mismatches;
          ADD_FAILURE() << name << " camera " << i << " column " << x << ": dda wall " << dda.probe.columns[x].wall << " at "
                        << dda.probe.columns[x].dist << ", bsp wall " << bsp.probe.columns[x].wall << " at "
                        << bsp.probe.columns[x].dist << " (camera " << c.pos.x << "," << c.pos.y << " angle " << c.angle << ")";
        }
      }
      for (size_t p = 0; p < dda.frame.pixels.size(); ++p) pixel_mismatches += dda.frame.pixels[p] != bsp.frame.pixels[p];
      pixels += dda.frame.pixels.size();
      EXPECT_GT(dda.stats.steps, 0u);
      ++frames;
    }
  }
  std::printf("[ stats    ] dda vs bsp: %zu frames, %zu columns, %zu mismatches, %zu/%zu pixels differ\n", frames, columns,
              mismatches, pixel_mismatches, pixels);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GE(1.0 - double(pixel_mismatches) / double(pixels), 0.995);
  EXPECT_GE(frames, 200u);
}

// Cameras inside solid tiles and outside the grid: the walker enters the grid, and
// walls seen from behind stay invisible, as in the BSP renderer.
TEST(GridRayCaster, AgreesFromInsideSolidTilesAndOutsideTheGrid) {
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"));
  const double size_x = level.grid->cols * level.grid->cell, size_y = level.grid->rows * level.grid->cell;
  Rng rng(3);
  size_t columns = 0;
  for (int i = 0; i < 90; ++i) {
    // Anywhere inside or around the grid, a third of them on grid lines and corners.
    Vec2 p = i % 2 ? Vec2{rng.uniform(-600, size_x + 600), rng.uniform(-600, size_y + 600)}
                   : Vec2{rng.uniform(0, size_x), rng.uniform(0, size_y)};
    if (i % 3 == 0) p = glm::round(p / 32.0) * 32.0;
    const Camera c{p, 41, rng.uniform(0, 360), 90};
    const Rendered dda = render_with("dda", level, c, 80, 50), bsp = render_with("bsp", level, c, 80, 50);
    for (int x = 0; x < 80; ++x, ++columns)
      EXPECT_TRUE(same_or_tie(dda.probe.columns[x], bsp.probe.columns[x]))
          << "camera " << p.x << "," << p.y << " angle " << c.angle << " column " << x;
  }
  EXPECT_EQ(columns, 90u * 80u);
}

TEST(GridRayCaster, OnlyDrawsGridLevels) {
  EXPECT_FALSE(make_renderer("dda")->supports(test::compile(test::random_rooms(100, 1))));
}

// For each column the reference closes: the gap from its closing hit to any other
// wall the ray meets. Where that gap exceeds epsilon, sphere tracing must agree.
double isolation(const level::Level& level, const View& view, int x, const ColumnHit& closing) {
  double gap = INFINITY;
  for (uint32_t i = 0; i < level.walls.size(); ++i) {
    if (int32_t(i) == closing.wall) continue;
    double depth, t;
    if (WallProjector(view, level.walls[i].a, level.walls[i].b).hit(x, depth, t))
      gap = std::min(gap, std::fabs(depth - closing.dist));
  }
  return gap;
}

TEST(SphereTracer, AgreesWithTheReferenceWhereWallsAreApart) {
  std::vector<std::pair<std::string, level::Level>> levels;
  levels.push_back({"outpost", test::compile(map::load_map(test::source_dir() / "maps/outpost.map"))});
  levels.push_back({"soup", test::compile(test::random_soup(250, 4))});
  levels.push_back({"rooms", test::compile(test::random_rooms(300, 5))});
  levels.push_back({"bunker", test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"))});
  RendererOptions options;
  options.sphere_epsilon = 0.05;
  for (const char* mode : {"sphere", "sphere-naive"}) {
    size_t checked = 0, skipped = 0, pixels = 0, pixels_differ = 0;
    uint64_t max_steps = 0;
    for (const auto& [name, level] : levels) {
      Rng rng(17);
      for (int i = 0; i < (std::string(mode) == "sphere" ? 40 : 15); ++i) {
        const Camera c = test::random_camera(level, rng);
        const int w = 48 + int(rng.below(48)), h = 32;
        const Rendered s = render_with(mode, level, c, w, h, options), ref = render_with("reference", level, c, w, h);
        const View view(c, w, h);
        max_steps = std::max(max_steps, s.stats.max_steps);
        for (size_t p = 0; p < s.frame.pixels.size(); ++p) pixels_differ += s.frame.pixels[p] != ref.frame.pixels[p];
        pixels += s.frame.pixels.size();
        EXPECT_EQ(s.stats.rays, uint64_t(w));
        for (int x = 0; x < w; ++x) {
          const ColumnHit& want = ref.probe.columns[x];
          if (want.wall >= 0 && isolation(level, view, x, want) <= options.sphere_epsilon) {
            ++skipped;
            continue;
          }
          ++checked;
          const ColumnHit& got = s.probe.columns[x];
          EXPECT_EQ(got.wall, want.wall) << mode << " " << name << " camera " << i << " column " << x;
          if (want.wall >= 0) {
            EXPECT_NEAR(got.dist, want.dist, options.sphere_epsilon) << mode << " " << name;
          }
        }
      }
    }
    std::printf("[ stats    ] %s: %zu columns checked, %zu skipped (walls within epsilon), max steps %llu, "
                "%zu/%zu pixels differ\n",
                mode, checked, skipped, (unsigned long long)max_steps, pixels_differ, pixels);
    EXPECT_GT(checked, 10 * skipped);
    EXPECT_GE(1.0 - double(pixels_differ) / double(pixels), 0.995) << mode;
  }
}

TEST(SphereTracer, GrazingAndEscapingRaysTerminate) {
  // A camera exactly on a grid line looking along it, and one outside the level looking away.
  const level::Level level = test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"));
  RendererOptions options;
  options.sphere_max_steps = 64;
  for (const char* mode : {"sphere", "sphere-naive"}) {
    const Rendered along = render_with(mode, level, camera_at(level, {352, 704}, 0), 64, 40, options);
    EXPECT_LE(along.stats.max_steps, 64u);
    const Rendered away = render_with(mode, level, Camera{{-500, -500}, 41, 225, 90}, 64, 40, options);
    EXPECT_LE(away.stats.max_steps, 3u) << mode << ": rays leaving the level stop at once";
    EXPECT_EQ(away.stats.columns_closed, 0u);
  }
}

TEST(Painter, PaintsTheSamePictureWithOverdraw) {
  std::vector<std::pair<std::string, level::Level>> levels;
  levels.push_back({"outpost", test::compile(map::load_map(test::source_dir() / "maps/outpost.map"))});
  levels.push_back({"rooms", test::compile(test::random_rooms(400, 2))});
  levels.push_back({"soup", test::compile(test::random_soup(300, 2))});
  levels.push_back({"bunker", test::compile(map::load_grid(test::source_dir() / "maps/bunker.grid"))});
  size_t pixels = 0, differ = 0, frames = 0;
  double overdraw_sum = 0;
  for (const auto& [name, level] : levels) {
    Rng rng(5);
    for (int i = 0; i < 40; ++i) {
      const Camera c = test::random_camera(level, rng);
      const int w = 40 + int(rng.below(80)), h = 30 + int(rng.below(50));
      const Rendered painter = render_with("painter", level, c, w, h), bsp = render_with("bsp", level, c, w, h);
      for (size_t p = 0; p < bsp.frame.pixels.size(); ++p) differ += painter.frame.pixels[p] != bsp.frame.pixels[p];
      pixels += bsp.frame.pixels.size();
      EXPECT_GE(painter.stats.pixels_written, bsp.stats.pixels_written) << name << " camera " << i;
      for (int x = 0; x < w; ++x)
        EXPECT_TRUE(painter.probe.columns[x].wall == bsp.probe.columns[x].wall &&
                    painter.probe.columns[x].dist == bsp.probe.columns[x].dist)
            << name << " camera " << i << " column " << x;
      overdraw_sum += double(painter.stats.pixels_written) / (w * h);
      ++frames;
    }
  }
  std::printf("[ stats    ] painter vs bsp: %zu frames, %zu/%zu pixels differ, mean painter overdraw %.2fx\n", frames,
              differ, pixels, overdraw_sum / frames);
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(overdraw_sum / frames, 1.2);
}

TEST(Probe, OverdrawCountsMatchPixelsWritten) {
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  for (const char* name : {"bsp", "painter", "reference"}) {
    Frame frame(96, 60);
    Probe probe;
    probe.want_writes = probe.want_order = true;
    const RenderStats s = make_renderer(name)->render(level, camera_at(level, {64, 96}, 30), frame, &probe);
    uint64_t total = 0;
    for (uint16_t n : probe.writes) total += n;
    EXPECT_EQ(total, s.pixels_written + s.masked_pixels + s.sprite_pixels) << name;
    if (std::string(name) != "reference") {
      EXPECT_EQ(probe.order.size(), s.fragments_drawn) << name;
    }
  }
}

}  // namespace
}  // namespace p3d::render
